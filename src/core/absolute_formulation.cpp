#include "riser_sim/absolute_formulation.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "riser_sim/force_term.h"
#include "riser_sim/rfe_inertia.h"

namespace riser_sim {

AbsoluteFormulation::AbsoluteFormulation(const Model& model, double stabilization)
    : model_(model), omega_(stabilization) {
  const int nb = model.bodies(), nc = nb + 1;
  kin_.resize(nb);
  Q_.setZero(model.dofs());
  h_.setZero(model.dofs());
  M_.resize(nb);
  Minv_.resize(nb);
  comp_.resize(nb);
  body_inv_.assign(6 * nb, 0.0);
  diag_.resize(nc);
  low_.resize(nc);
  up_.resize(nc);
  rhs_.resize(nc);
  lambda_.assign(nc, Vec2::Zero());
  reactions_.joint.assign(nc, Vec2::Zero());
  rigid_only_ = true;
  for (const auto& term : model.terms()) rigid_only_ = rigid_only_ && !term->hasInertia();
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
  rfeMassBlocks(model_, kin_, t, M_, h_);
}

namespace {
// R diag(p, q) R^T with R = [e n].
inline Mat2 rotated(const BodyKinematics& b, double p, double q) {
  const double cc = b.c * b.c, ss = b.s * b.s, cs = b.c * b.s;
  Mat2 r;
  r << p * cc + q * ss, (p - q) * cs, (p - q) * cs, p * ss + q * cc;
  return r;
}
}  // namespace

// Rigid parts only: in the rfe frame (e, n) the mass matrix splits into two 2x2 blocks, (e, Δ) and
// (n, φ), with the closed-form inverses [[a_ee, -g_d], [-g_d, i_d]] and [[a_nn, -g_p], [-g_p, i_p]].
void AbsoluteFormulation::rigidBody(int i, bool axial) {
  const Rfe& r = model_.rfe(i);
  const BodyKinematics& b = kin_[i];
  const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), I = r.inertiaAboutA(b.delta);
  double a_ee = 1.0 / m, g_d = 0.0, i_d = 0.0;
  if (axial) {
    const double s_d = mk - mk * mk / m;
    g_d = mk / (m * s_d);
    a_ee += g_d * mk / m;
    i_d = 1.0 / s_d;
  }
  const double s_p = I - S * S / m, g_p = S / (m * s_p), a_nn = 1.0 / m + g_p * S / m, i_p = 1.0 / s_p;
  double* k = body_inv_.data() + 6 * i;
  k[0] = a_ee, k[1] = g_d, k[2] = i_d, k[3] = a_nn, k[4] = g_p, k[5] = i_p;

  const Vec4 f = Q_.segment<4>(4 * i) - h_.segment<4>(4 * i);
  const double fe = b.c * f[0] + b.s * f[1], fn = -b.s * f[0] + b.c * f[1];
  const double Ae = a_ee * fe - g_d * f[2], dd = -g_d * fe + i_d * f[2];
  const double An = a_nn * fn - g_p * f[3], pp = -g_p * fn + i_p * f[3];
  Compliance& c = comp_[i];
  c.aA = Ae * b.e() + An * b.nrm();
  c.aE = (Ae + dd) * b.e() + (An + b.len * pp) * b.nrm() + 2.0 * b.delta_dot * b.phi_dot * b.nrm() -
         b.len * b.phi_dot * b.phi_dot * b.e();
  c.AA = rotated(b, a_ee, a_nn);
  c.AE = rotated(b, a_ee - g_d, a_nn - b.len * g_p);
  c.EE = rotated(b, a_ee - 2.0 * g_d + i_d, a_nn - 2.0 * b.len * g_p + b.len * b.len * i_p);
}

void AbsoluteFormulation::generalBody(int i, bool axial) {
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
  Mat24 G;
  G << 1, 0, b.c, -b.len * b.s, 0, 1, b.s, b.len * b.c;
  const Vec4 a = Mi * (Q_.segment<4>(4 * i) - h_.segment<4>(4 * i));
  const Mat42 V = Mi * G.transpose();
  Compliance& c = comp_[i];
  c.aA = a.head<2>();
  c.aE = G * a + 2.0 * b.delta_dot * b.phi_dot * b.nrm() - b.len * b.phi_dot * b.phi_dot * b.e();
  c.AA = Mi.topLeftCorner<2, 2>();
  c.AE = V.topRows<2>();
  c.EE = G * V;
}

// q''_i for forces FA at A_i and FE at E_i (besides the applied ones).
void AbsoluteFormulation::bodyAcceleration(int i, bool axial, const Vec2& FA, const Vec2& FE, double* qdd) const {
  const BodyKinematics& b = kin_[i];
  Vec4 f = Q_.segment<4>(4 * i) - h_.segment<4>(4 * i);
  f.head<2>() += FA + FE;
  f[kDelta] += axial ? b.e().dot(FE) : 0.0;
  f[kPhi] += b.len * b.nrm().dot(FE);
  if (!rigid_only_) {
    Eigen::Map<Vec4> out(qdd);
    out = Minv_[i] * f;
    return;
  }
  const double* k = body_inv_.data() + 6 * i;
  const double fe = b.c * f[0] + b.s * f[1], fn = -b.s * f[0] + b.c * f[1];
  const double Ae = k[0] * fe - k[1] * f[2], An = k[3] * fn - k[4] * f[3];
  qdd[kX] = Ae * b.c - An * b.s;
  qdd[kY] = Ae * b.s + An * b.c;
  qdd[kDelta] = axial ? -k[1] * fe + k[2] * f[2] : 0.0;
  qdd[kPhi] = -k[4] * fn + k[5] * f[3];
}

void AbsoluteFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) {
  const int nb = model_.bodies(), nq = model_.dofs(), nc = constraints();
  const bool pinned = model_.bottom() == BottomBoundary::kPinned;
  const bool axial = model_.options().axial_flexibility;
  kinematics(y, kin_);
  Q_.setZero();
  last_term_power_ = addTermForcesAndPower(model_, term_data_, kin_, t, Q_);
  if (rigid_only_) {
    for (int i = 0; i < nb; ++i) {
      const BodyKinematics& b = kin_[i];
      const Rfe& r = model_.rfe(i);
      const double mk = r.mass_k, S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
      const double w2 = b.phi_dot * b.phi_dot, dw = 2.0 * b.delta_dot * b.phi_dot;
      h_.segment<4>(4 * i) = Vec4(-mk * dw * b.s - S * w2 * b.c, mk * dw * b.c - S * w2 * b.s, -Sk * w2, Sk * dw);
      rigidBody(i, axial);
    }
  } else {
    massBlocks(t);
    for (int i = 0; i < nb; ++i) generalBody(i, axial);
  }

  // Constraint rows k = 0..n (+ n+1 when pinned): c_k = E_{k-1} - A_k, E_{-1} = top point;
  // force on rfe k at A_k is -λ_k, on rfe k-1 at its end +λ_k.
  const double w = omega_;
  double cmax = 0.0;
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
      r = -comp_[k - 1].aE;
      d += comp_[k - 1].EE;
      low_[k] = -comp_[k - 1].AE.transpose();
    }
    if (k < nb) {
      r += comp_[k].aA;
      d += comp_[k].AA;
      up_[k] = (k < nb - 1 || pinned) ? Mat2(-comp_[k].AE) : Mat2::Zero();
    }
    rhs_[k] = r - 2.0 * w * cd - w * w * c;
    cmax = std::max(cmax, c.squaredNorm());
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
  for (int i = 0; i < nb; ++i) bodyAcceleration(i, axial, -lambda_[i], lambda_[i + 1], dy.data() + nq + 4 * i);
  for (int k = 0; k <= nb; ++k) reactions_.joint[k] = lambda_[k];
  reactions_.top = lambda_[0];
  reactions_.bottom = pinned ? Vec2(-lambda_[nb]) : Vec2::Zero();
  last_constraint_error_ = std::sqrt(cmax);
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
