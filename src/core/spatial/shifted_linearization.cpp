// The structured solver's linearisation (shifted_solver.h): the per-rfe mass, stiffness, damping and
// constraint rows the factor is built from, and the kept factor's turn with the line.
#include <cmath>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/shifted_solver.h"

namespace riser_sim {
namespace spatial {

// Per rfe (u = [A, Δ, e], a = u''): M a + h(u, u') = Q + constraint forces. K, C gather -∂/∂(q, q') of the
// right side minus the left: the terms' own, ∂(M a + h)/∂(q, q') (axial: M and h move with e and Δ), the
// director multiplier μ on e (force μ e) and the joint force λ_{i+1} at E_i on Δ-e ([λ; e·λ; len λ]).
void ShiftedSolver3::setLinearization(const NaturalData& d, const Eigen::Ref<const VecX>& acc) {
  pinned_ = model_.bottom() == BottomBoundary::kPinned;  // read per linearisation, as derivative() does
  added_ = !d.added.empty();
  S_.setZero();
  for (const auto& term : model_.terms()) term->addStiffness(model_, d.kin, d.t, S_);
  const Mat3 I3 = Mat3::Identity();
  const double w = omega_;
  for (int i = 0; i < nb_; ++i) {
    const BodyKinematics3& b = d.kin[i];
    const Rfe& r = model_.rfe(i);
    Body& B = body_[i];
    const Vec3 Add = acc.segment<3>(kDofPerBody3 * i + kA), edd = acc.segment<3>(kDofPerBody3 * i + kE);
    const double Ddd = axial_ ? acc[kDofPerBody3 * i + kDelta3] : 0.0;
    const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
    const double I = r.inertiaAboutA(b.delta);
    const Vec3& L = d.lambda[i + 1];  // zero at a free end
    Mat7& M = M_[i];
    M.setZero();
    B.m = m, B.S = S, B.I = I, B.e = b.e;
    B.mk = axial_ ? mk : 0.0, B.Sk = axial_ ? Sk : 0.0;
    M.block<3, 3>(kA, kA) = m * I3;
    M.block<3, 3>(kA, kE) = S * I3;
    M.block<3, 3>(kE, kA) = S * I3;
    M.block<3, 3>(kE, kE) = I * I3;
    Mat7& K = S_.K_diag[i];
    Mat7& C = S_.C_diag[i];
    // μ from the e rows: S A'' + S_k e Δ'' + I_A e'' + h_e = Q_e + len λ_{i+1} + μ e.
    const Vec3 he = d.h.segment<3>(kDofPerBody3 * i + kE), Qe = d.Q.segment<3>(kDofPerBody3 * i + kE);
    Vec3 res = S * Add + Sk * Ddd * b.e + I * edd + he - Qe - b.len * L;
    if (!d.added.empty()) {  // added mass: in M and in μ's e rows (its turning with e is left out of K)
      Mat7 Ma = Mat7::Zero();
      addAddedMassBlock(d.added[i], b, axial_, Ma);
      M += Ma;
      res += Ma.middleRows<3>(kE) * acc.segment<7>(kDofPerBody3 * i);
    }
    const double mu = b.e.dot(res) / b.e.squaredNorm();
    K.block<3, 3>(kE, kE) -= mu * I3;
    if (axial_) {
      M.block<3, 1>(kA, kDelta3) += mk * b.e;
      M.block<1, 3>(kDelta3, kA) += mk * b.e.transpose();
      M.block<3, 1>(kE, kDelta3) += Sk * b.e;
      M.block<1, 3>(kDelta3, kE) += Sk * b.e.transpose();
      M(kDelta3, kDelta3) += mk * b.e.squaredNorm();
      // ∂(M a)/∂q (dS/dΔ = dS_k/dΔ = m_k, dI_A/dΔ = 2 S_k).
      K.block<3, 3>(kA, kE) += mk * Ddd * I3;
      K.block<3, 1>(kA, kDelta3) += mk * edd;
      K.block<1, 3>(kDelta3, kE) += (mk * Add + 2.0 * mk * Ddd * b.e + Sk * edd).transpose();
      K(kDelta3, kDelta3) += mk * b.e.dot(edd);
      K.block<3, 3>(kE, kE) += Sk * Ddd * I3;
      K.block<3, 1>(kE, kDelta3) += mk * Add + mk * Ddd * b.e + 2.0 * Sk * edd;
      // h = 2Δ' [m_k e'; m_k e·e'; S_k e'].
      const double dd = b.delta_dot;
      C.block<3, 1>(kA, kDelta3) += 2.0 * mk * b.e_dot;
      C(kDelta3, kDelta3) += 2.0 * mk * b.e.dot(b.e_dot);
      C.block<3, 1>(kE, kDelta3) += 2.0 * Sk * b.e_dot;
      C.block<3, 3>(kA, kE) += 2.0 * dd * mk * I3;
      C.block<1, 3>(kDelta3, kE) += 2.0 * dd * mk * b.e.transpose();
      C.block<3, 3>(kE, kE) += 2.0 * dd * Sk * I3;
      K.block<1, 3>(kDelta3, kE) += 2.0 * dd * mk * b.e_dot.transpose();
      K.block<3, 1>(kE, kDelta3) += 2.0 * dd * mk * b.e_dot;
      // Joint force λ_{i+1} at E_i: [λ; e·λ; len λ].
      K.block<1, 3>(kDelta3, kE) -= L.transpose();
      K.block<3, 1>(kE, kDelta3) -= L;
    } else {  // Δ locked: x_v,Δ = b_v,Δ
      for (Mat7* X : {&K, &C}) X->row(kDelta3).setZero(), X->col(kDelta3).setZero();
      M(kDelta3, kDelta3) = 1.0;
    }
    // E = A + len e: E'' = A'' + Δ'' e + len e'' + 2Δ' e', law E'' + 2ω E' + ω² E (+ prescribed).
    const Vec3 ge = axial_ ? b.e : Vec3::Zero();
    B.gE = Row3{1.0, b.len, ge};
    B.pE = Row3{2.0 * w, 2.0 * w * b.len + 2.0 * b.delta_dot, 2.0 * w * ge};
    B.rE = Row3{w * w, (w * w) * b.len + Ddd + 2.0 * w * b.delta_dot, (w * w) * ge};
    if (axial_) {
      B.pE.d += 2.0 * b.e_dot;
      B.rE.d += edd + 2.0 * w * b.e_dot;
    }
    // ½(e·e - 1): e·e'' + e'·e' + 2ω e·e' + ω² ½(e·e - 1) = 0.
    B.gu.setZero();
    B.pu.setZero();
    B.ru.setZero();
    B.gu.segment<3>(kE) = b.e;
    B.pu.segment<3>(kE) = 2.0 * b.e_dot + 2.0 * w * b.e;
    B.ru.segment<3>(kE) = edd + 2.0 * w * b.e_dot + (w * w) * b.e;
  }
  for (int i = 0; i + 1 < nb_; ++i) body_[i].Kup = S_.K_sub[i + 1].transpose() + S_.K_sup[i + 1];  // K(i, i+1)
  linearized_ = true;
  factored_ = false;
  turning_ = false;
}

// The linearisation's director is gu's e part. A director turned by more than 60° (no kept factor lives
// that long) keeps R = I.
void ShiftedSolver3::followDirectors(const NaturalData& d) {
  if (!linearized_) return;
  for (int i = 0; i < nb_; ++i) {
    const Vec3 a = body_[i].gu.segment<3>(kE), e = d.kin[i].e.normalized();
    const double cs = a.dot(e);
    Mat3& R = turn_[i];
    if (!(cs > 0.5)) {
      R.setIdentity();
      continue;
    }
    const Vec3 v = a.cross(e);  // R = cos I + [v]x + (1 - cos) w wᵀ with v = sin w (Rodrigues)
    R = (v / (1.0 + cs)) * v.transpose();
    R.diagonal().array() += cs;
    R(0, 1) -= v.z(), R(1, 0) += v.z();
    R(0, 2) += v.y(), R(2, 0) -= v.y();
    R(1, 2) -= v.x(), R(2, 1) += v.x();
  }
  turning_ = true;
}

}  // namespace spatial
}  // namespace riser_sim
