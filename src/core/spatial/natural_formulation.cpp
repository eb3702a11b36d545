#include "riser_sim/spatial/natural_formulation.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include <stdexcept>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/shifted_solver.h"

namespace riser_sim {
namespace spatial {

NaturalData::NaturalData(const Model3& model, bool dense_path) : kin(model.bodies()) {
  const int nb = model.bodies(), nc = nb + 1;
  reactions.joint.assign(nc, Vec3::Zero());
  Q.setZero(model.dofs());
  h.setZero(model.dofs());
  acc.setZero(model.dofs());
  dy.setZero(2 * (model.dofs() + (model.hasTorsion() ? nb : 0)));  // [q; θ; v; ω] (linearize's evaluation)
  body.resize(nb);
  if (dense_path) dense.resize(nb);
  diag.assign(nc, Mat3::Zero());
  up.assign(nc, Mat3::Zero());
  rhs.assign(nc, Vec3::Zero());
  lambda.assign(nc, Vec3::Zero());
  if (model.hasTorsion()) {
    twist.resize(nb);
    twist_y.setZero(2 * nb);
  }
  for (const auto& term : model.terms())
    if (term->hasInertia()) added.assign(nb, AddedMass3());
}

NaturalFormulation::NaturalFormulation(const Model3& model, double stabilization, bool closed_form)
    : model_(model), omega_(stabilization), closed_form_(closed_form) {}

void NaturalFormulation::packState(const Kinematics3& kin, VecX& y) const {
  const int nq = positionSize();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics3& b = kin[i];
    double* q = y.data() + kDofPerBody3 * i;
    double* v = y.data() + nq + kDofPerBody3 * i;
    for (int k = 0; k < 3; ++k) q[kA + k] = b.A[k], q[kE + k] = b.e[k], v[kA + k] = b.A_dot[k], v[kE + k] = b.e_dot[k];
    q[kDelta3] = b.delta;
    v[kDelta3] = b.delta_dot;
  }
}

BodyKinematics3 NaturalFormulation::body(const VecX& y, int i) const {
  const int nq = positionSize();
  const bool axial = model_.options().axial_flexibility;
  const double* q = y.data() + kDofPerBody3 * i;
  const double* v = y.data() + nq + kDofPerBody3 * i;
  BodyKinematics3 b;
  b.A = Vec3(q[kA], q[kA + 1], q[kA + 2]);
  b.A_dot = Vec3(v[kA], v[kA + 1], v[kA + 2]);
  b.delta = axial ? q[kDelta3] : 0.0;  // inextensible: Δ locked at 0
  b.delta_dot = axial ? v[kDelta3] : 0.0;
  b.e = Vec3(q[kE], q[kE + 1], q[kE + 2]);
  b.e_dot = Vec3(v[kE], v[kE + 1], v[kE + 2]);
  b.len = model_.rfe(i).length + b.delta;
  return b;
}

void NaturalFormulation::kinematics(const VecX& y, Kinematics3& kin) const {
  for (int i = 0; i < model_.bodies(); ++i) kin[i] = body(y, i);
}

// Mass block, its inverse with Δ locked when inextensible, then the unit-length constraint g·u'' = γ
// (g = [0; 0; e]) eliminated: W = M⁻¹ - u uᵀ/s, u = M⁻¹ g, s = g·u; free u'' = W f + u γ/s.
double NaturalFormulation::unitGamma(const BodyKinematics3& b) const {
  return -b.e_dot.squaredNorm() - 2.0 * omega_ * b.e.dot(b.e_dot) - 0.5 * omega_ * omega_ * (b.e.squaredNorm() - 1.0);
}

void NaturalFormulation::denseBody(int i, NaturalData& d) const {
  const Rfe& r = model_.rfe(i);
  const BodyKinematics3& b = d.kin[i];
  const bool axial = model_.options().axial_flexibility;
  const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
  const double I = r.inertiaAboutA(b.delta);
  Mat7 M = Mat7::Zero();
  M.block<3, 3>(kA, kA).diagonal().setConstant(m);
  M.block<3, 3>(kA, kE).diagonal().setConstant(S);
  M.block<3, 3>(kE, kA).diagonal().setConstant(S);
  M.block<3, 3>(kE, kE).diagonal().setConstant(I);
  if (axial) {
    M.block<3, 1>(kA, kDelta3) = mk * b.e;
    M.block<1, 3>(kDelta3, kA) = mk * b.e.transpose();
    M.block<3, 1>(kE, kDelta3) = Sk * b.e;
    M.block<1, 3>(kDelta3, kE) = Sk * b.e.transpose();
    M(kDelta3, kDelta3) = mk * b.e.squaredNorm();
  } else {
    M(kDelta3, kDelta3) = 1.0;
  }
  if (!d.added.empty()) addAddedMassBlock(d.added[i], b, axial, M);
  NaturalData::Body& c = d.body[i];
  NaturalData::DenseBody& dn = d.dense[i];
  Mat7& W = dn.W;
  W = M.llt().solve(Mat7::Identity());
  if (!axial) {
    W.row(kDelta3).setZero();
    W.col(kDelta3).setZero();
  }
  const Vec7 u = W.middleCols<3>(kE) * b.e;
  const double s = b.e.dot(u.tail<3>());
  W.noalias() -= (u / s) * u.transpose();
  const double gamma = unitGamma(b);
  const Vec7 f = d.Q.segment<7>(kDofPerBody3 * i) - d.h.segment<7>(kDofPerBody3 * i);
  c.a.noalias() = W * f;
  c.a += (gamma / s) * u;
  // B_E = [I, e, len I]: E'' = B_E u'' + 2Δ' e'.
  dn.WE = W.middleCols<3>(kA) + W.col(kDelta3) * b.e.transpose() + b.len * W.middleCols<3>(kE);
  c.AA = W.block<3, 3>(kA, kA);
  c.AE = dn.WE.middleRows<3>(kA);
  c.EE = dn.WE.middleRows<3>(kA) + b.e * dn.WE.row(kDelta3) + b.len * dn.WE.middleRows<3>(kE);
  c.aA = c.a.segment<3>(kA);
  c.aE = c.a.segment<3>(kA) + c.a[kDelta3] * b.e + b.len * c.a.segment<3>(kE) + 2.0 * b.delta_dot * b.e_dot;
}

// With n = e/ρ the mass matrix splits exactly: along n the rows (A·n, Δ, n·e) with n·e'' = γ/ρ prescribed
// by the unit-length constraint, leaving [[m, m_k ρ], [m_k ρ, m_k ρ²]] on (A·n, Δ); across n, per
// direction, [[m, S], [S, I_A]] on (A⊥, e⊥). Δ locked (inextensible): m alone along n.
void NaturalFormulation::closedFormBody(int i, NaturalData& d) const {
  const Rfe& r = model_.rfe(i);
  const BodyKinematics3& b = d.kin[i];
  NaturalData::Body& c = d.body[i];
  // Along n (t) and across it (n): the rfe's own moments plus the added mass's (added_mass.h).
  const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), I = r.inertiaAboutA(b.delta);
  const AddedMass3 a = d.added.empty() ? AddedMass3() : d.added[i];
  const double m_t = m + a.axial.m, mk_t = mk + a.axial.mk, S_t = S + a.axial.S;
  const double m_n = m + a.normal.m, S_n = S + a.normal.S, I_n = I + a.normal.I;
  c.rho = b.e.norm();
  c.n = b.e / c.rho;
  if (model_.options().axial_flexibility) {
    const double det = mk_t * c.rho * c.rho * (m_t - mk_t);
    c.a_aa = mk_t * c.rho * c.rho / det;
    c.a_ad = -mk_t * c.rho / det;
    c.a_dd = m_t / det;
    c.Sk_rho = (r.firstMomentK(b.delta) + a.axial.Sk) * c.rho;
  } else {
    c.a_aa = 1.0 / m_t;
    c.a_ad = c.a_dd = c.Sk_rho = 0.0;
  }
  const double det = m_n * I_n - S_n * S_n;
  c.t_AA = I_n / det;
  c.t_Ae = -S_n / det;
  c.t_ee = m_n / det;
  c.S = S_t;
  c.bdd = unitGamma(b) / c.rho;
  closedFormAcceleration(c, d.Q.segment<7>(kDofPerBody3 * i) - d.h.segment<7>(kDofPerBody3 * i), c.a.data());
  // Compliances p n nᵀ + q (I - n nᵀ): a unit force at E_i adds [F; ρ n·F; len F] to f, and E'' = A'' + ρ Δ'' n + len
  // e''.
  const double len = b.len, rho = c.rho;
  const Mat3 N = c.n * c.n.transpose();
  auto split = [&N](double p, double q, Mat3& out) {
    out = (p - q) * N;
    out.diagonal().array() += q;
  };
  split(c.a_aa, c.t_AA, c.AA);
  split(c.a_aa + rho * c.a_ad, c.t_AA + len * c.t_Ae, c.AE);
  split(c.a_aa + 2.0 * rho * c.a_ad + rho * rho * c.a_dd, c.t_AA + 2.0 * len * c.t_Ae + len * len * c.t_ee, c.EE);
  c.aA = c.a.segment<3>(kA);
  c.aE = c.a.segment<3>(kA) + c.a[kDelta3] * b.e + len * c.a.segment<3>(kE) + 2.0 * b.delta_dot * b.e_dot;
}

void NaturalFormulation::closedFormAcceleration(const NaturalData::Body& c, const Vec7& f, double* udd) {
  const Vec3 fA = f.segment<3>(kA), fe = f.segment<3>(kE);
  const double nA = c.n.dot(fA), ne = c.n.dot(fe);
  const double fa = nA - c.S * c.bdd, fd = f[kDelta3] - c.Sk_rho * c.bdd;
  const Vec3 pA = fA - nA * c.n, pe = fe - ne * c.n;
  const Vec3 A = (c.a_aa * fa + c.a_ad * fd) * c.n + c.t_AA * pA + c.t_Ae * pe;
  const Vec3 e = c.bdd * c.n + c.t_Ae * pA + c.t_ee * pe;
  for (int k = 0; k < 3; ++k) udd[kA + k] = A[k], udd[kE + k] = e[k];
  udd[kDelta3] = c.a_ad * fa + c.a_dd * fd;
}

void NaturalFormulation::derivative(double t, const VecX& y, const PointMotion3& top, VecX& dy, NaturalData& d) const {
  const int nb = model_.bodies(), nq = model_.dofs(), vo = positionSize(), nt = twistDofs();
  const bool pinned = model_.bottom() == BottomBoundary::kPinned;
  d.t = t;
  d.top = top;
  if (pinned) d.bottom = model_.bottomAt(t);
  kinematics(y, d.kin);
  d.Q.setZero();
  d.term_power = 0.0;
  for (const auto& term : model_.terms()) d.term_power += term->addForcesAndPower(model_, d.kin, t, d.Q);
  if (!d.added.empty()) {
    std::fill(d.added.begin(), d.added.end(), AddedMass3());
    for (const auto& term : model_.terms())
      if (term->hasInertia()) term->addInertia(model_, d.kin, d.added);
  }
  if (nt > 0) {
    d.twist_y.head(nt) = y.segment(nq, nt);
    d.twist_y.tail(nt) = y.segment(vo + nq, nt);
    if (firstSpin(model_) > 0) d.twist_y[0] = d.twist_y[nt] = 0.0;  // rfe 0 is held by the hang-off
    turnHangOff(d.twist.frames, top.R, top.w, firstSpin(model_) > 0);
    d.term_power += addTwistForces(model_, d.kin, d.twist_y.data(), d.twist_y.data() + nt, d.twist, d.Q);
  }
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics3& b = d.kin[i];
    const Rfe& r = model_.rfe(i);
    const double w = 2.0 * b.delta_dot;
    double* h = d.h.data() + kDofPerBody3 * i;
    for (int k = 0; k < 3; ++k)
      h[kA + k] = w * r.mass_k * b.e_dot[k], h[kE + k] = w * r.firstMomentK(b.delta) * b.e_dot[k];
    h[kDelta3] = w * r.mass_k * b.e.dot(b.e_dot);
    if (!d.added.empty()) addAddedVelocityTerms(d.added[i], b, h);
    if (closed_form_)
      closedFormBody(i, d);
    else
      denseBody(i, d);
  }

  jointReactions(d);

  dy.head(nq) = y.segment(vo, nq);
  for (int i = 0; i < nb; ++i) {
    const NaturalData::Body& c = d.body[i];
    if (closed_form_) {  // f + B_Aᵀ(-λ_i) + B_Eᵀ λ_{i+1}
      const BodyKinematics3& b = d.kin[i];
      const Vec3& L = d.lambda[i + 1];
      Vec7 f = d.Q.segment<7>(kDofPerBody3 * i) - d.h.segment<7>(kDofPerBody3 * i);
      f.segment<3>(kA) += L - d.lambda[i];
      f[kDelta3] += b.e.dot(L);
      f.segment<3>(kE) += b.len * L;
      closedFormAcceleration(c, f, dy.data() + vo + kDofPerBody3 * i);
    } else {
      dy.segment<7>(vo + kDofPerBody3 * i).noalias() =
          c.a - d.dense[i].W.middleCols<3>(kA) * d.lambda[i] + d.dense[i].WE * d.lambda[i + 1];
    }
  }
  for (int k = 0; k <= nb; ++k) d.reactions.joint[k] = d.lambda[k];
  d.reactions.top = d.lambda[0];
  d.reactions.bottom = pinned ? Vec3(-d.lambda[nb]) : Vec3::Zero();
  d.acc = dy.segment(vo, nq);
  if (nt > 0) {  // θ' = ω - a(c, e)·e' (the chart's reference turns with e), J ω' = moment
    dy[nq] = dy[vo + nq] = 0.0;
    for (int i = firstSpin(model_); i < nb; ++i) {
      const BodyKinematics3& b = d.kin[i];
      dy[nq + i] = d.twist_y[nt + i] - spinConnection(d.twist.frames.centre[i], b.e / b.e.norm()).dot(b.e_dot);
      dy[vo + nq + i] = d.twist.moment[i] / polarInertia(model_, i);
    }
    const Vec3& h = d.twist.frames.top_axis;
    const Vec3 n0 = d.kin[0].e / d.kin[0].e.norm();
    const double held = hangOffTwist(model_, d.twist);
    d.reactions.top_twist = held;
    d.reactions.top_twist_moment = held / (1.0 + h.dot(n0)) * (h + n0);
  }
}

void NaturalFormulation::initTwist(const VecX& y, NaturalData& d, const Mat3& R0, const HangOff& hang_off) const {
  if (!model_.hasTorsion()) return;
  kinematics(y, d.kin);
  initTwistFrames(d.kin, d.twist.frames, model_.bendingAxis(), hang_off);
  holdHangOff(d.twist.frames, R0);
  d.t = std::numeric_limits<double>::quiet_NaN();  // the charts changed: no evaluation is current
}

void NaturalFormulation::rechartTwist(const VecX& y, const PointMotion3& top, NaturalData& d) const {
  if (!model_.hasTorsion()) return;
  kinematics(y, d.kin);
  turnHangOff(d.twist.frames, top.R, top.w, firstSpin(model_) > 0);
  rechartTwistFrames(d.kin, d.twist.frames, firstSpin(model_));
  d.t = std::numeric_limits<double>::quiet_NaN();
}

double NaturalFormulation::twistEnergy(const VecX& y, const PointMotion3& top, NaturalData& d) const {
  const int nt = twistDofs();
  if (nt == 0) return 0.0;
  kinematics(y, d.kin);
  turnHangOff(d.twist.frames, top.R, top.w, firstSpin(model_) > 0);
  d.t = std::numeric_limits<double>::quiet_NaN();
  d.twist_y.head(nt) = y.segment(model_.dofs(), nt);
  if (firstSpin(model_) > 0) d.twist_y[0] = 0.0;
  return spatial::twistEnergy(model_, d.kin, d.twist_y.data(), d.twist);
}

std::unique_ptr<ShiftedSolver3> NaturalFormulation::makeShifted() const {
  return std::make_unique<ShiftedSolver3>(model_, omega_);
}

bool NaturalFormulation::evaluatedAt(double t, const VecX& y, const NaturalData& d) const {
  if (d.t != t) return false;
  const int nt = twistDofs(), nq = model_.dofs();
  for (int i = firstSpin(model_); i < nt; ++i)
    if (y[nq + i] != d.twist_y[i] || y[positionSize() + nq + i] != d.twist_y[nt + i]) return false;
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics3 b = body(y, i);
    const BodyKinematics3& k = d.kin[i];
    if (!(b.A == k.A && b.A_dot == k.A_dot && b.delta == k.delta && b.delta_dot == k.delta_dot && b.e == k.e &&
          b.e_dot == k.e_dot))
      return false;
  }
  return true;
}

void NaturalFormulation::linearize(double t, const VecX& y, const PointMotion3& top, NaturalData& d,
                                   ShiftedSolver3& s) const {
  if (!evaluatedAt(t, y, d)) derivative(t, y, top, d.dy, d);
  s.setLinearization(d, d.acc);
}

void NaturalFormulation::factorShifted(double c, ShiftedSolver3& s) const {
  if (!s.linearized()) throw std::logic_error("spatial natural formulation: factorShifted() before linearize()");
  s.factor(c);
}

void NaturalFormulation::solveShifted(const VecX& b, VecX& x, ShiftedSolver3& s) const {
  if (!s.factored()) throw std::logic_error("spatial natural formulation: solveShifted() before factorShifted()");
  s.solve(b, x);
}

}  // namespace spatial
}  // namespace riser_sim
