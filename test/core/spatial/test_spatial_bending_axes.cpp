// Bending stiffness about two material axes (spatial/bending_axes.h): the forces against the energy (finite
// differences, spins included), the energy of a bend in and between the principal planes against ½ (EI_j/d) θ²,
// frame invariance, a cantilever under a sideways load against the isotropic line of the axis' stiffness and
// Euler-Bernoulli, and a swinging twisted line: energy balance, both formulations agree, the implicit scheme.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alloc_counter.h"
#include "riser_sim/scene/choices.h"
#include "riser_sim/spatial/bending_axes.h"
#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/shifted_solver.h"
#include "riser_sim/spatial/statics.h"
#include "spatial_independent_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using spatial_test::LineSpec;

constexpr double kEI1 = 1.6e3, kEI2 = 0.4e3;  // mean 1e3: flexibleLine's EI

TorsionProperties twist(double damping) {
  TorsionProperties p;
  p.stiffness = 2e3;
  p.polar_inertia = 0.05;
  p.damping = damping;
  p.end_polar_inertia = 0.3;
  return p;
}

std::shared_ptr<Model3> axesModel(LineSpec s, const Vec3& gravity, const Vec3& axis1, double EI1 = kEI1,
                                  double EI2 = kEI2, double twist_damping = 0.0) {
  s.props.EI = 0.5 * (EI1 + EI2);
  auto m = spatial_test::spatialModel(s, gravity);
  m->setTorsion(twist(twist_damping));
  m->setBendingAxes(EI1, EI2, axis1);
  return m;
}

// A bent line with its directors moved off their chart centres and random spins.
struct BentState {
  std::shared_ptr<Model3> model;
  Kinematics3 kin;
  TwistData data;
  std::vector<double> theta;
};

BentState bentState(unsigned seed) {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 6;
  BentState t;
  t.model = axesModel(s, Vec3::Zero(), Vec3(1.0, 2.0, 0.3));
  const int nb = t.model->bodies();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  t.kin = spatial_test::randomBentChain(t.model->line(), rng);
  t.data.resize(nb);
  initTwistFrames(t.kin, t.data.frames, t.model->bendingAxis());
  for (int i = 0; i < nb; ++i) {
    t.kin[i].e = (t.kin[i].e + 0.3 * Vec3(u(rng), u(rng), u(rng))).normalized() * (1.0 + 0.1 * u(rng));
    t.theta.push_back(0.8 * u(rng));
  }
  return t;
}

// -∂V/∂θ_i = the moment about e_i; -∂V/∂e_i at fixed θ = Q_e + moment_i a_i (the chart's reference turns with
// e_i by a_i·δe_i beyond the minimal rotation the forces are written for). e_i of any length.
TEST(SpatialBendingAxes, ForcesAreTheGradientOfTheEnergy) {
  double worst = 0.0, scale = 0.0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    BentState t = bentState(seed);
    const Model3& m = *t.model;
    const int nb = m.bodies();
    VecX Q = VecX::Zero(m.dofs());
    std::vector<double> moment(nb, 0.0);
    addBendingAxesForces(m, t.kin, t.theta.data(), t.data.frames, t.data.m1, Q, moment.data());
    for (int i = 0; i < nb; ++i)
      scale = std::max({scale, std::abs(moment[i]), Q.segment<3>(kDofPerBody3 * i + kE).norm()});
    auto V = [&](const Kinematics3& kin, const std::vector<double>& th) {
      return bendingAxesEnergy(m, kin, th.data(), t.data.frames);
    };
    constexpr double eps = 1e-6;
    for (int i = 0; i < nb; ++i) {
      std::vector<double> p = t.theta, q = t.theta;
      p[i] += eps;
      q[i] -= eps;
      worst = std::max(worst, std::abs(-(V(t.kin, p) - V(t.kin, q)) / (2 * eps) - moment[i]));
      const Vec3 e = t.kin[i].e, n = e.normalized();
      const Vec3 expect =
          Q.segment<3>(kDofPerBody3 * i + kE) + moment[i] * spinConnection(t.data.frames.centre[i], n) / e.norm();
      for (int k = 0; k < 3; ++k) {  // every direction: the part along e must vanish (V is degree 0 in |e|)
        Kinematics3 kp = t.kin, kq = t.kin;
        kp[i].e[k] += eps;
        kq[i].e[k] -= eps;
        worst = std::max(worst, std::abs(-(V(kp, t.theta) - V(kq, t.theta)) / (2 * eps) - expect[k]));
      }
    }
  }
  std::printf("[bending axes] forces vs -dV (central differences, 5 states, spins and |e| != 1): %.2e of %.3g N m\n",
              worst / scale, scale);
  EXPECT_GT(scale, 10.0);
  EXPECT_LT(worst / scale, 1e-7);  // central differences at 1e-6: truncation ~1e-12, round-off ~1e-10 V/eps
}

// Two rfes along -z, axis 1 = x at the hang-off: a bend by θ about x costs ½ (EI_1/d) θ², about y ½ (EI_2/d) θ²,
// about x + y the mean; rfe 1 spun by 90° (its axis 1 along y): the two rfes' axes average to the mean too.
TEST(SpatialBendingAxes, PrincipalBendsCostTheirAxisStiffness) {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 1;
  const auto m = axesModel(s, Vec3::Zero(), Vec3::UnitX());
  const double d = m->line().segmentLength(), theta = 0.3;
  const auto energy = [&](const Vec3& about, double spin) {
    const Vec3 down = -Vec3::UnitZ(), bent = Eigen::AngleAxisd(theta, about.normalized()) * down;
    const Kinematics3 kin = rigidChain(m->line(), Vec3::Zero(), {down, bent}, Vec3::Zero(), Vec3::Zero());
    TwistData data;
    data.resize(2);
    initTwistFrames(kin, data.frames, m->bendingAxis());
    const double th[2] = {0.0, spin};
    return 0.5 * m->bendingStiffness(1) * theta * theta + bendingAxesEnergy(*m, kin, th, data.frames);
  };
  const double v1 = 0.5 * kEI1 / d * theta * theta, v2 = 0.5 * kEI2 / d * theta * theta, vm = 0.5 * (v1 + v2);
  std::printf(
      "[bending axes] bend 0.3 rad about axis 1: %.12g J (EI_1: %.12g), axis 2: %.12g (EI_2: %.12g), "
      "between: %.12g, axes crossed by a 90 deg twist: %.12g (mean %.12g)\n",
      energy(Vec3::UnitX(), 0.0), v1, energy(Vec3::UnitY(), 0.0), v2, energy(Vec3(1, 1, 0), 0.0),
      energy(Vec3::UnitX(), 0.5 * M_PI), vm);
  EXPECT_NEAR(energy(Vec3::UnitX(), 0.0), v1, 1e-12 * v1);
  EXPECT_NEAR(energy(Vec3::UnitY(), 0.0), v2, 1e-12 * v1);
  EXPECT_NEAR(energy(Vec3(1, 1, 0), 0.0), vm, 1e-12 * v1);
  EXPECT_NEAR(energy(Vec3::UnitX(), 0.5 * M_PI), vm, 1e-12 * v1);
  EXPECT_NEAR(energy(Vec3::UnitY(), 0.5 * M_PI), vm, 1e-12 * v1);
}

// The energy and the forces turn with the line: rotate the state and axis 1 by R, the energy is the same and
// every force and moment the rotated one (to round-off).
TEST(SpatialBendingAxes, FrameInvariant) {
  BentState t = bentState(3);
  const Model3& m = *t.model;
  const int nb = m.bodies();
  const Mat3 R = spatial_test::yawTilt(2.1, 0.7);
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 6;
  const auto mr = axesModel(s, Vec3::Zero(), R * m.bendingAxis());
  Kinematics3 kr = t.kin;
  for (auto& b : kr) b.A = R * b.A, b.e = R * b.e;
  TwistData dr;
  dr.resize(nb);
  TwistData d0 = t.data;
  dr.frames = d0.frames;
  for (int i = 0; i < nb; ++i) dr.frames.centre[i] = R * d0.frames.centre[i], dr.frames.ref[i] = R * d0.frames.ref[i];
  VecX Q = VecX::Zero(m.dofs()), Qr = Q;
  std::vector<double> mo(nb, 0.0), mor(nb, 0.0);
  addBendingAxesForces(m, t.kin, t.theta.data(), d0.frames, d0.m1, Q, mo.data());
  addBendingAxesForces(*mr, kr, t.theta.data(), dr.frames, dr.m1, Qr, mor.data());
  const double v = bendingAxesEnergy(m, t.kin, t.theta.data(), d0.frames),
               vr = bendingAxesEnergy(*mr, kr, t.theta.data(), dr.frames);
  double df = 0.0, scale = 0.0;
  for (int i = 0; i < nb; ++i) {
    df = std::max({df, (R * Q.segment<3>(kDofPerBody3 * i + kE) - Qr.segment<3>(kDofPerBody3 * i + kE)).norm(),
                   std::abs(mo[i] - mor[i])});
    scale = std::max(scale, std::abs(mo[i]));
  }
  std::printf("[bending axes] rotated state: energy %.3e J off of %.4g J, forces %.2e of %.3g N m\n", std::abs(v - vr),
              v, df / scale, scale);
  EXPECT_GT(std::abs(v), 1.0);
  EXPECT_NEAR(v, vr, 1e-12 * std::abs(v));
  EXPECT_LT(df / scale, 1e-12);
}

// A 10 m cantilever along -z clamped by a stiff flex joint, loaded by its own weight across it (gravity
// g_s = 1e-3 m/s² along (cos β, sin β, 0): small deflections), axis 1 along y. Load along x: the line bends about
// y = axis 1 and is the isotropic line of EI_1 (the same discrete problem: to Newton's 1e-12); along y, EI_2's.
Vec3 cantileverTip(double beta, double EI1, double EI2, bool isotropic, int n = 20) {
  LineSpec s;
  s.segments = n;
  s.props.mass_per_length = 10.0;
  s.props.EA = 1e8;
  s.props.EI = 0.5 * (EI1 + EI2);
  const double g = 1e-3;
  const Vec3 gravity(g * std::cos(beta), g * std::sin(beta), 0.0);
  std::shared_ptr<Model3> m;
  if (isotropic) {
    m = spatial_test::spatialModel(s, gravity);
    m->setTorsion(twist(0.0));
  } else {
    m = axesModel(s, gravity, Vec3::UnitY(), EI1, EI2);
  }
  m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, -Vec3::UnitZ(), 1e9, 0.0));
  const std::vector<Vec3> down(m->bodies(), -Vec3::UnitZ());
  const Kinematics3 eq = equilibrium3(*m, rigidChain(m->line(), Vec3::Zero(), down, Vec3::Zero(), Vec3::Zero()));
  return eq.back().end();
}

TEST(SpatialBendingAxes, CantileverBendsAboutEachAxisWithItsStiffness) {
  const Vec3 ax = cantileverTip(0.0, kEI1, kEI2, false), ay = cantileverTip(0.5 * M_PI, kEI1, kEI2, false);
  const Vec3 ix = cantileverTip(0.0, kEI1, kEI1, true), iy = cantileverTip(0.5 * M_PI, kEI2, kEI2, true);
  // Euler-Bernoulli: q L⁴ / (8 EI), q = 10 kg/m x 1e-3 m/s²; the lumped rfes converge at O(1/n²).
  const double q = 10.0 * 1e-3, L = 10.0, eb1 = q * L * L * L * L / (8.0 * kEI1), eb2 = eb1 * kEI1 / kEI2;
  std::printf(
      "[bending axes] cantilever tip, load along x (about axis 1): %.9e m (isotropic EI_1 %.9e, EB %.6e); "
      "along y: %.9e m (isotropic EI_2 %.9e, EB %.6e); ratio %.9f (EI_1/EI_2 %.3f); out of the load's "
      "plane %.1e, %.1e m\n",
      ax.x(), ix.x(), eb1, ay.y(), iy.y(), eb2, ay.y() / ax.x(), kEI1 / kEI2, std::abs(ax.y()), std::abs(ay.x()));
  EXPECT_NEAR(ax.x(), ix.x(), 1e-10);  // [m] Newton to 1e-12 of the weight
  EXPECT_NEAR(ay.y(), iy.y(), 1e-10);
  EXPECT_LT(std::abs(ax.y()) + std::abs(ay.x()), 1e-12);
  // Against the continuum (n = 20): the RFEM's lumped bending at O(1/n²), ~1 % here.
  EXPECT_NEAR(ax.x() / eb1, 1.0, 0.02);
  EXPECT_NEAR(ay.y() / eb2, 1.0, 0.02);
}

// Loaded between the axes (β = 30°): the line bends towards the soft axis, off the load's plane. In the linear
// range the tip is the two principal tips superposed, each scaled by the load's component along it:
// (cos β x_1, sin β y_2). Its direction off by (δ/L)² ~ 1e-5 relative (the geometric nonlinearity).
TEST(SpatialBendingAxes, CantileverLoadedBetweenTheAxesBendsTowardsTheSoftOne) {
  const double beta = M_PI / 6.0;
  const Vec3 tip = cantileverTip(beta, kEI1, kEI2, false);
  const Vec3 ax = cantileverTip(0.0, kEI1, kEI2, false), ay = cantileverTip(0.5 * M_PI, kEI1, kEI2, false);
  const Vec2 expect(std::cos(beta) * ax.x(), std::sin(beta) * ay.y());
  const double angle = std::atan2(tip.y(), tip.x()), expect_angle = std::atan2(expect.y(), expect.x());
  std::printf(
      "[bending axes] load at %.0f deg: tip (%.6e, %.6e) m at %.4f deg; principal superposition (%.6e, "
      "%.6e) at %.4f deg\n",
      beta * 180 / M_PI, tip.x(), tip.y(), angle * 180 / M_PI, expect.x(), expect.y(), expect_angle * 180 / M_PI);
  EXPECT_GT(angle - beta, 0.5);  // [rad] 30° load, ~66° deflection: clearly towards the soft axis
  EXPECT_NEAR(angle, expect_angle, 1e-4);
  EXPECT_NEAR(tip.head<2>().norm() / expect.norm(), 1.0, 1e-4);
}

// The flexible line (dampers on), twisted and spinning under a swaying, yawing top, axes oblique, EI_1 = 4 EI_2:
// both formulations (rk4, 1e-4 s) agree and keep E - E0 - W, as the torsion cross-check's bounds.
// The swinging tests' line: flexibleLine at n = 8 with dampers, axes oblique, EI_1 = 4 EI_2, bent; turning at w.
std::shared_ptr<Model3> swingLine(Kinematics3& kin0, const Vec3& w) {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 8;
  const auto m = axesModel(s, Vec3(0, 0, -s.g), Vec3(1.0, 2.0, 0.3), kEI1, kEI2, 2.0);
  std::vector<Vec3> dirs;
  for (int i = 0; i < m->bodies(); ++i) dirs.push_back(Vec3(0.3 + 0.1 * i, 0.2 - 0.05 * i, -1.0).normalized());
  kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), w);
  return m;
}

TEST(SpatialBendingAxes, SwingingLineBalancesEnergyInBothFormulations) {
  const LineSpec s = spatial_test::flexibleLine();
  Kinematics3 kin0;
  const auto m = swingLine(kin0, Vec3(0.2, -0.3, 0.5));
  const int nb = m->bodies();
  const auto top = [] {
    return std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), spatial_test::yawTilt(0.3, 0.5));
  };
  Simulator3 nat(m, top(), IntegratorKind::kRk4);
  IndependentSimulator3 ind(m, top(), IntegratorKind::kRk4);
  nat.reset(kin0, 0.0);
  ind.reset(kin0, 0.0);
  VecX theta(nb), omega(nb);
  for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i, omega[i] = 3.0 * std::sin(1.0 + i);
  nat.setTwist(theta, omega);
  ind.setTwist(theta, omega);
  const double scale = (s.props.mass_per_length * s.length + s.end_mass) * s.g * s.length;
  const double e0n = nat.energy(), e0i = ind.energy();
  AlignedVector<Vec3> pn(nb + 1), pi(nb + 1);
  double dx = 0.0, balance = 0.0, bend = 0.0;
  for (int k = 0; k < 20; ++k) {
    for (int j = 0; j < 500; ++j) {
      ASSERT_TRUE(nat.step(1e-4));
      ASSERT_TRUE(ind.step(1e-4));
    }
    nat.positions(pn);
    ind.positions(pi);
    for (int i = 0; i <= nb; ++i) dx = std::max(dx, (pn[i] - pi[i]).norm());
    balance = std::max({balance, std::abs(nat.energy() - e0n - nat.work()) / scale,
                        std::abs(ind.energy() - e0i - ind.work()) / scale});
    const TwistData& tw = nat.evaluate().twist;
    for (double b : tw.bend) bend = std::max(bend, std::abs(b));
  }
  std::printf(
      "[bending axes] swinging, twisted line, 1 s: natural vs independent |dx| %.2e m; E - E0 - W %.2e of "
      "m g L; largest axes' twisting moment %.3g N m\n",
      dx, balance, bend);
  EXPECT_GT(bend, 1.0);  // [N m] the axes' part acts
  EXPECT_LT(dx, 1e-9);
  EXPECT_LT(balance, 1e-9);
}

// The implicit midpoint with the O(n) structured solve (its linearisation leaves the axes' part out: Newton
// converges on the full residual) against rk4 at 1e-4 s: second order, the same motion.
TEST(SpatialBendingAxes, ImplicitSchemeConvergesWithoutTheAxesInItsJacobian) {
  Kinematics3 kin0;
  const auto m = swingLine(kin0, Vec3::Zero());
  const int nb = m->bodies();
  const auto run = [&](IntegratorKind kind, double h) {
    IntegratorOptions io;
    io.jacobian = JacobianKind::kStructured;
    Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), kind, io);
    sim.reset(kin0, 0.0);
    const int steps = int(std::lround(0.5 / h));
    for (int k = 0; k < steps; ++k) EXPECT_TRUE(sim.step(h));
    AlignedVector<Vec3> p(nb + 1);
    sim.positions(p);
    return p;
  };
  const AlignedVector<Vec3> ref = run(IntegratorKind::kRk4, 1e-4);
  double err[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const AlignedVector<Vec3> p = run(IntegratorKind::kMidpoint, k == 0 ? 2e-3 : 1e-3);
    for (int i = 0; i <= nb; ++i) err[k] = std::max(err[k], (p[i] - ref[i]).norm());
  }
  std::printf("[bending axes] midpoint vs rk4 at 0.5 s: h = 2e-3 %.3e m, 1e-3 %.3e m (ratio %.2f)\n", err[0], err[1],
              err[0] / err[1]);
  EXPECT_LT(err[1], 1e-3);
  EXPECT_GT(err[0] / err[1], 3.0);  // second order: 4
  EXPECT_LT(err[0] / err[1], 5.0);
}

// Zero allocations per step with the axes on: every integrator (the implicit ones structured), the energy too.
TEST(SpatialBendingAxes, NoAllocationPerStep) {
  Kinematics3 kin0;
  const auto m = swingLine(kin0, Vec3::Zero());
  for (IntegratorKind kind : {IntegratorKind::kRk4, IntegratorKind::kDopri5, IntegratorKind::kMidpoint,
                              IntegratorKind::kGeneralizedAlpha, IntegratorKind::kRosenbrock2}) {
    IntegratorOptions io;
    io.jacobian = JacobianKind::kStructured;
    Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), kind, io);
    sim.reset(kin0, 0.0);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(sim.step(1e-3)) << name(kind);
    const long before = g_allocations.load();
    double sink = 0.0;
    for (int k = 0; k < 20; ++k) {
      EXPECT_TRUE(sim.step(1e-3)) << name(kind);
      sink += sim.energy() + sim.work() + sim.evaluate().reactions.top_twist;
    }
    EXPECT_TRUE(std::isfinite(sink));
    EXPECT_EQ(g_allocations.load() - before, 0) << name(kind);
  }
}

// linearize() evaluates a state it was not handed into the data's own dy: sized for [q; θ; v; ω] with torsion on
// (it held [q; v] only: a heap overflow a twisted implicit run could reach).
TEST(SpatialBendingAxes, LinearizationWorkspaceHoldsTheSpins) {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 4;
  const auto m = axesModel(s, Vec3(0, 0, -s.g), Vec3::UnitX());
  const NaturalFormulation f(*m, 50.0);
  const auto d = f.makeData();
  EXPECT_EQ(d->dy.size(), 2 * f.positionSize());
  const std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.1, -1.0).normalized());
  VecX y = VecX::Zero(2 * f.positionSize());
  f.packState(rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero()), y);
  f.initTwist(y, *d);
  const auto solver = f.makeShifted();
  f.linearize(0.0, y, PointMotion3{}, *d, *solver);
  EXPECT_TRUE(d->dy.allFinite());
}
}  // namespace
}  // namespace riser_sim
