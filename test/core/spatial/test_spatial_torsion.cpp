// Torsion in the spatial core (spatial/torsion.h): the torsional pendulum against its exact frequency
// equation, the twist's forces against its energy (finite differences), the energy balance and the axial
// angular momentum in large 3D motions, the moving charts through vertical and horizontal, second order of
// the implicit schemes with the approximate structured solve, torsion off unchanged, no allocation per step.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <yaml-cpp/yaml.h>

#include "alloc_counter.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

// First root of x tan x = mu in (0, π/2), by bisection (to round-off).
double firstRoot(double mu) {
  double lo = 0.0, hi = 0.5 * M_PI - 1e-15;
  for (int k = 0; k < 200; ++k) {
    const double x = 0.5 * (lo + hi);
    (x * std::tan(x) < mu ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

// A straight vertical line (inextensible, no bending: nothing but twist moves), top fixed in twist, an end
// body of polar inertia J_end [kg m^2]. L = 10 m, GJ = 1e4 N m^2.
constexpr double kL = 10.0, kGJ = 1e4, kJend = 10.0;

std::shared_ptr<Model3> pendulumModel(int n, double rho_ip) {
  TorsionProperties t;
  t.stiffness = kGJ;
  t.polar_inertia = rho_ip;
  t.end_polar_inertia = kJend;
  return spatial_test::twistShaft(n, t);  // L = kL
}

// Period [s] of the end's twist, from upward zero crossings over `periods` periods, starting in the
// continuous first mode θ(s) = 0.1 sin(x s / L).
double pendulumPeriod(int n, double rho_ip, double h, int periods) {
  auto m = pendulumModel(n, rho_ip);
  const int nb = m->bodies();
  Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  sim.reset(rigidChain(m->line(), Vec3::Zero(), std::vector<Vec3>(nb, -Vec3::UnitZ()), Vec3::Zero(), Vec3::Zero()),
            0.0);
  const double x = firstRoot(rho_ip * kL / kJend), d = kL / n;
  VecX theta(nb), omega = VecX::Zero(nb);
  for (int i = 0; i < nb; ++i) theta[i] = -0.1 * std::sin(x * std::min(i * d, kL) / kL);
  sim.setTwist(theta, omega);
  const int idx = m->dofs() + nb - 1;  // θ_n
  double prev = sim.state()[idx], first = -1.0, last = -1.0;
  int crossings = 0;
  for (int k = 1; crossings <= periods && k < 100000000; ++k) {
    EXPECT_TRUE(sim.step(h));
    const double th = sim.state()[idx];
    if (prev < 0.0 && th >= 0.0) {
      const double tc = sim.time() - h + h * (-prev) / (th - prev);
      if (crossings == 0) first = tc;
      last = tc;
      ++crossings;
    }
    prev = th;
  }
  return (last - first) / periods;
}

double exactPeriod(double rho_ip) {
  const double c = std::sqrt(kGJ / rho_ip), x = firstRoot(rho_ip * kL / kJend);
  return 2.0 * M_PI * kL / (x * c);
}

TEST(SpatialTorsion, PendulumConvergesToTheExactFrequencyEquation) {
  const double rho_ip = 1.0;  // J_line = J_end: x tan x = 1
  const double T = exactPeriod(rho_ip);
  double prev_err = 0.0;
  for (int n : {4, 8, 16, 32}) {
    const double err = std::abs(pendulumPeriod(n, rho_ip, 5e-4, 10) / T - 1.0);
    std::printf("[torsion pendulum] J_line = J_end, n = %2d: period %.9f s vs exact %.9f s, error %.3e%s\n", n,
                T * (1 + err), T, err, n > 4 ? (" (x" + std::to_string(prev_err / err) + ")").c_str() : "");
    // Lumped polar inertias (half an rfe at each end) on springs GJ/d: second order in d.
    if (n > 4) {
      EXPECT_GT(prev_err / err, 3.5);
      EXPECT_LT(prev_err / err, 4.5);
    }
    prev_err = err;
  }
  EXPECT_LT(prev_err, 1e-3);
}

TEST(SpatialTorsion, LightLinePendulumPeriod) {
  const double rho_ip = 1e-3;  // J_line / J_end = 1e-3
  const double Tn = pendulumPeriod(8, rho_ip, 2e-4, 10), T = exactPeriod(rho_ip);
  const double T0 = 2.0 * M_PI * std::sqrt(kJend * kL / kGJ);
  std::printf(
      "[torsion pendulum] light line, n = 8: %.9f s; exact %.9f s (error %.2e); 2π sqrt(J L / GJ) = %.9f s "
      "(%.2e)\n",
      Tn, T, Tn / T - 1.0, T0, Tn / T0 - 1.0);
  EXPECT_LT(std::abs(Tn / T - 1.0), 1e-5);
  // The massless-line formula is off by the line's inertia, ~ J_line / (6 J_end) = 1.7e-4.
  EXPECT_LT(std::abs(Tn / T0 - 1.0), 2.5e-4);
}

// A bent line with twist: random charts moved off their centres, random spins.
struct TwistState {
  std::shared_ptr<Model3> model;
  Kinematics3 kin;
  TwistData data;
  std::vector<double> theta, omega;
};

TwistState twistState(double damping, unsigned seed) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = 6;
  TwistState t;
  t.model = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties p;
  p.stiffness = 2e3;
  p.polar_inertia = 0.05;
  p.damping = damping;
  p.end_polar_inertia = 0.3;
  t.model->setTorsion(p);
  const int nb = t.model->bodies();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  t.kin = spatial_test::randomBentChain(t.model->line(), rng);
  t.data.resize(nb);
  initTwistFrames(t.kin, t.data.frames);
  for (int i = 0; i < nb; ++i) {  // move every director ~0.3 rad off its chart centre
    BodyKinematics3& b = t.kin[i];
    b.e = (b.e + 0.3 * Vec3(u(rng), u(rng), u(rng))).normalized();
    const Vec3 r(u(rng), u(rng), u(rng));
    b.e_dot = r - r.dot(b.e) * b.e;
    t.theta.push_back(i == 0 ? 0.0 : 0.5 * u(rng));
    t.omega.push_back(i == 0 ? 0.0 : 2.0 * u(rng));
  }
  return t;
}

TEST(SpatialTorsion, ForcesAreTheGradientOfTheTwistEnergy) {
  double worst = 0.0, scale = 0.0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    TwistState t = twistState(0.0, seed);
    const Model3& m = *t.model;
    const int nb = m.bodies();
    const std::vector<double> still(nb, 0.0);  // ω = 0: no gyroscopic part
    VecX Q = VecX::Zero(m.dofs());
    addTwistForces(m, t.kin, t.theta.data(), still.data(), t.data, Q);
    const std::vector<double> moment = t.data.moment;
    for (double v : moment) scale = std::max(scale, std::abs(v));
    TwistData work = t.data;
    auto energy = [&](const Kinematics3& kin, const std::vector<double>& th) {
      return twistEnergy(m, kin, th.data(), work);
    };
    constexpr double eps = 1e-6;
    for (int i = 1; i < nb; ++i) {  // -∂V/∂θ_i = moment about e_i
      std::vector<double> p = t.theta, q = t.theta;
      p[i] += eps;
      q[i] -= eps;
      const double fd = -(energy(t.kin, p) - energy(t.kin, q)) / (2 * eps);
      worst = std::max(worst, std::abs(fd - moment[i]));
    }
    for (int i = 0; i < nb; ++i) {  // -∂V/∂e_i at fixed θ (the chart's reference turns: + moment_i a_i)
      const Vec3 e = t.kin[i].e;
      const Vec3 t1 = e.unitOrthogonal(), t2 = e.cross(t1);
      Vec3 expect = Q.segment<3>(kDofPerBody3 * i + kE);
      if (i > 0) expect += moment[i] * spinConnection(t.data.frames.centre[i], e);
      for (const Vec3& dir : {t1, t2}) {
        Kinematics3 kp = t.kin, kq = t.kin;
        kp[i].e = (e + eps * dir).normalized();
        kq[i].e = (e - eps * dir).normalized();
        const double fd = -(energy(kp, t.theta) - energy(kq, t.theta)) / (2 * eps);
        worst = std::max(worst, std::abs(fd - expect.dot(dir)));
      }
    }
  }
  std::printf("[torsion] forces vs -dV (central differences, 5 states): %.2e of the largest moment %.3g N m\n",
              worst / scale, scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(worst / scale, 1e-7);  // central differences at 1e-6: truncation ~1e-12, round-off ~1e-10 V/eps
}

// Q·e' + Σ moment_i ω_i = -dV/dt + P along the flow (θ' = ω - a·e'): the twist rate, the dampers' power,
// the hang-off term of rfe 0 and the workless gyroscopic part.
TEST(SpatialTorsion, PowerIdentityWithDampingAndSpin) {
  double worst = 0.0, pscale = 0.0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    TwistState t = twistState(3.0, seed);
    const Model3& m = *t.model;
    const int nb = m.bodies();
    VecX Q = VecX::Zero(m.dofs());
    const double P = addTwistForces(m, t.kin, t.theta.data(), t.omega.data(), t.data, Q);
    double power = 0.0;
    for (int i = 0; i < nb; ++i) {
      power += Q.segment<3>(kDofPerBody3 * i + kE).dot(t.kin[i].e_dot);
      if (i > 0) power += t.data.moment[i] * t.omega[i];
    }
    TwistData work = t.data;
    constexpr double eps = 1e-6;
    auto energyAt = [&](double s) {
      Kinematics3 k = t.kin;
      std::vector<double> th = t.theta;
      for (int i = 0; i < nb; ++i) {
        k[i].e = (t.kin[i].e + s * t.kin[i].e_dot).normalized();
        if (i > 0) th[i] += s * (t.omega[i] - spinConnection(t.data.frames.centre[i], t.kin[i].e).dot(t.kin[i].e_dot));
      }
      return twistEnergy(m, k, th.data(), work);
    };
    const double dV = (energyAt(eps) - energyAt(-eps)) / (2 * eps);
    worst = std::max(worst, std::abs(power + dV - P));
    pscale = std::max({pscale, std::abs(P), std::abs(dV)});
  }
  std::printf("[torsion] power identity: %.2e of %.3g W\n", worst / pscale, pscale);
  EXPECT_LT(worst / pscale, 1e-7);
}

// The flexible line with torsion, bent and twisted, spinning, under a swaying top.
struct Swing {
  std::shared_ptr<Model3> model;
  std::unique_ptr<Simulator3> sim;
  double scale;
};

Swing swing(IntegratorKind kind, double damping, bool moving_top = true, double bending_damping = 10.0) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.props.bending_damping = bending_damping;
  Swing w;
  w.model = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties p;
  p.stiffness = 1e3;
  p.polar_inertia = 0.05;
  p.damping = damping;
  p.end_polar_inertia = 0.5;
  w.model->setTorsion(p);
  const int nb = w.model->bodies();
  IntegratorOptions io;
  io.jacobian = JacobianKind::kStructured;
  std::unique_ptr<TopMotion3> top;
  if (moving_top)
    top = std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), spatial_test::yawTilt(0.3, 0.5));
  else
    top = std::make_unique<FixedMotion3>(Vec3::Zero());
  w.sim = std::make_unique<Simulator3>(w.model, std::move(top), kind, io);
  std::vector<Vec3> dirs;
  for (int i = 0; i < nb; ++i) dirs.push_back(Vec3(0.3 + 0.1 * i, 0.2 - 0.05 * i, -1.0));
  w.sim->reset(rigidChain(w.model->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3(0.2, -0.3, 0.5)), 0.0);
  VecX theta(nb), omega(nb);
  for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i, omega[i] = 3.0 * std::sin(1.0 + i);
  w.sim->setTwist(theta, omega);
  w.scale = (s.props.mass_per_length * s.length + s.end_mass) * s.g * s.length;
  return w;
}

double balance(Swing& w, double h, double duration, double* work = nullptr) {
  const double e0 = w.sim->energy();
  double worst = 0.0, wmax = 0.0;
  const int steps = int(std::lround(duration / h));
  for (int k = 1; k <= steps; ++k) {
    EXPECT_TRUE(w.sim->step(h)) << w.sim->integrator().failure();
    if (k % 10) continue;
    worst = std::max(worst, std::abs(w.sim->energy() - e0 - w.sim->work()) / w.scale);
    wmax = std::max(wmax, std::abs(w.sim->work()) / w.scale);
  }
  if (work) *work = wmax;
  return worst;
}

TEST(SpatialTorsion, EnergyBalanceExplicit) {
  Swing w = swing(IntegratorKind::kRk4, 2.0);
  double W = 0.0;
  const double err = balance(w, 1e-4, 1.0, &W);
  std::printf("[torsion] rk4 h = 1e-4 s, 1 s: |E - E0 - W| = %.2e of m g L (|W| up to %.2e)\n", err, W);
  EXPECT_GT(W, 1e-3);
  EXPECT_LT(err, 1e-9);  // O(h⁴), as the spatial energy test without torsion
}

TEST(SpatialTorsion, EnergyBalanceImplicit) {
  for (IntegratorKind kind : {IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha}) {
    double errs[2];
    int i = 0;
    for (double h : {2e-3, 1e-3}) {
      Swing w = swing(kind, 2.0);
      errs[i++] = balance(w, h, 1.0);
      const auto st = w.sim->integrator().stats();
      std::printf("[torsion] %s structured h = %.0e s, 1 s: |E - E0 - W| = %.2e of m g L, %.2f Newton/step\n",
                  name(kind), h, errs[i - 1], double(st.newton) / std::max<long>(1, st.substeps));
    }
    // Second order: the balance error falls ~4x per halving of h.
    EXPECT_GT(errs[0] / errs[1], 3.0);
    EXPECT_LT(errs[1], 1e-4);
  }
}

// Positions and twist after 0.5 s against rk4 at 1e-4 s: ratio per halving of h.
TEST(SpatialTorsion, ImplicitSchemesStaySecondOrder) {
  Swing ref = swing(IntegratorKind::kRk4, 2.0);
  for (int k = 0; k < 5000; ++k) ASSERT_TRUE(ref.sim->step(1e-4));
  const VecX yref = ref.sim->state();
  const int p = ref.sim->formulation().positionSize();
  for (IntegratorKind kind : {IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha}) {
    double prev = 0.0;
    for (double h : {2e-3, 1e-3, 5e-4}) {
      Swing w = swing(kind, 2.0);
      const int steps = int(std::lround(0.5 / h));
      for (int k = 0; k < steps; ++k) ASSERT_TRUE(w.sim->step(h)) << w.sim->integrator().failure();
      const double err = (w.sim->state().head(p) - yref.head(p)).cwiseAbs().maxCoeff();
      std::printf("[torsion] %s h = %.0e s: max |q - q_rk4| (incl. θ) = %.3e%s\n", name(kind), h, err,
                  prev > 0 ? (" ratio " + std::to_string(prev / err)).c_str() : "");
      if (prev > 0) EXPECT_GT(prev / err, 3.3);
      prev = err;
    }
  }
}

// The approximate structured solve converges to the same steps as the dense finite-difference Jacobian
// (Newton to 1e-11 on both): the left-out coupling costs iterations only.
TEST(SpatialTorsion, StructuredAndDenseJacobiansAgree) {
  for (IntegratorKind kind : {IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha}) {
    Swing a = swing(kind, 2.0), b = swing(kind, 2.0);
    IntegratorOptions io;
    io.jacobian = JacobianKind::kDense;
    b.sim = std::make_unique<Simulator3>(
        b.model,
        std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), spatial_test::yawTilt(0.3, 0.5)),
        kind, io);
    b.sim->reset(rigidChain(
                     b.model->line(), Vec3::Zero(),
                     [&] {
                       std::vector<Vec3> d;
                       for (int i = 0; i < b.model->bodies(); ++i)
                         d.push_back(Vec3(0.3 + 0.1 * i, 0.2 - 0.05 * i, -1.0));
                       return d;
                     }(),
                     Vec3::Zero(), Vec3(0.2, -0.3, 0.5)),
                 0.0);
    const int nb = b.model->bodies();
    VecX theta(nb), omega(nb);
    for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i, omega[i] = 3.0 * std::sin(1.0 + i);
    b.sim->setTwist(theta, omega);
    ASSERT_EQ(a.sim->state(), b.sim->state());
    for (int k = 0; k < 200; ++k) {
      ASSERT_TRUE(a.sim->step(1e-3)) << a.sim->integrator().failure();
      ASSERT_TRUE(b.sim->step(1e-3)) << b.sim->integrator().failure();
    }
    const int p = a.sim->formulation().positionSize();
    const double diff = (a.sim->state().head(p) - b.sim->state().head(p)).cwiseAbs().maxCoeff();
    const auto sa = a.sim->integrator().stats(), sb = b.sim->integrator().stats();
    std::printf("[torsion] %s structured vs dense, 0.2 s: %.2e (q, θ); Newton/step %.2f vs %.2f\n", name(kind), diff,
                double(sa.newton) / sa.substeps, double(sb.newton) / sb.substeps);
    // Newton stops at 1e-11 (1 + |z|) per step: over 200 steps with |z| <= ~10 the runs may part by ~2e-8.
    EXPECT_LT(diff, 2e-8);
  }
}

// Angular momentum about the vertical through the fixed top: only the hang-off's moment (minus
// reactions.top_twist_moment) turns it. Without the gyroscopic term J ω e × e' it would not balance.
TEST(SpatialTorsion, AxialAngularMomentumBalance) {
  // No bending damping: its torques drop their parts along each rfe's axis (no spin in that term), which
  // changes L_z (by 0.29 N m s here without torsion).
  Swing w = swing(IntegratorKind::kRk4, 0.0, false, 0.0);
  const Model3& m = *w.model;
  auto Lz = [&]() {
    const VecX& y = w.sim->state();
    double L = 0.0;
    const int nb = m.bodies(), p = w.sim->formulation().positionSize();
    for (int i = 0; i < nb; ++i) {
      const BodyKinematics3 b = w.sim->formulation().body(y, i);
      const Rfe& r = m.rfe(i);
      for (int k = 0; k < r.num_parts; ++k) {
        const RigidPart& part = r.part[k];
        L += part.mass * b.point(part.s0, part.kappa).cross(b.velocity(part.s0, part.kappa)).z() +
             part.inertia * b.e.cross(b.e_dot).z();
      }
      if (i > 0) L += polarInertia(m, i) * y[p + m.dofs() + i] * b.e.z();
    }
    return L;
  };
  auto torque = [&]() {  // z moment of the hang-off on the line
    const NaturalData& d = w.sim->evaluate();
    return -d.reactions.top_twist_moment.z();
  };
  const double h = 1e-4, L0 = Lz();
  double impulse = 0.0, t0 = torque(), t1 = 0.0, worst = 0.0, lmax = 0.0, spin_part = 0.0;
  for (int k = 1; k <= 10000; ++k) {
    ASSERT_TRUE(w.sim->step(h));
    if (k % 2) {
      t1 = torque();
      continue;
    }
    const double t2 = torque();
    impulse += h / 3.0 * (t0 + 4.0 * t1 + t2);  // Simpson: (ω h)⁴/180 ~ 1e-9 relative at ω ~ 300 rad/s
    t0 = t2;
    const double L = Lz();
    worst = std::max(worst, std::abs(L - L0 - impulse));
    lmax = std::max({lmax, std::abs(L), std::abs(impulse)});
  }
  for (int i = 1; i < m.bodies(); ++i) spin_part = std::max(spin_part, std::abs(polarInertia(m, i) * 3.0));
  std::printf("[torsion] L_z - L_z0 - ∫ M_z dt: %.2e N m s (|L_z|, |∫M_z| up to %.3g; a spin's J ω ~ %.2g)\n", worst,
              lmax, spin_part);
  EXPECT_GT(lmax, 1.0);
  EXPECT_LT(worst, 1e-6 * lmax);
}

// A line whirling from straight down up past horizontal and back (every rfe through vertical and
// horizontal, where Euler angles fail), spinning: the charts move every step, the energy stays.
TEST(SpatialTorsion, ChartsThroughVerticalAndHorizontal) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = 8;
  s.options.axial_flexibility = false;
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties p;
  p.stiffness = 1e3;
  p.polar_inertia = 0.05;
  p.end_polar_inertia = 0.5;
  m->setTorsion(p);
  const int nb = m->bodies();
  Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  // Hanging straight down, swung about an oblique horizontal axis: up to ~130° from down.
  sim.reset(
      rigidChain(m->line(), Vec3::Zero(), std::vector<Vec3>(nb, -Vec3::UnitZ()), Vec3::Zero(), Vec3(0.7, 1.77, 0.0)),
      0.0);
  VecX theta = VecX::Zero(nb), omega(nb);
  for (int i = 0; i < nb; ++i) omega[i] = 5.0 * std::cos(0.7 * i);
  sim.setTwist(theta, omega);
  const double scale = (s.props.mass_per_length * s.length + s.end_mass) * s.g * s.length, e0 = sim.energy();
  double worst = 0.0, zmin = 1.0, zmax = -1.0, top_angle = 0.0, twist = 0.0;
  Kinematics3 kin(nb);
  for (int k = 1; k <= 40000; ++k) {  // 4 s
    ASSERT_TRUE(sim.step(1e-4));
    if (k % 20) continue;
    sim.kinematics(kin);
    for (const auto& b : kin) zmin = std::min(zmin, std::abs(b.e.z())), zmax = std::max(zmax, -b.e.z());
    top_angle = std::max(top_angle, std::acos(std::clamp(-kin[0].e.z(), -1.0, 1.0)));
    twist = std::max(twist, std::abs(sim.evaluate().reactions.top_twist));
    worst = std::max(worst, std::abs(sim.energy() - e0 - sim.work()) / scale);
  }
  std::printf(
      "[torsion] whirl, rk4 h = 1e-4 s, 4 s: |E - E0 - W| = %.2e of m g L; min |e_z| %.1e, max -e_z %.6f, top rfe "
      "up to %.0f deg from down, top twisting moment up to %.3g N m\n",
      worst, zmin, zmax, top_angle * 180 / M_PI, twist);
  EXPECT_LT(zmin, 0.02);      // through horizontal
  EXPECT_GT(zmax, 0.9999);    // through straight down
  EXPECT_GT(top_angle, 1.6);  // past horizontal at the top
  EXPECT_GT(twist, 1.0);
  EXPECT_LT(worst, 1e-9);
}

// Torsion off: the state is [q; v; W] as before, no twist data, no twist energy.
TEST(SpatialTorsion, OffLeavesTheStateAsItWas) {
  const spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  EXPECT_EQ(sim.formulation().positionSize(), 7 * m->bodies());
  EXPECT_EQ(sim.state().size(), 2 * 7 * m->bodies() + 1);
  EXPECT_THROW(sim.setTwist(VecX::Zero(m->bodies()), VecX::Zero(m->bodies())), std::invalid_argument);
  auto on = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  on->setTorsion(TorsionProperties{1e3, 0.05, 0.0, 0.0});
  Simulator3 st(on, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  EXPECT_EQ(st.state().size(), 2 * 8 * on->bodies() + 1);
  EXPECT_THROW(on->setTorsion(TorsionProperties{1e3, 0.0, 0.0, 0.0}), std::invalid_argument);
}

// Scene: line.torsion builds the torsion (polar inertia from the pipe's diameters when not given), a planar
// scene refuses it naming the key, and a twisted-free hanging start runs with the twist at rest.
const char* kTorsionScene = R"(
space: spatial
line: {length: 50, elements: 10, outer_diameter: 0.3, inner_diameter: 0.2, youngs_modulus: 2.1e11,
       density: 7850, end_mass: 100, axial_flexibility: false,
       torsion: {stiffness: 1.0e7, end_polar_inertia: 2.0}}
solver: {dt: 0.001}
)";

TEST(SpatialTorsion, SceneKey) {
  const Scene s = parseScene(YAML::Load(kTorsionScene));
  ASSERT_TRUE(s.torsion.enabled);
  const double m = s.line.mass_per_length;
  EXPECT_DOUBLE_EQ(s.torsion.polar_inertia, m * (0.09 + 0.04) / 8.0);  // ρ π (D⁴ - d⁴)/32 = m (D² + d²)/8
  EXPECT_NEAR(s.torsion.polar_inertia, 7850 * M_PI * (std::pow(0.3, 4) - std::pow(0.2, 4)) / 32.0, 1e-9);
  Run3 run(s);
  EXPECT_TRUE(run.model().hasTorsion());
  EXPECT_EQ(run.simulator().state().size(), 2 * 8 * run.model().bodies() + 1);
  for (int k = 0; k < 100; ++k) ASSERT_TRUE(run.step()) << run.divergenceReason();
  EXPECT_LT(std::abs(run.simulator().evaluate().reactions.top_twist), 1e-6);  // hanging, untwisted: stays so
  try {
    const std::string text = kTorsionScene;
    parseScene(YAML::Load(text.substr(text.find("line:"))));  // without space: spatial
    ADD_FAILURE() << "a planar scene took line.torsion";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "line.torsion") << e.what();
  }
  const std::string no_d =
      "space: spatial\nline: {length: 5, elements: 2, EA: 1e6, EI: 1e3, mass_per_length: 1, "
      "torsion: {stiffness: 1}}\n";
  try {
    parseScene(YAML::Load(no_d));
    ADD_FAILURE() << "no polar inertia and no diameter";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "line.torsion.polar_inertia") << e.what();
  }
}

long allocationsPerStep(IntegratorKind kind) {
  Swing w = swing(kind, 2.0);
  AlignedVector<Vec3> p(w.model->bodies() + 1);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(w.sim->step(1e-3));
  const long before = g_allocations.load();
  double sink = 0.0;
  for (int k = 0; k < 20; ++k) {
    EXPECT_TRUE(w.sim->step(1e-3)) << w.sim->integrator().failure();
    w.sim->positions(p);
    sink += w.sim->energy() + w.sim->work() + w.sim->evaluate().reactions.top_twist;
  }
  EXPECT_TRUE(std::isfinite(sink));
  return g_allocations.load() - before;
}

TEST(SpatialTorsion, NoAllocationPerStep) {
  for (IntegratorKind kind : {IntegratorKind::kRk4, IntegratorKind::kDopri5, IntegratorKind::kMidpoint,
                              IntegratorKind::kGeneralizedAlpha, IntegratorKind::kRosenbrock2})
    EXPECT_EQ(allocationsPerStep(kind), 0) << name(kind);
  const long before = g_allocations.load();
  auto v = std::make_unique<VecX>(10);  // the counter counts
  EXPECT_GT(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace riser_sim
