#include "riser_sim/planar/chain_formulation.h"

#include <cmath>

#include "riser_sim/planar/chain_kinematics.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/line/rfe_inertia.h"

namespace riser_sim {

ChainData::ChainData(const ChainFormulation& owner, const Model& model)
    : FormulationData(owner, model.bodies()), shifted(model, chainDofsPerRfe(model)) {
  const int nb = model.bodies(), p = chainDofsPerRfe(model) * nb;
  bias.assign(nb, Vec2::Zero());
  Q.setZero(model.dofs());
  h.setZero(model.dofs());
  M.assign(nb, Mat4::Zero());
  lin_kin.resize(nb);
  lin_M.assign(nb, Mat4::Zero());
  lin_joint.assign(nb + 1, Vec2::Zero());
  lin_h.setZero(model.dofs());
  lin_r.setZero(p);
  lin_x.setZero(p);
  lin_dy.setZero(2 * p);
  lin_S.resize(nb);
}

ChainFormulation::ChainFormulation(const Model& model, double stabilization)
    : Formulation(model), k_(chainDofsPerRfe(model)), omega_(stabilization) {
  for (const auto& term : model.terms()) rigid_only_ = rigid_only_ && !term->hasInertia();
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
}

void ChainFormulation::kinematics(const VecX& y, const PointMotion& top, Kinematics& kin) const {
  chainKinematics(model_, top.p, top.v, y.data(), y.data() + positionSize(), kin);
}

bool ChainFormulation::holdsState(const VecX& y, const Kinematics& kin) const {
  const int nt = positionSize();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    const int c = k_ * i + k_ - 1;
    if (!(b.phi == y[c] && b.phi_dot == y[nt + c] &&
          (k_ == 1 || (b.delta == y[2 * i] && b.delta_dot == y[nt + 2 * i]))))
      return false;
  }
  return true;
}

void ChainFormulation::beginEvaluation(double t, const VecX& y, const PointMotion& top, ChainData& d) const {
  d.t = t;
  d.top = top;
  kinematics(y, top, d.kin);
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = d.kin[i];
    const double w = b.phi_dot;
    d.bias[i] = (2.0 * b.delta_dot * w) * b.nrm() - (b.len * w * w) * b.e();
  }
  d.Q.setZero();
  d.term_power = addTermForcesAndPower(model_, d.term_data, d.kin, t, d.Q);
}

void ChainFormulation::reactionsFromAccelerations(const AlignedVector<Vec2>& A_dd, const VecX& theta_dd,
                                                  const Vec2& tip_force, ChainData& d) const {
  // Rows A of rfe m: P A'' + B u'' + h_A = Q_A + f_m - f_{m+1}, f_m the force on rfes m..n at A_m.
  const int nb = model_.bodies();
  Vec2 f = tip_force;
  d.reactions.joint[nb] = -f;
  for (int m = nb - 1; m >= 0; --m) {
    Vec4 qdd(A_dd[m].x(), A_dd[m].y(), k_ == 2 ? theta_dd[2 * m] : 0.0, theta_dd[k_ * m + k_ - 1]);
    f += (d.M[m] * qdd).head<2>() + d.h.segment<2>(4 * m) - d.Q.segment<2>(4 * m);
    d.reactions.joint[m] = -f;
  }
  d.reactions.top = d.reactions.joint[0];
  d.reactions.bottom = pinned() ? tip_force : Vec2::Zero();
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

void ChainFormulation::linearize(double t, const VecX& y, const PointMotion& top, FormulationData& data) const {
  ChainData& d = dataOf<ChainData>(data);
  if (!evaluatedAt(t, y, top, d)) derivative(t, y, top, d.lin_dy, d);
  d.lin_kin = d.kin;
  d.lin_joint = d.reactions.joint;
  rfeMassBlocks(model_, d.lin_kin, t, d.lin_M, d.lin_h);
  d.lin_S.setZero();
  addTermStiffness(model_, d.term_data, d.lin_kin, t, d.lin_S);
  d.shifted.setLinearization(d.lin_kin, d.lin_M, d.lin_S, d.lin_joint);
  d.shifted_c = 0.0;
  d.linearized = true;
  d.factored = false;
}

void ChainFormulation::factorShifted(double c, FormulationData& data) const {
  ChainData& d = dataOf<ChainData>(data);
  if (!d.linearized) throw std::logic_error(name() + " formulation: factorShifted() before linearize()");
  d.shifted.factor(c);
  d.shifted_c = c;
  d.factored = true;
}

// (I - cJ) x = b with J = [[0, I], [-W_M^-1 K, -W_M^-1 C]]:  (M + cC + c²K) x_v = M b_v - c K b_q,
// x_q = b_q + c x_v. A pinned end adds Gᵀ μ and the linearised Baumgarte row of the ODE,
// G a = -2ω G v - ω² G q (G = ∂A_{n+1}/∂θ, A_0 prescribed), on the increment: with c G a(x) = G x_v - G b_v
// and x_q = b_q + c x_v,  G x_v (1 + ωc)² = G b_v - ω² c G b_q.
void ChainFormulation::solveShifted(const VecX& b, VecX& x, FormulationData& data) const {
  ChainData& d = dataOf<ChainData>(data);
  if (!d.factored) throw std::logic_error(name() + " formulation: solveShifted() before factorShifted()");
  const int p = positionSize();
  const double c = d.shifted_c;
  d.shifted.massMinusStiffness(b.segment(p, p), b.head(p), c, d.lin_r);
  Vec2 end = Vec2::Zero();
  if (pinned()) {
    const double wc = 1.0 + omega_ * c;
    end = (d.shifted.endMotion(b.segment(p, p)) - (omega_ * omega_ * c) * d.shifted.endMotion(b.head(p))) / (wc * wc);
  }
  d.shifted.solve(d.lin_r, d.lin_x, end);
  x.segment(p, p) = d.lin_x;
  x.head(p) = b.head(p) + c * d.lin_x;
}

}  // namespace riser_sim
