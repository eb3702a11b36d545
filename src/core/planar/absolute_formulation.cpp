#include "riser_sim/planar/absolute_formulation.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "riser_sim/planar/force_term.h"
#include "riser_sim/line/rfe_inertia.h"

namespace riser_sim {

AbsoluteData::AbsoluteData(const AbsoluteFormulation& owner, const Model& model)
    : FormulationData(owner, model.bodies()) {
  const int nb = model.bodies(), nc = nb + 1;
  Q.setZero(model.dofs());
  h.setZero(model.dofs());
  M.resize(nb);
  Minv.resize(nb);
  comp.resize(nb);
  body_inv.assign(6 * nb, 0.0);
  diag.resize(nc);
  low.resize(nc);
  up.resize(nc);
  rhs.resize(nc);
  lambda.assign(nc, Vec2::Zero());
}

AbsoluteFormulation::AbsoluteFormulation(const Model& model, double stabilization)
    : Formulation(model), omega_(stabilization) {
  for (const auto& term : model.terms()) rigid_only_ = rigid_only_ && !term->hasInertia();
}

std::unique_ptr<FormulationData> AbsoluteFormulation::makeData() const {
  return std::make_unique<AbsoluteData>(*this, model_);
}

void AbsoluteFormulation::packState(const Kinematics& kin, VecX& y) const {
  const int nq = model_.dofs();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    y.segment<4>(4 * i) = Vec4(b.A.x(), b.A.y(), b.delta, b.phi);
    y.segment<4>(nq + 4 * i) = Vec4(b.A_dot.x(), b.A_dot.y(), b.delta_dot, b.phi_dot);
  }
}

void AbsoluteFormulation::kinematics(const VecX& y, const PointMotion&, Kinematics& kin) const {
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

bool AbsoluteFormulation::holdsState(const VecX& y, const Kinematics& kin) const {
  const int nq = model_.dofs();
  const bool axial = model_.options().axial_flexibility;
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    const double* q = y.data() + 4 * i;
    const double* v = y.data() + nq + 4 * i;
    if (!(b.A.x() == q[kX] && b.A.y() == q[kY] && b.A_dot.x() == v[kX] && b.A_dot.y() == v[kY] && b.phi == q[kPhi] &&
          b.phi_dot == v[kPhi] && (!axial || (b.delta == q[kDelta] && b.delta_dot == v[kDelta]))))
      return false;
  }
  return true;
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
void AbsoluteFormulation::rigidBody(int i, bool axial, AbsoluteData& d) const {
  const Rfe& r = model_.rfe(i);
  const BodyKinematics& b = d.kin[i];
  const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), I = r.inertiaAboutA(b.delta);
  double a_ee = 1.0 / m, g_d = 0.0, i_d = 0.0;
  if (axial) {
    const double s_d = mk - mk * mk / m;
    g_d = mk / (m * s_d);
    a_ee += g_d * mk / m;
    i_d = 1.0 / s_d;
  }
  const double s_p = I - S * S / m, g_p = S / (m * s_p), a_nn = 1.0 / m + g_p * S / m, i_p = 1.0 / s_p;
  double* k = d.body_inv.data() + 6 * i;
  k[0] = a_ee, k[1] = g_d, k[2] = i_d, k[3] = a_nn, k[4] = g_p, k[5] = i_p;

  const Vec4 f = d.Q.segment<4>(4 * i) - d.h.segment<4>(4 * i);
  const double fe = b.c * f[0] + b.s * f[1], fn = -b.s * f[0] + b.c * f[1];
  const double Ae = a_ee * fe - g_d * f[2], dd = -g_d * fe + i_d * f[2];
  const double An = a_nn * fn - g_p * f[3], pp = -g_p * fn + i_p * f[3];
  AbsoluteData::Compliance& c = d.comp[i];
  c.aA = Ae * b.e() + An * b.nrm();
  c.aE = (Ae + dd) * b.e() + (An + b.len * pp) * b.nrm() + 2.0 * b.delta_dot * b.phi_dot * b.nrm() -
         b.len * b.phi_dot * b.phi_dot * b.e();
  c.AA = rotated(b, a_ee, a_nn);
  c.AE = rotated(b, a_ee - g_d, a_nn - b.len * g_p);
  c.EE = rotated(b, a_ee - 2.0 * g_d + i_d, a_nn - 2.0 * b.len * g_p + b.len * b.len * i_p);
}

void AbsoluteFormulation::generalBody(int i, bool axial, AbsoluteData& d) const {
  const BodyKinematics& b = d.kin[i];
  Mat4& Mi = d.Minv[i];
  if (axial) {
    Mi = d.M[i].llt().solve(Mat4::Identity());
  } else {  // Δ locked: invert on (x, y, φ), zero the Δ row and column
    Eigen::Matrix3d m3;
    const int idx[3] = {kX, kY, kPhi};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m3(r, c) = d.M[i](idx[r], idx[c]);
    const Eigen::Matrix3d inv = m3.llt().solve(Eigen::Matrix3d::Identity());
    Mi.setZero();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) Mi(idx[r], idx[c]) = inv(r, c);
  }
  Mat24 G;
  G << 1, 0, b.c, -b.len * b.s, 0, 1, b.s, b.len * b.c;
  const Vec4 a = Mi * (d.Q.segment<4>(4 * i) - d.h.segment<4>(4 * i));
  const Mat42 V = Mi * G.transpose();
  AbsoluteData::Compliance& c = d.comp[i];
  c.aA = a.head<2>();
  c.aE = G * a + 2.0 * b.delta_dot * b.phi_dot * b.nrm() - b.len * b.phi_dot * b.phi_dot * b.e();
  c.AA = Mi.topLeftCorner<2, 2>();
  c.AE = V.topRows<2>();
  c.EE = G * V;
}

// q''_i for forces FA at A_i and FE at E_i (besides the applied ones).
void AbsoluteFormulation::bodyAcceleration(int i, bool axial, const Vec2& FA, const Vec2& FE, const AbsoluteData& d,
                                           double* qdd) const {
  const BodyKinematics& b = d.kin[i];
  Vec4 f = d.Q.segment<4>(4 * i) - d.h.segment<4>(4 * i);
  f.head<2>() += FA + FE;
  f[kDelta] += axial ? b.e().dot(FE) : 0.0;
  f[kPhi] += b.len * b.nrm().dot(FE);
  if (!rigid_only_) {
    Eigen::Map<Vec4> out(qdd);
    out = d.Minv[i] * f;
    return;
  }
  const double* k = d.body_inv.data() + 6 * i;
  const double fe = b.c * f[0] + b.s * f[1], fn = -b.s * f[0] + b.c * f[1];
  const double Ae = k[0] * fe - k[1] * f[2], An = k[3] * fn - k[4] * f[3];
  qdd[kX] = Ae * b.c - An * b.s;
  qdd[kY] = Ae * b.s + An * b.c;
  qdd[kDelta] = axial ? -k[1] * fe + k[2] * f[2] : 0.0;
  qdd[kPhi] = -k[4] * fn + k[5] * f[3];
}

void AbsoluteFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy,
                                     FormulationData& data) const {
  AbsoluteData& d = dataOf<AbsoluteData>(data);
  const int nb = model_.bodies(), nq = model_.dofs(), nc = constraints();
  const bool pinned = model_.bottom() == BottomBoundary::kPinned;
  const bool axial = model_.options().axial_flexibility;
  d.t = t;
  d.top = top;
  kinematics(y, top, d.kin);
  d.Q.setZero();
  d.term_power = addTermForcesAndPower(model_, d.term_data, d.kin, t, d.Q);
  if (rigid_only_) {
    for (int i = 0; i < nb; ++i) {
      const BodyKinematics& b = d.kin[i];
      const Rfe& r = model_.rfe(i);
      const double mk = r.mass_k, S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
      const double w2 = b.phi_dot * b.phi_dot, dw = 2.0 * b.delta_dot * b.phi_dot;
      d.h.segment<4>(4 * i) = Vec4(-mk * dw * b.s - S * w2 * b.c, mk * dw * b.c - S * w2 * b.s, -Sk * w2, Sk * dw);
      rigidBody(i, axial, d);
    }
  } else {
    rfeMassBlocks(model_, d.kin, t, d.M, d.h);
    for (int i = 0; i < nb; ++i) generalBody(i, axial, d);
  }

  // Constraint rows k = 0..n (+ n+1 when pinned): c_k = E_{k-1} - A_k, E_{-1} = top point;
  // force on rfe k at A_k is -λ_k, on rfe k-1 at its end +λ_k.
  const double w = omega_;
  double cmax = 0.0;
  for (int k = 0; k < nc; ++k) {
    Vec2 c, cd, r;
    Mat2 dk = Mat2::Zero();
    if (k == 0) {
      c = top.p - d.kin[0].A;
      cd = top.v - d.kin[0].A_dot;
      r = -top.a;
    } else {
      const BodyKinematics& bp = d.kin[k - 1];
      const Vec2 Ak = k < nb ? d.kin[k].A : model_.bottomPoint();
      const Vec2 Akd = k < nb ? d.kin[k].A_dot : Vec2::Zero();
      c = bp.end() - Ak;
      cd = bp.endVelocity() - Akd;
      r = -d.comp[k - 1].aE;
      dk += d.comp[k - 1].EE;
      d.low[k] = -d.comp[k - 1].AE.transpose();
    }
    if (k < nb) {
      r += d.comp[k].aA;
      dk += d.comp[k].AA;
      d.up[k] = (k < nb - 1 || pinned) ? Mat2(-d.comp[k].AE) : Mat2::Zero();
    }
    d.rhs[k] = r - 2.0 * w * cd - w * w * c;
    cmax = std::max(cmax, c.squaredNorm());
    d.diag[k] = dk;
  }
  // Block Thomas: forward elimination, back substitution.
  for (int k = 1; k < nc; ++k) {
    const Mat2 L = d.low[k] * d.diag[k - 1].inverse();
    d.diag[k] -= L * d.up[k - 1];
    d.rhs[k] -= L * d.rhs[k - 1];
  }
  d.lambda[nc - 1] = d.diag[nc - 1].inverse() * d.rhs[nc - 1];
  for (int k = nc - 2; k >= 0; --k) d.lambda[k] = d.diag[k].inverse() * (d.rhs[k] - d.up[k] * d.lambda[k + 1]);
  if (!pinned) d.lambda[nb] = Vec2::Zero();

  dy.head(nq) = y.segment(nq, nq);
  for (int i = 0; i < nb; ++i) bodyAcceleration(i, axial, -d.lambda[i], d.lambda[i + 1], d, dy.data() + nq + 4 * i);
  for (int k = 0; k <= nb; ++k) d.reactions.joint[k] = d.lambda[k];
  d.reactions.top = d.lambda[0];
  d.reactions.bottom = pinned ? Vec2(-d.lambda[nb]) : Vec2::Zero();
  d.constraint_error = std::sqrt(cmax);
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

}  // namespace riser_sim
