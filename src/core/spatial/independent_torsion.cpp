// Torsion in IndependentFormulation3 (independent_formulation.h): spin angles φ_i as generalised
// coordinates beside the sphere charts' u_i, from the Lagrangian
//   L = T(u, u') + Σ ½ J_i ω_i² - V(u) - Σ ½ (GJ/d) m_k²,   ω_i = φ'_i + a_i·e'_i,  a_i = a(c_i, e_i).
// Twist: m_k = φ_{k+1} - φ_k + m_ref,k(e_k, e_{k+1}). At fixed φ the frame of rfe i spins by a_i·δe_i beyond
// the minimal rotation, so ∂m_k/∂e_k = kb_k - a_k and ∂m_k/∂e_{k+1} = kb_k + a_{k+1}; the damper's Rayleigh
// function ½ (c_GJ/d) m'_k² has the same derivatives in the rates.
#include <algorithm>
#include <cmath>

#include "riser_sim/spatial/bending_axes.h"

#include "riser_sim/spatial/independent_formulation.h"

namespace riser_sim {
namespace spatial {

namespace {
// da/dt of a(c, e) = -(c × e)/(1 + c·e) at rate e'.
Vec3 connectionRate(const Vec3& c, const Vec3& e, const Vec3& ed) {
  const double den = 1.0 + c.dot(e);
  return -c.cross(ed) / den + c.cross(e) * (c.dot(ed) / (den * den));
}
}  // namespace

double IndependentFormulation3::spinInertia(int i) const {
  if (i < s0_) return 0.0;
  const TorsionProperties& t = model_.torsion();
  return t.polar_inertia * model_.rfe(i).length + (i == model_.bodies() - 1 ? t.end_polar_inertia : 0.0);
}

void IndependentFormulation3::spinPhase(const VecX& y, const SphereCharts& charts, IndependentData3& d) const {
  const int p = positionSize();
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics3& b = d.kin[i];
    const bool spins = i >= s0_;
    d.phi[i] = spins ? y[spinIndex(i)] : 0.0;
    d.conn[i] = spinConnection(charts.twist.centre[i], b.e);
    d.omega[i] = (spins ? y[p + spinIndex(i)] : 0.0) + d.conn[i].dot(b.e_dot);
  }
  if (s0_ > 0) d.omega[0] += hangOffSpin(charts.twist, d.kin[0].e);  // held: rfe 0 turns with the hang-off
}

// Generalised forces of the twist: on e_i (natural coordinates, projected by the chart with the terms'
// forces) -τ_i (kb_i - a_i) - τ_{i-1} (kb_{i-1} + a_i); on φ_i the moment τ_i - τ_{i-1} (kept in
// d.twist.moment for addSpinInertia). τ_k = (GJ/d) m_k + (c_GJ/d) m'_k.
void IndependentFormulation3::addTwistForces(const VecX& y, const SphereCharts& charts, IndependentData3& d) const {
  const int nb = model_.bodies(), nj = nb - 1;
  TwistData& t = d.twist;
  spinPhase(y, charts, d);
  twistAngles(d.kin, d.phi.data(), charts.twist, t.m.data(), t.kb.data());
  const double k = twistStiffness(model_), c = twistDamping(model_);
  double power = 0.0;
  for (int j = 0; j < nj; ++j) {
    t.mdot[j] = d.omega[j + 1] - d.omega[j] + t.kb[j].dot(d.kin[j].e_dot + d.kin[j + 1].e_dot);
    t.tau[j] = k * t.m[j] + c * t.mdot[j];
    power -= c * t.mdot[j] * t.mdot[j];
  }
  // Top spring (flex joint's torsional stiffness) and damper: V_t = ½ k_t m_t², τ_t = k_t m_t + c_t m_t', ∂m_t/∂φ_0 =
  // 1, ∂m_t/∂e_0 = a(c_0, e_0) - a(h, e_0) (rfe 0's frame and the hang-off's transported one both spin). A turning
  // hang-off moves the twist next to it by -s: the holder's work -τ s (natural_formulation's too).
  const double s = hangOffSpin(charts.twist, d.kin[0].e);
  if (s0_ > 0 && nj > 0) power -= t.tau[0] * s;
  const double kt = model_.torsion().top_stiffness;
  t.top_tau = 0.0;
  if (kt > 0.0) {
    t.top_twist = topSpringTwist(d.kin, d.phi[0], charts.twist);
    const Vec3 a = spinConnection(charts.twist.top_axis, d.kin[0].e);
    const double ct = model_.torsion().top_damping, rate = d.omega[0] - a.dot(d.kin[0].e_dot) - s;  // m_t'
    t.top_tau = kt * t.top_twist + ct * rate;
    power -= ct * rate * rate + t.top_tau * s;
    d.Q.segment<3>(kE) += t.top_tau * a;
  }
  if (model_.hasBendingAxes()) {  // else t.bend stays 0 (resize)
    std::fill(t.bend.begin(), t.bend.end(), 0.0);
    addBendingAxesForces(model_, d.kin, d.phi.data(), charts.twist, t.m1, d.Q, t.bend.data());
    if (s0_ > 0) power -= t.bend[0] * s;  // the holder spins rfe 0's axes: ∂V/∂t
  }
  for (int i = 0; i < nb; ++i) {
    const double ti = i < nj ? t.tau[i] : 0.0, tp = i > 0 ? t.tau[i - 1] : 0.0;
    t.moment[i] = ti - tp - (i == 0 ? t.top_tau : 0.0) + t.bend[i];
    Vec3 F = t.moment[i] * d.conn[i];
    if (i < nj) F -= ti * t.kb[i];
    if (i > 0) F -= tp * t.kb[i - 1];
    d.Q.segment<3>(kDofPerBody3 * i + kE) += F;
  }
  d.term_power += power;
  const Vec3& h = charts.twist.top_axis;
  const Vec3& n0 = d.kin[0].e;
  d.reactions.top_twist = hangOffTwist(model_, t);
  d.reactions.top_twist_moment = d.reactions.top_twist / (1.0 + h.dot(n0)) * (h + n0);
}

// The spins' inertia in M_θ and their velocity terms (Lagrange's equations of ½ J (φ' + b·u')², b = Gᵀ a):
//   φ row:  J (φ'' + b·u'') = Q_φ - J β,
//   u rows: ... + J b (φ'' + b·u'') = Q_u - J b β + J ω s (-u'_2, u'_1),
// with β = a'·e' + a·e''_bias (ω' at θ'' = 0) and s = e·(G_1 × G_2).
void IndependentFormulation3::addSpinInertia(const VecX& y, const SphereCharts& charts, IndependentData3& d) const {
  const int p = positionSize();
  for (int i = s0_; i < model_.bodies(); ++i) {
    const BodyKinematics3& b = d.kin[i];
    const double J = spinInertia(i);
    const int r = spinIndex(i), cu = k_ * i + ku_;
    const Eigen::Matrix<double, 3, 2>& G = d.G[i];
    const Eigen::Vector2d bv = G.transpose() * d.conn[i];
    const Vec3 ad = connectionRate(charts.twist.centre[i], b.e, b.e_dot);
    const double beta = ad.dot(b.e_dot) + d.conn[i].dot(d.e_bias[i]);
    const double s = b.e.dot(G.col(0).cross(G.col(1)));
    const double ud1 = y[p + k_ * i + ku_], ud2 = y[p + k_ * i + ku_ + 1];
    d.M(r, r) = J;
    for (int a = 0; a < 2; ++a) {
      d.M(r, cu + a) = d.M(cu + a, r) = J * bv[a];
      for (int c = 0; c < 2; ++c) d.M(cu + a, cu + c) += J * bv[a] * bv[c];
    }
    d.rhs[r] = d.twist.moment[i] - J * beta;
    d.rhs[cu] += -J * bv[0] * beta - J * d.omega[i] * s * ud2;
    d.rhs[cu + 1] += -J * bv[1] * beta + J * d.omega[i] * s * ud1;
  }
}

void IndependentFormulation3::recentreTwist(VecX& y, SphereCharts& charts) const {
  const int p = positionSize();
  kinematics(y, charts, PointMotion3(), charts.kin);  // e, e' only (the top does not enter them)
  for (int i = s0_; i < model_.bodies(); ++i) {       // φ' <- ω: a = 0 at the new centre
    const BodyKinematics3& b = charts.kin[i];
    y[p + spinIndex(i)] += spinConnection(charts.twist.centre[i], b.e).dot(b.e_dot);
  }
  rechartTwistFrames(charts.kin, charts.twist, s0_);
}

void IndependentFormulation3::refreshTwist(const VecX& y, SphereCharts& charts) const {
  kinematics(y, charts, PointMotion3(), charts.kin);  // e only
  refreshTwistBranches(charts.kin, charts.twist, s0_);
}

void IndependentFormulation3::setSpins(const VecX& theta, const VecX& omega, VecX& y) const {
  const int p = positionSize();
  for (int i = s0_; i < model_.bodies(); ++i) {
    y[spinIndex(i)] = theta[i];
    y[p + spinIndex(i)] = omega[i];
  }
}

double IndependentFormulation3::spinRate(const VecX& y, const SphereCharts& charts, const Kinematics3& kin,
                                         int i) const {
  const double phid = i >= s0_ ? y[positionSize() + spinIndex(i)] : 0.0;
  return phid + spinConnection(charts.twist.centre[i], kin[i].e).dot(kin[i].e_dot);
}

Vec3 IndependentFormulation3::materialDirector(const VecX& y, const SphereCharts& charts, const Kinematics3& kin,
                                               int i) const {
  return spatial::materialDirector(charts.twist, i, kin[i].e, i >= s0_ ? y[spinIndex(i)] : 0.0);
}

double IndependentFormulation3::spinKineticEnergy(const VecX& y, const SphereCharts& charts,
                                                  const Kinematics3& kin) const {
  double T = 0.0;
  for (int i = s0_; i < nt_ + s0_; ++i) T += 0.5 * spinInertia(i) * std::pow(spinRate(y, charts, kin, i), 2);
  return T;
}

double IndependentFormulation3::twistEnergy(const VecX& y, const SphereCharts& charts, const Kinematics3& kin,
                                            IndependentData3& d) const {
  if (nt_ == 0) return 0.0;
  for (int i = 0; i < model_.bodies(); ++i) d.phi[i] = i >= s0_ ? y[spinIndex(i)] : 0.0;
  twistAngles(kin, d.phi.data(), charts.twist, d.twist.m.data(), d.twist.kb.data());
  double v = 0.0;
  for (double m : d.twist.m) v += m * m;
  const double kt = model_.torsion().top_stiffness, mt = kt > 0.0 ? topSpringTwist(kin, d.phi[0], charts.twist) : 0.0;
  return 0.5 * twistStiffness(model_) * v + 0.5 * kt * mt * mt +
         bendingAxesEnergy(model_, kin, d.phi.data(), charts.twist);
}

}  // namespace spatial
}  // namespace riser_sim
