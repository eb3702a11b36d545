// A torsionally free top (TorsionProperties::free_top, scene top.torsion: free): the hang-off holds no
// twisting moment, so a line hanging straight keeps its axial angular momentum Σ J_i ω_i and its J-weighted
// mean spin angle moves at that momentum over Σ J_i. Exact answers: a line spun uniformly turns rigidly
// (θ_i = Ω t, no twist); a twisted line released at rest with twist dampers untwists to the uniform angle
// θ̄ = Σ J_i θ_i(0) / Σ J_i. Both formulations (natural and independent), rk4.
#include <gtest/gtest.h>

#include <cmath>

#include "alloc_counter.h"
#include "riser_sim/spatial/independent_formulation.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kL = 10.0, kGJ = 1e4, kRhoIp = spatial_test::kShaftRhoIp, kJend = spatial_test::kShaftJend;
using spatial_test::shaftTorsion;

std::shared_ptr<Model3> freeShaft(int n, double damping) {
  TorsionProperties t = shaftTorsion(kGJ, damping);
  t.free_top = true;
  return spatial_test::twistShaft(n, t);  // L = kL
}

Kinematics3 straightDown(const Model3& m) {
  return rigidChain(m.line(), Vec3::Zero(), std::vector<Vec3>(m.bodies(), -Vec3::UnitZ()), Vec3::Zero(), Vec3::Zero());
}

// Spin angles and rates of both runs after `steps` rk4 steps of h from (θ, ω).
struct Spins {
  VecX theta, omega;
};
std::pair<Spins, Spins> run(const std::shared_ptr<Model3>& m, const VecX& theta, const VecX& omega, double h, int steps,
                            double* top_twist) {
  const int nb = m->bodies();
  Simulator3 nat(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  IndependentSimulator3 ind(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  nat.reset(straightDown(*m), 0.0);
  ind.reset(straightDown(*m), 0.0);
  nat.setTwist(theta, omega);
  ind.setTwist(theta, omega);
  *top_twist = 0.0;
  for (int k = 0; k < steps; ++k) {
    EXPECT_TRUE(nat.step(h));
    EXPECT_TRUE(ind.step(h));
    *top_twist = std::max(
        {*top_twist, std::abs(nat.evaluate().reactions.top_twist), std::abs(ind.evaluate().reactions.top_twist)});
  }
  std::pair<Spins, Spins> r;
  const int vo = nat.formulation().positionSize(), p = ind.formulation().positionSize();
  r.first.theta = nat.state().segment(m->dofs(), nb);
  r.first.omega = nat.state().segment(vo + m->dofs(), nb);
  r.second.theta = ind.state().segment(ind.formulation().spinIndex(0), nb);
  r.second.omega = ind.state().segment(p + ind.formulation().spinIndex(0), nb);
  return r;
}

// Straight down the charts stay on e (a = 0): θ is the spin angle itself and φ' = ω.
TEST(SpatialTorsionFreeTop, UniformSpinTurnsRigidly) {
  auto m = freeShaft(8, 5.0);
  const int nb = m->bodies();
  const double Omega = 2.0, h = 1e-3;
  const int steps = 2000;  // 2 s
  double twist = 0.0;
  const auto r = run(m, VecX::Zero(nb), VecX::Constant(nb, Omega), h, steps, &twist);
  double worst = 0.0;
  for (const Spins* s : {&r.first, &r.second})
    for (int i = 0; i < nb; ++i)
      worst = std::max({worst, std::abs(s->theta[i] - Omega * h * steps), std::abs(s->omega[i] - Omega)});
  std::printf(
      "[free top] uniform spin 2 rad/s, 2 s: max |θ_i - Ω t|, |ω_i - Ω| %.2e (natural and independent), hang-off "
      "twisting moment %.1e N m\n",
      worst, twist);
  EXPECT_LT(worst, 1e-11);  // no twist, no force: round-off of 2000 steps on angles ~4 rad
  EXPECT_EQ(twist, 0.0);    // a free top holds none
}

// Released twisted at rest: ΣJω = 0 and Σ J θ are linear invariants of the equations (the twist moments
// telescope to zero at two free ends), which rk4 keeps to round-off; the dampers take out the twist
// (slowest mode ~14 rad/s at modal damping ζ = ω c/(2 GJ) ~ 0.5: e^-35 in 5 s).
TEST(SpatialTorsionFreeTop, TwistedLineUntwistsToTheMeanAngle) {
  auto m = freeShaft(8, 700.0);
  const int nb = m->bodies();
  VecX theta(nb), J(nb);
  double jsum = 0.0, jtheta = 0.0;
  for (int i = 0; i < nb; ++i) {
    theta[i] = 0.8 * std::cos(0.7 * i) + 0.1 * i;
    J[i] = polarInertia(*m, i);
    jsum += J[i];
    jtheta += J[i] * theta[i];
  }
  const double mean = jtheta / jsum;
  double twist = 0.0;
  const auto r = run(m, theta, VecX::Zero(nb), 1e-3, 5000, &twist);
  double worst = 0.0, momentum = 0.0;
  for (const Spins* s : {&r.first, &r.second}) {
    for (int i = 0; i < nb; ++i) worst = std::max(worst, std::abs(s->theta[i] - mean));
    momentum = std::max(momentum, std::abs(J.dot(s->omega)));
  }
  std::printf(
      "[free top] twisted line released (θ̄ = %.6f rad): after 5 s max |θ_i - θ̄| %.2e rad, |Σ J ω| %.2e N m s "
      "(natural and independent)\n",
      mean, worst, momentum);
  EXPECT_GT(J[0], 0.0);        // rfe 0 spins: its own polar inertia
  EXPECT_LT(worst, 1e-9);      // [rad] decay e^-35 of ~1 rad + round-off
  EXPECT_LT(momentum, 1e-10);  // [N m s] round-off of moments ~1e3 N m over 5000 steps x 1e-3 s
  EXPECT_EQ(twist, 0.0);
}

// The natural formulation's twist forces with a spinning top rfe (free, spring-held) against its twist
// energy by central differences: -∂V/∂θ_i = moment_i, -∂V/∂e_i at fixed θ = Q_e + moment_i a(c_i, e_i) (the
// chart's reference turns with e), as test_spatial_torsion's check for the held top.
TEST(SpatialTorsionFreeTop, ForcesAreTheGradientOfTheTwistEnergy) {
  for (bool spring : {false, true}) {
    spatial_test::LineSpec s = spatial_test::flexibleLine();
    s.segments = 6;
    auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
    TorsionProperties t;
    t.stiffness = 2e3;
    t.polar_inertia = 0.05;
    t.end_polar_inertia = 0.3;
    t.free_top = !spring;
    t.top_stiffness = spring ? 700.0 : 0.0;
    m->setTorsion(t);
    const int nb = m->bodies();
    std::vector<Vec3> dirs;
    for (int i = 0; i < nb; ++i) dirs.push_back(Vec3(0.4 * i, 0.3 * std::sin(i), -1.0));
    Kinematics3 kin = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
    TwistData d;
    d.resize(nb);
    initTwistFrames(kin, d.frames);
    std::vector<double> theta(nb), still(nb, 0.0);
    for (int i = 0; i < nb; ++i) {  // directors ~0.3 rad off their charts (rfe 0's and the hang-off's too)
      kin[i].e = (kin[i].e + 0.3 * Vec3(std::cos(3.0 * i), std::sin(2.0 * i), 0.5)).normalized();
      theta[i] = 0.4 * std::sin(1.0 + 2.0 * i);
    }
    VecX Q = VecX::Zero(m->dofs());
    addTwistForces(*m, kin, theta.data(), still.data(), d, Q);
    const std::vector<double> moment = d.moment;
    TwistData work = d;
    auto V = [&](const Kinematics3& k, const std::vector<double>& th) { return twistEnergy(*m, k, th.data(), work); };
    constexpr double eps = 1e-6;
    double worst = 0.0, scale = 0.0;
    for (double v : moment) scale = std::max(scale, std::abs(v));
    for (int i = 0; i < nb; ++i) {
      std::vector<double> p = theta, q = theta;
      p[i] += eps;
      q[i] -= eps;
      worst = std::max(worst, std::abs(-(V(kin, p) - V(kin, q)) / (2 * eps) - moment[i]));
      const Vec3 e = kin[i].e, t1 = e.unitOrthogonal(), t2 = e.cross(t1);
      const Vec3 expect = Q.segment<3>(kDofPerBody3 * i + kE) + moment[i] * spinConnection(d.frames.centre[i], e);
      for (const Vec3& dir : {t1, t2}) {
        Kinematics3 kp = kin, kq = kin;
        kp[i].e = (e + eps * dir).normalized();
        kq[i].e = (e - eps * dir).normalized();
        worst = std::max(worst, std::abs(-(V(kp, theta) - V(kq, theta)) / (2 * eps) - expect.dot(dir)));
      }
    }
    std::printf("[free top] natural twist forces vs -dV, %s top: %.2e of the largest moment %.3g N m\n",
                spring ? "spring-held" : "free", worst / scale, scale);
    EXPECT_LT(worst / scale, 1e-7);  // central differences at 1e-6: truncation ~1e-12, round-off ~1e-10 V/eps
  }
}

// Implicit schemes with a spinning top rfe (the spring-held one with its damper): the structured solve's spin
// rows leave out their coupling to e, an approximate Jacobian. Newton still converges to the step (its tolerance), so
// the balance E - E0 - W stays second order: the bent, twisted, spinning flexible line under a swaying top, free and
// spring-held, 1 s.
std::unique_ptr<Simulator3> spinningTop(bool spring, IntegratorKind kind, double* scale) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties t;
  t.stiffness = 1e3;
  t.polar_inertia = 0.05;
  t.damping = 2.0;
  t.end_polar_inertia = 0.5;
  t.free_top = !spring;
  t.top_stiffness = spring ? 500.0 : 0.0;
  t.top_damping = spring ? 30.0 : 0.0;  // its power is in W
  m->setTorsion(t);
  const int nb = m->bodies();
  IntegratorOptions io;
  io.jacobian = JacobianKind::kStructured;
  auto sim = std::make_unique<Simulator3>(
      m, std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0)), kind, io);
  std::vector<Vec3> dirs;
  for (int i = 0; i < nb; ++i) dirs.push_back(Vec3(0.3 + 0.1 * i, 0.2 - 0.05 * i, -1.0));
  sim->reset(rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3(0.2, -0.3, 0.5)), 0.0);
  VecX theta(nb), omega(nb);
  for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i, omega[i] = 3.0 * std::sin(1.0 + i);
  sim->setTwist(theta, omega);
  *scale = (s.props.mass_per_length * s.length + s.end_mass) * s.g * s.length;
  return sim;
}

TEST(SpatialTorsionFreeTop, ImplicitSchemesConvergeWithASpinningTop) {
  for (bool spring : {false, true}) {
    double errs[2];
    int j = 0;
    for (double h : {2e-3, 1e-3}) {
      double scale = 0.0;
      auto ps = spinningTop(spring, IntegratorKind::kMidpoint, &scale);
      Simulator3& sim = *ps;
      const double e0 = sim.energy();
      double worst = 0.0;
      const int steps = int(std::lround(1.0 / h));
      for (int k = 1; k <= steps; ++k) {
        ASSERT_TRUE(sim.step(h)) << sim.integrator().failure();
        worst = std::max(worst, std::abs(sim.energy() - e0 - sim.work()) / scale);
      }
      errs[j++] = worst;
      const auto st = sim.integrator().stats();
      std::printf("[free top] midpoint structured, %s top, h = %.0e s: |E - E0 - W| %.2e of m g L, %.2f Newton/step\n",
                  spring ? "spring-held" : "free", h, worst, double(st.newton) / std::max<long>(1, st.substeps));
    }
    EXPECT_GT(errs[0] / errs[1], 3.0);  // second order (4x per halving)
    EXPECT_LT(errs[1], 1e-4);           // as the held top's bound (test_spatial_torsion)
  }
}

TEST(SpatialTorsionFreeTop, NoAllocationPerStep) {
  for (bool spring : {false, true})
    for (IntegratorKind kind : {IntegratorKind::kRk4, IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha}) {
      double scale = 0.0;
      auto sim = spinningTop(spring, kind, &scale);
      AlignedVector<Vec3> p(sim->model().bodies() + 1);
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(sim->step(1e-3));
      const long before = g_allocations.load();
      double sink = 0.0;
      for (int k = 0; k < 20; ++k) {
        EXPECT_TRUE(sim->step(1e-3));
        sim->positions(p);
        sink += sim->energy() + sim->work() + sim->evaluate().reactions.top_twist;
      }
      EXPECT_TRUE(std::isfinite(sink));
      EXPECT_EQ(g_allocations.load() - before, 0) << name(kind) << (spring ? " spring-held" : " free");
    }
}

// A stiff shaft hanging straight down on a damped top spring (k_t, c_t), twisted uniformly by θ0 and released:
// in the rigid limit GJ/L >> k_t it is the oscillator J θ'' + c_t θ' + k_t θ = 0, J = ρI_p L + J_end, whose
// solution is θ0 e^(-ζ ω t) (cos ω_d t + ζ ω/ω_d sin ω_d t). The shaft's own compliance shifts ω by about
// ½ k_t L/GJ; ten times stiffer, the gap to the oscillator falls about tenfold (the limit, not a tolerance).
TEST(SpatialTorsionFreeTop, DampedTopSpringIsTheRigidShaftOscillator) {
  const double kt = 10.0, ct = 2.0, theta0 = 0.3, J = kRhoIp * kL + kJend;  // ζ = 0.071, ω = 0.707 rad/s
  const double w = std::sqrt(kt / J), zeta = ct / (2.0 * std::sqrt(kt * J)), wd = w * std::sqrt(1.0 - zeta * zeta);
  double gaps[2];
  int j = 0;
  for (const double GJ : {1e5, 1e6}) {
    TorsionProperties t = shaftTorsion(GJ, 0.0);
    t.top_stiffness = kt;
    t.top_damping = ct;
    auto m = spatial_test::twistShaft(8, t);
    const int nb = m->bodies();
    Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
    sim.reset(straightDown(*m), 0.0);
    sim.setTwist(VecX::Constant(nb, theta0), VecX::Zero(nb));
    const double h = 2e-4, e0 = sim.energy();
    double gap = 0.0;
    for (int k = 1; k <= 50000; ++k) {  // 10 s: 1.1 periods, the amplitude down to e^-0.5
      ASSERT_TRUE(sim.step(h));
      const double tk = k * h;
      const double exact = theta0 * std::exp(-zeta * w * tk) * (std::cos(wd * tk) + zeta * w / wd * std::sin(wd * tk));
      gap = std::max(gap, std::abs(sim.state()[m->dofs() + nb - 1] - exact));
    }
    const double balance = std::abs(sim.energy() - e0 - sim.work()) / (0.5 * kt * theta0 * theta0);
    std::printf(
        "[damped top spring] GJ %.0e: max |θ_end - oscillator| %.2e rad of %.2f (½ k_t L/GJ %.1e); "
        "E - E0 - W %.1e of the initial spring energy\n",
        GJ, gap, theta0, 0.5 * kt * kL / GJ, balance);
    // rk4's truncation on the shaft's fastest twist modes (ω h ~ 0.1 / 0.3): measured 4.2e-9 / 3.8e-7, x90 for
    // ω x3.2, the (ω h)^4 of a fourth-order scheme. W holds the damper's work, ~60 % of the initial energy.
    EXPECT_LT(balance, 1e-6);
    gaps[j++] = gap;
  }
  EXPECT_LT(gaps[1], 2e-3 * theta0);  // ½ k_t L/GJ = 5e-5 in ω over ~7 rad of phase: ~4e-4 θ0
  EXPECT_GT(gaps[0] / gaps[1], 5.0);  // the rigid limit: ~10x per decade of GJ
}

}  // namespace
}  // namespace riser_sim
