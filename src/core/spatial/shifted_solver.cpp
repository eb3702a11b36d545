#include "riser_sim/spatial/shifted_solver.h"

#include <cmath>
#include <utility>

#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

namespace {
using Mat11 = ShiftedSolver3::Mat11;

// LU with partial pivoting of an 11x11 block in place (unit lower L below the diagonal, U on and above;
// row k was swapped with piv[k] at step k), on fixed-size column-major loops (Eigen's PartialPivLU goes
// through its blocked dynamic-size kernels at this size).
void luFactor(Mat11& A, int* piv) {
  double* a = A.data();
  for (int k = 0; k < 11; ++k) {
    int p = k;
    double best = std::abs(a[k + 11 * k]);
    for (int i = k + 1; i < 11; ++i)
      if (std::abs(a[i + 11 * k]) > best) best = std::abs(a[i + 11 * k]), p = i;
    piv[k] = p;
    if (p != k)
      for (int j = 0; j < 11; ++j) std::swap(a[k + 11 * j], a[p + 11 * j]);
    const double inv = 1.0 / a[k + 11 * k];
    for (int i = k + 1; i < 11; ++i) a[i + 11 * k] *= inv;
    for (int j = k + 1; j < 11; ++j) {
      const double akj = a[k + 11 * j];
      if (akj == 0.0) continue;
      for (int i = k + 1; i < 11; ++i) a[i + 11 * j] -= a[i + 11 * k] * akj;
    }
  }
}

// b <- A⁻¹ b with luFactor's A, piv.
void luSolve(const Mat11& A, const int* piv, double* b) {
  const double* a = A.data();
  for (int k = 0; k < 11; ++k)
    if (piv[k] != k) std::swap(b[k], b[piv[k]]);
  for (int k = 0; k < 11; ++k) {
    const double bk = b[k];
    if (bk == 0.0) continue;
    for (int i = k + 1; i < 11; ++i) b[i] -= a[i + 11 * k] * bk;
  }
  for (int k = 10; k >= 0; --k) {
    b[k] /= a[k + 11 * k];
    const double bk = b[k];
    for (int i = 0; i < k; ++i) b[i] -= a[i + 11 * k] * bk;
  }
}

// X <- A⁻¹ X for 10 right sides at once, X row-major: every row operation runs over the 10 columns.
using Rows11x10 = Eigen::Matrix<double, 11, 10, Eigen::RowMajor>;
void luSolveRows(const Mat11& A, const int* piv, Rows11x10& X) {
  for (int k = 0; k < 11; ++k)
    if (piv[k] != k) X.row(k).swap(X.row(piv[k]));
  for (int k = 0; k < 11; ++k)
    for (int i = k + 1; i < 11; ++i) X.row(i) -= A(i, k) * X.row(k);
  for (int k = 10; k >= 0; --k) {
    X.row(k) *= 1.0 / A(k, k);
    for (int i = 0; i < k; ++i) X.row(i) -= A(i, k) * X.row(k);
  }
}
}  // namespace

ShiftedSolver3::ShiftedSolver3(const SpatialModel& model, double stabilization)
    : model_(model),
      omega_(stabilization),
      nb_(model.bodies()),
      nq_(model.dofs()),
      nt_(model.hasTorsion() ? model.bodies() : 0),
      vo_(nq_ + nt_),
      axial_(model.options().axial_flexibility) {
  body_.resize(nb_ + 1);  // + the pinned end's block (used when the bottom is pinned)
  for (Body& B : body_) {
    for (Mat7* m : {&B.M, &B.Kup}) m->setZero();
    for (Mat37* m : {&B.gE, &B.pE, &B.rE}) m->setZero();
    for (Vec7* v : {&B.gu, &B.pu, &B.ru}) v->setZero();
    B.L.setZero();
    B.Y.setZero();
    B.z.setZero();
    B.lu.setIdentity();
    for (int k = 0; k < 11; ++k) B.piv[k] = k;
  }
  S_.resize(nb_);
  t_diag_.assign(nt_, 1.0);
  t_mul_.assign(nt_, 0.0);
}

// Per rfe (u = [A, Δ, e], a = u''): M a + h(u, u') = Q + constraint forces. K, C gather -∂/∂(q, q') of the
// right side minus the left: the terms' own, ∂(M a + h)/∂(q, q') (axial: M and h move with e and Δ), the
// director multiplier μ on e (force μ e) and the joint force λ_{i+1} at E_i on Δ-e ([λ; e·λ; len λ]).
void ShiftedSolver3::setLinearization(const NaturalData& d, const Eigen::Ref<const VecX>& acc) {
  pinned_ = model_.bottom() == BottomBoundary::kPinned;  // read per linearisation, as derivative() does
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
    Mat7& M = B.M;
    M.setZero();
    M.block<3, 3>(kA, kA) = m * I3;
    M.block<3, 3>(kA, kE) = S * I3;
    M.block<3, 3>(kE, kA) = S * I3;
    M.block<3, 3>(kE, kE) = I * I3;
    Mat7& K = S_.K_diag[i];
    Mat7& C = S_.C_diag[i];
    // μ from the e rows: S A'' + S_k e Δ'' + I_A e'' + h_e = Q_e + len λ_{i+1} + μ e.
    const Vec3 he = d.h.segment<3>(kDofPerBody3 * i + kE), Qe = d.Q.segment<3>(kDofPerBody3 * i + kE);
    const Vec3 res = S * Add + Sk * Ddd * b.e + I * edd + he - Qe - b.len * L;
    const double mu = b.e.dot(res) / b.e.squaredNorm();
    K.block<3, 3>(kE, kE) -= mu * I3;
    if (axial_) {
      M.block<3, 1>(kA, kDelta3) = mk * b.e;
      M.block<1, 3>(kDelta3, kA) = mk * b.e.transpose();
      M.block<3, 1>(kE, kDelta3) = Sk * b.e;
      M.block<1, 3>(kDelta3, kE) = Sk * b.e.transpose();
      M(kDelta3, kDelta3) = mk * b.e.squaredNorm();
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
      for (Mat7* X : {&K, &C, &S_.K_sub[i], &S_.K_sup[i], &S_.C_sub[i]}) X->row(kDelta3).setZero(), X->col(kDelta3).setZero();
      M(kDelta3, kDelta3) = 1.0;
    }
    // E = A + len e: E'' = A'' + Δ'' e + len e'' + 2Δ' e', law E'' + 2ω E' + ω² E (+ prescribed).
    B.gE.setZero();
    B.gE.block<3, 3>(0, kA) = I3;
    B.gE.block<3, 3>(0, kE) = b.len * I3;
    if (axial_) B.gE.col(kDelta3) = b.e;
    B.pE = 2.0 * w * B.gE;
    B.rE = (w * w) * B.gE;
    B.pE.block<3, 3>(0, kE) += 2.0 * b.delta_dot * I3;
    B.rE.block<3, 3>(0, kE) += (Ddd + 2.0 * w * b.delta_dot) * I3;
    if (axial_) {
      B.pE.col(kDelta3) += 2.0 * b.e_dot;
      B.rE.col(kDelta3) += edd + 2.0 * w * b.e_dot;
    }
    // ½(e·e - 1): e·e'' + e'·e' + 2ω e·e' + ω² ½(e·e - 1) = 0.
    B.gu.setZero();
    B.pu.setZero();
    B.ru.setZero();
    B.gu.segment<3>(kE) = b.e;
    B.pu.segment<3>(kE) = 2.0 * b.e_dot + 2.0 * w * b.e;
    B.ru.segment<3>(kE) = edd + 2.0 * w * b.e_dot + (w * w) * b.e;
  }
  // K(i, i+1) once per linearisation (after the locked-Δ rows and columns are cleared above).
  for (int i = 0; i + 1 < nb_; ++i) body_[i].Kup = S_.K_sub[i + 1].transpose() + S_.K_sup[i + 1];
  linearized_ = true;
  factored_ = false;
}

void ShiftedSolver3::factor(double c) {
  const double s = (1.0 + omega_ * c) * (1.0 + omega_ * c), c2 = c * c;
  const Mat3 I3 = Mat3::Identity();
  Rows11x10 U;
  for (int i = 0; i < nb_; ++i) {
    Body& B = body_[i];
    Mat11& D = B.lu;
    D.setZero();
    D.block<3, 3>(0, 3 + kA) = s * I3;  // A_i's row (top or joint), g = [I 0 0]
    D.block<3, 3>(3 + kA, 0) = I3;
    D.block<7, 7>(3, 3) = B.M + c * S_.C_diag[i] + c2 * S_.K_diag[i];
    D.block<7, 1>(3, 10) = B.gu;
    D.block<1, 7>(10, 3) = (B.gu + c * B.pu + c2 * B.ru).transpose();
    if (i > 0) {
      const Body& P = body_[i - 1];
      // L: columns of x_v,i-1 only; row 10 (unit length) and column 10 of Y (ν) are zero.
      B.L.topRows<3>() = -(P.gE + c * P.pE + c2 * P.rE);
      B.L.bottomRows<7>() = c * S_.C_sub[i] + c2 * S_.K_sub[i];
      D.topLeftCorner<10, 10>() -= B.L.lazyProduct(P.Y.middleRows<7>(3));
    }
    luFactor(D, B.piv);
    if (i + 1 < blocks()) {
      U.setZero();
      U.block<7, 3>(3, 0) = -B.gE.transpose();
      if (i + 1 < nb_) U.block<7, 7>(3, 3) = (c * S_.C_sub[i + 1]).transpose() + c2 * B.Kup;
      luSolveRows(D, B.piv, U);
      B.Y = U;
    }
  }
  if (pinned_) {  // E_n = p_b: rows 0..2; the rest of the block is padding (identity)
    Body& B = body_[nb_];
    const Body& P = body_[nb_ - 1];
    Mat11& D = B.lu;
    D.setIdentity();
    D.block<3, 3>(0, 0).setZero();
    B.L.setZero();
    B.L.topRows<3>() = -(P.gE + c * P.pE + c2 * P.rE);
    D.topLeftCorner<10, 10>() -= B.L.lazyProduct(P.Y.middleRows<7>(3));
    luFactor(D, B.piv);
  }
  if (nt_ > 0) {  // spins: diagonal J_i + s (joints at i), off-diagonal -s between rows i, i+1 >= 1
    const double s = c * twistDamping(model_) + c * c * twistStiffness(model_);
    for (int i = 1; i < nt_; ++i) {
      t_diag_[i] = polarInertia(model_, i) + s * (i + 1 < nt_ ? 2.0 : 1.0);
      if (i > 1) {
        t_mul_[i] = -s / t_diag_[i - 1];
        t_diag_[i] -= t_mul_[i] * -s;
      }
    }
  }
  c_ = c;
  factored_ = true;
}

// Right side of block blk: rows g b_v - c r b_q, then M b_v - c K b_q, then the unit-length row.
void ShiftedSolver3::assembleRhs(int blk, const VecX& b, Vec11& r) const {
  const double c = c_, w2 = omega_ * omega_;
  auto bq = [&](int i) { return b.segment<7>(kDofPerBody3 * i); };
  auto bv = [&](int i) { return b.segment<7>(vo_ + kDofPerBody3 * i); };
  r.setZero();
  if (blk > 0) {
    const Body& P = body_[blk - 1];
    r.head<3>() = -(P.gE * bv(blk - 1) - c * (P.rE * bq(blk - 1)));
  }
  if (blk == nb_) return;  // the pinned end's block
  const Body& B = body_[blk];
  r.head<3>() += bv(blk).segment<3>(kA) - (c * w2) * bq(blk).segment<3>(kA);
  Vec7 kq = S_.K_diag[blk] * bq(blk);
  if (blk > 0) kq.noalias() += S_.K_sub[blk] * bq(blk - 1);
  if (blk + 1 < nb_) kq.noalias() += B.Kup * bq(blk + 1);
  r.segment<7>(3).noalias() = B.M * bv(blk) - c * kq;
  r[10] = B.gu.dot(bv(blk)) - c * B.ru.dot(bq(blk));
}

void ShiftedSolver3::solve(const VecX& b, VecX& x) {
  const int nblk = blocks();
  Vec11 r;
  for (int i = 0; i < nblk; ++i) {
    assembleRhs(i, b, r);
    if (i > 0) r.head<10>().noalias() -= body_[i].L * body_[i - 1].z.segment<7>(3);
    luSolve(body_[i].lu, body_[i].piv, r.data());
    body_[i].z = r;
  }
  for (int i = nblk - 2; i >= 0; --i) body_[i].z.noalias() -= body_[i].Y * body_[i + 1].z.head<10>();
  for (int i = 0; i < nb_; ++i) {
    const auto xv = body_[i].z.segment<7>(3);
    x.segment<7>(vo_ + kDofPerBody3 * i) = xv;
    x.segment<7>(kDofPerBody3 * i) = b.segment<7>(kDofPerBody3 * i) + c_ * xv;
  }
  if (nt_ == 0) return;
  // Spins: rows 1..n (rfe 0 held: x = b there), r_i = J_i b_ω,i - c (K_t b_θ)_i, then Thomas.
  const double k = twistStiffness(model_), s = c_ * twistDamping(model_) + c_ * c_ * k;
  auto bth = [&](int i) { return i > 0 && i < nt_ ? b[nq_ + i] : 0.0; };
  x[nq_] = b[nq_];
  x[vo_ + nq_] = b[vo_ + nq_];
  for (int i = 1; i < nt_; ++i) {
    double kq = k * (bth(i) - bth(i - 1));
    if (i + 1 < nt_) kq += k * (bth(i) - bth(i + 1));
    double r = polarInertia(model_, i) * b[vo_ + nq_ + i] - c_ * kq;
    if (i > 1) r -= t_mul_[i] * x[vo_ + nq_ + i - 1];
    x[vo_ + nq_ + i] = r;
  }
  for (int i = nt_ - 1; i >= 1; --i) {
    double r = x[vo_ + nq_ + i];
    if (i + 1 < nt_) r += s * x[vo_ + nq_ + i + 1];
    x[vo_ + nq_ + i] = r / t_diag_[i];
  }
  for (int i = 1; i < nt_; ++i) x[nq_ + i] = b[nq_ + i] + c_ * x[vo_ + nq_ + i];
}

}  // namespace spatial
}  // namespace riser_sim
