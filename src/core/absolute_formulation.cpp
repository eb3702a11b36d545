#include "riser_sim/absolute_formulation.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "riser_sim/force_term.h"

namespace riser_sim {

AbsoluteFormulation::AbsoluteFormulation(const Model& model, double stabilization)
    : model_(model), omega_(stabilization) {
  const int nb = model.bodies(), nc = nb + 1;
  kin_.resize(nb);
  Q_.setZero(model.dofs());
  h_.setZero(model.dofs());
  M_.resize(nb);
  Minv_.resize(nb);
  U_.resize(nb);
  V_.resize(nb);
  a_.resize(nb);
  G_.resize(nb);
  gamma_.resize(nb);
  diag_.resize(nc);
  low_.resize(nc);
  up_.resize(nc);
  rhs_.resize(nc);
  lambda_.assign(nc, Vec2::Zero());
  reactions_.joint.assign(nc, Vec2::Zero());
}

void AbsoluteFormulation::packState(const Kinematics& kin, VecX& y) const {
  const int nq = model_.dofs();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    y.segment<4>(4 * i) = Vec4(b.A.x(), b.A.y(), b.delta, b.phi);
    y.segment<4>(nq + 4 * i) = Vec4(b.A_dot.x(), b.A_dot.y(), b.delta_dot, b.phi_dot);
  }
}

void AbsoluteFormulation::kinematics(const VecX& y, Kinematics& kin) const {
  const int nq = model_.dofs();
  const bool axial = model_.options().axial_flexibility;
  for (int i = 0; i < model_.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    const double* q = y.data() + 4 * i;
    const double* v = y.data() + nq + 4 * i;
    b.A = Vec2(q[kX], q[kY]);
    b.A_dot = Vec2(v[kX], v[kY]);
    b.delta = axial ? q[kDelta] : 0.0;
    b.delta_dot = axial ? v[kDelta] : 0.0;
    b.phi = q[kPhi];
    b.phi_dot = v[kPhi];
    b.c = std::cos(b.phi);
    b.s = std::sin(b.phi);
    b.len = model_.rfe(i).length + b.delta;
  }
}

void AbsoluteFormulation::massBlocks(double t) {
  for (int i = 0; i < model_.bodies(); ++i) {
    const Rfe& r = model_.rfe(i);
    const BodyKinematics& b = kin_[i];
    double m = 0, mk = 0, S = 0, Sk = 0, I = 0;
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      const double s = part.s0 + part.kappa * b.delta;
      m += part.mass;
      mk += part.mass * part.kappa;
      S += part.mass * s;
      Sk += part.mass * part.kappa * s;
      I += part.mass * s * s + part.inertia;
    }
    Mat4& M = M_[i];
    M << m, 0, mk * b.c, -S * b.s,  //
        0, m, mk * b.s, S * b.c,    //
        mk * b.c, mk * b.s, mk, 0,  //
        -S * b.s, S * b.c, 0, I;
    const double w2 = b.phi_dot * b.phi_dot, dw = 2.0 * b.delta_dot * b.phi_dot;
    h_.segment<4>(4 * i) = Vec4(-mk * dw * b.s - S * w2 * b.c, mk * dw * b.c - S * w2 * b.s, -Sk * w2, Sk * dw);
  }
  for (const auto& term : model_.terms())
    if (term->hasInertia()) term->addInertia(model_, kin_, t, M_, h_);
}

void AbsoluteFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) {
  const int nb = model_.bodies(), nq = model_.dofs(), nc = constraints();
  const bool pinned = model_.bottom() == BottomBoundary::kPinned;
  const bool axial = model_.options().axial_flexibility;
  kinematics(y, kin_);
  Q_.setZero();
  for (const auto& term : model_.terms()) term->addForces(model_, kin_, t, Q_);
  massBlocks(t);

  for (int i = 0; i < nb; ++i) {
    const BodyKinematics& b = kin_[i];
    Mat4& Mi = Minv_[i];
    if (axial) {
      Mi = M_[i].llt().solve(Mat4::Identity());
    } else {  // Δ locked: invert on (x, y, φ), zero the Δ row and column
      Eigen::Matrix3d m3;
      const int idx[3] = {kX, kY, kPhi};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m3(r, c) = M_[i](idx[r], idx[c]);
      const Eigen::Matrix3d inv = m3.llt().solve(Eigen::Matrix3d::Identity());
      Mi.setZero();
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Mi(idx[r], idx[c]) = inv(r, c);
    }
    a_[i] = Mi * (Q_.segment<4>(4 * i) - h_.segment<4>(4 * i));
    Mat24& G = G_[i];
    G << 1, 0, b.c, -b.len * b.s, 0, 1, b.s, b.len * b.c;
    U_[i] = Mi.leftCols<2>();
    V_[i] = Mi * G.transpose();
    gamma_[i] = 2.0 * b.delta_dot * b.phi_dot * b.nrm() - b.len * b.phi_dot * b.phi_dot * b.e();
  }

  // Constraint rows k = 0..n (+ n+1 when pinned): c_k = E_{k-1} - A_k, E_{-1} = top point.
  const double w = omega_;
  for (int k = 0; k < nc; ++k) {
    Vec2 c, cd, r;
    Mat2 d = Mat2::Zero();
    if (k == 0) {
      c = top.p - kin_[0].A;
      cd = top.v - kin_[0].A_dot;
      r = -top.a;
    } else {
      const BodyKinematics& bp = kin_[k - 1];
      const Vec2 Ak = k < nb ? kin_[k].A : model_.bottomPoint();
      const Vec2 Akd = k < nb ? kin_[k].A_dot : Vec2::Zero();
      c = bp.end() - Ak;
      cd = bp.endVelocity() - Akd;
      r = -gamma_[k - 1] - G_[k - 1] * a_[k - 1];
      d += G_[k - 1] * V_[k - 1];
      low_[k] = -G_[k - 1] * U_[k - 1];
    }
    if (k < nb) {
      r += a_[k].head<2>();
      d += U_[k].topRows<2>();
      up_[k] = (k < nb - 1 || pinned) ? Mat2(-V_[k].topRows<2>()) : Mat2::Zero();
    }
    rhs_[k] = r - 2.0 * w * cd - w * w * c;
    diag_[k] = d;
  }
  // Block Thomas: forward elimination, back substitution.
  for (int k = 1; k < nc; ++k) {
    const Mat2 L = low_[k] * diag_[k - 1].inverse();
    diag_[k] -= L * up_[k - 1];
    rhs_[k] -= L * rhs_[k - 1];
  }
  lambda_[nc - 1] = diag_[nc - 1].inverse() * rhs_[nc - 1];
  for (int k = nc - 2; k >= 0; --k) lambda_[k] = diag_[k].inverse() * (rhs_[k] - up_[k] * lambda_[k + 1]);
  if (!pinned) lambda_[nb] = Vec2::Zero();

  dy.head(nq) = y.segment(nq, nq);
  for (int i = 0; i < nb; ++i) {
    Vec4 acc = a_[i] - U_[i] * lambda_[i];
    if (i + 1 < nb || pinned) acc += V_[i] * lambda_[i + 1];
    dy.segment<4>(nq + 4 * i) = acc;
  }
  for (int k = 0; k <= nb; ++k) reactions_.joint[k] = lambda_[k];
  reactions_.top = lambda_[0];
  reactions_.bottom = pinned ? Vec2(-lambda_[nb]) : Vec2::Zero();
}

double AbsoluteFormulation::constraintError(const VecX& y, const PointMotion& top) const {
  const int nb = model_.bodies(), nq = model_.dofs();
  const bool axial = model_.options().axial_flexibility;
  auto endOf = [&](int i) {
    const double* q = y.data() + 4 * i;
    const double len = model_.rfe(i).length + (axial ? q[kDelta] : 0.0);
    return Vec2(q[kX] + len * std::cos(q[kPhi]), q[kY] + len * std::sin(q[kPhi]));
  };
  (void)nq;
  double err = (top.p - Vec2(y[0], y[1])).norm();
  for (int k = 1; k < nb; ++k) err = std::max(err, (endOf(k - 1) - Vec2(y[4 * k], y[4 * k + 1])).norm());
  if (model_.bottom() == BottomBoundary::kPinned) err = std::max(err, (endOf(nb - 1) - model_.bottomPoint()).norm());
  return err;
}

double AbsoluteFormulation::kineticEnergy(double t, const VecX& y) {
  kinematics(y, kin_);
  massBlocks(t);
  const int nq = model_.dofs();
  double T = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    Vec4 v = y.segment<4>(nq + 4 * i);
    if (!model_.options().axial_flexibility) v[kDelta] = 0.0;
    T += 0.5 * v.dot(M_[i] * v);
  }
  return T;
}

}  // namespace riser_sim
