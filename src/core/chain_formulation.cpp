#include "riser_sim/chain_formulation.h"

#include <cmath>

#include "riser_sim/force_term.h"
#include "riser_sim/rfe_inertia.h"

namespace riser_sim {

ChainFormulation::ChainFormulation(const Model& model, double stabilization)
    : model_(model),
      k_(model.options().axial_flexibility ? 2 : 1),
      omega_(stabilization),
      shifted_(model, model.options().axial_flexibility ? 2 : 1) {
  const int nb = model.bodies();
  kin_.resize(nb);
  bias_.assign(nb, Vec2::Zero());
  Q_.setZero(model.dofs());
  h_.setZero(model.dofs());
  M_.assign(nb, Mat4::Zero());
  reactions_.joint.assign(nb + 1, Vec2::Zero());
  for (const auto& term : model.terms()) rigid_only_ = rigid_only_ && !term->hasInertia();
  lin_kin_.resize(nb);
  lin_M_.assign(nb, Mat4::Zero());
  lin_joint_.assign(nb + 1, Vec2::Zero());
  lin_h_.setZero(model.dofs());
  lin_r_.setZero(positionSize());
  lin_x_.setZero(positionSize());
  lin_S_.resize(nb);
}

void ChainFormulation::packState(const Kinematics& kin, VecX& y) const {
  const int nt = positionSize();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    if (k_ == 2) {
      y[2 * i] = b.delta;
      y[nt + 2 * i] = b.delta_dot;
    }
    y[k_ * i + k_ - 1] = b.phi;
    y[nt + k_ * i + k_ - 1] = b.phi_dot;
  }
  top_.p = kin[0].A;
  top_.v = kin[0].A_dot;
}

void ChainFormulation::chainKinematics(const VecX& y, const Vec2& p, const Vec2& v, Kinematics& kin) const {
  const int nt = positionSize();
  Vec2 A = p, Ad = v;
  for (int i = 0; i < model_.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = A;
    b.A_dot = Ad;
    b.delta = k_ == 2 ? y[2 * i] : 0.0;
    b.delta_dot = k_ == 2 ? y[nt + 2 * i] : 0.0;
    b.phi = y[k_ * i + k_ - 1];
    b.phi_dot = y[nt + k_ * i + k_ - 1];
    b.c = std::cos(b.phi);
    b.s = std::sin(b.phi);
    b.len = model_.rfe(i).length + b.delta;
    const Vec2 e(b.c, b.s), n(-b.s, b.c);
    A += b.len * e;
    Ad += b.delta_dot * e + (b.len * b.phi_dot) * n;
  }
}

void ChainFormulation::kinematics(const VecX& y, Kinematics& kin) const { chainKinematics(y, top_.p, top_.v, kin); }

void ChainFormulation::updateKinematics(const VecX& y, const PointMotion& top) {
  top_ = top;
  chainKinematics(y, top.p, top.v, kin_);
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin_[i];
    const double w = b.phi_dot;
    bias_[i] = (2.0 * b.delta_dot * w) * b.nrm() - (b.len * w * w) * b.e();
  }
}

void ChainFormulation::evaluateForces(double t) {
  Q_.setZero();
  last_term_power_ = addTermForcesAndPower(model_, term_data_, kin_, t, Q_);
}

void ChainFormulation::generalMassBlocks(double t) {
  rfeMassBlocks(model_, kin_, t, M_, h_);
}

void ChainFormulation::reactionsFromAccelerations(const AlignedVector<Vec2>& A_dd, const VecX& theta_dd,
                                                  const Vec2& tip_force) {
  // Rows A of rfe m: P A'' + B u'' + h_A = Q_A + f_m - f_{m+1}, f_m the force on rfes m..n at A_m.
  const int nb = model_.bodies();
  Vec2 f = tip_force;
  reactions_.joint[nb] = -f;
  for (int m = nb - 1; m >= 0; --m) {
    Vec4 qdd(A_dd[m].x(), A_dd[m].y(), k_ == 2 ? theta_dd[2 * m] : 0.0, theta_dd[k_ * m + k_ - 1]);
    f += (M_[m] * qdd).head<2>() + h_.segment<2>(4 * m) - Q_.segment<2>(4 * m);
    reactions_.joint[m] = -f;
  }
  reactions_.top = reactions_.joint[0];
  reactions_.bottom = pinned() ? tip_force : Vec2::Zero();
}

double ChainFormulation::constraintError(const VecX& y, const PointMotion& top) const {
  if (!pinned()) return 0.0;
  Vec2 E = top.p;
  for (int i = 0; i < model_.bodies(); ++i) {
    const double len = model_.rfe(i).length + (k_ == 2 ? y[2 * i] : 0.0), phi = y[k_ * i + k_ - 1];
    E += len * Vec2(std::cos(phi), std::sin(phi));
  }
  return (E - model_.bottomPoint()).norm();
}

double ChainFormulation::kineticEnergy(double t, const VecX& y) {
  chainKinematics(y, top_.p, top_.v, kin_);
  generalMassBlocks(t);
  double T = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin_[i];
    const Vec4 v(b.A_dot.x(), b.A_dot.y(), b.delta_dot, b.phi_dot);
    T += 0.5 * v.dot(M_[i] * v);
  }
  return T;
}

void ChainFormulation::linearize(double t) {
  lin_kin_ = kin_;
  lin_joint_ = reactions_.joint;
  rfeMassBlocks(model_, lin_kin_, t, lin_M_, lin_h_);
  lin_S_.setZero();
  addTermStiffness(model_, term_data_, lin_kin_, t, lin_S_);
  shifted_.setLinearization(lin_kin_, lin_M_, lin_S_, lin_joint_);
  shifted_c_ = 0.0;
}

void ChainFormulation::factorShifted(double c) {
  shifted_.factor(c);
  shifted_c_ = c;
}

// (I - cJ) x = b with J = [[0, I], [-W_M^-1 K, -W_M^-1 C]]:  (M + cC + c²K) x_v = M b_v - c K b_q,
// x_q = b_q + c x_v. A pinned end adds Gᵀ μ and the linearised Baumgarte row of the ODE,
// G a = -2ω G v - ω² G q (G = ∂A_{n+1}/∂θ, A_0 prescribed), on the increment: with c G a(x) = G x_v - G b_v
// and x_q = b_q + c x_v,  G x_v (1 + ωc)² = G b_v - ω² c G b_q.
void ChainFormulation::solveShifted(const VecX& b, VecX& x) {
  const int p = positionSize();
  const double c = shifted_c_;
  shifted_.massMinusStiffness(b.segment(p, p), b.head(p), c, lin_r_);
  Vec2 end = Vec2::Zero();
  if (pinned()) {
    const double wc = 1.0 + omega_ * c;
    end = (shifted_.endMotion(b.segment(p, p)) - (omega_ * omega_ * c) * shifted_.endMotion(b.head(p))) / (wc * wc);
  }
  shifted_.solve(lin_r_, lin_x_, end);
  x.segment(p, p) = lin_x_;
  x.head(p) = b.head(p) + c * lin_x_;
}

}  // namespace riser_sim
