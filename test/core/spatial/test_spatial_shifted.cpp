// The spatial formulation's structured O(n) solves (spatial/shifted_solver.h) against the implicit
// schemes' dense finite-difference Jacobian: the solve itself on random states, and end to end on a 3D
// swinging line (free end; pinned bottom) with midpoint, generalized_alpha and rosenbrock2. A planar scene
// through the 3D path against the 2D recursive formulation's structured midpoint.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <random>

#include "riser_sim/planar/simulator.h"
#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

struct LineCase {
  const char* name;
  bool pinned, flexible;
  bool bending_damping = true;
  bool ends = false;  // flex joints at the top (and at a pinned bottom), the pinned bottom moving
};

spatial_test::LineSpec spec(bool flexible, int segments = 10, bool bending_damping = true) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = segments;
  if (!bending_damping) s.props.bending_damping = 0.0;
  if (!flexible) {
    s.options.axial_flexibility = false;
    s.options.bending = false;
  }
  return s;
}

// A bent line hung from the origin (slack when pinned at its initial end), swinging out of any plane.
std::shared_ptr<Model3> swingModel(const LineCase& c, Kinematics3& kin0, int segments = 10) {
  const spatial_test::LineSpec s = spec(c.flexible, segments, c.bending_damping);
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  std::vector<Vec3> dirs(m->bodies());
  for (int i = 0; i < m->bodies(); ++i) dirs[i] = 2 * i < m->bodies() ? Vec3(0.4, 0.2, -1.0) : Vec3(-0.3, 0.3, -1.0);
  const Vec3 omega = c.pinned ? Vec3::Zero() : Vec3(0.2, -0.3, 0.5);
  kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), omega);
  if (c.pinned) m->setBottom(BottomBoundary::kPinned, kin0.back().end());
  return m;
}

std::unique_ptr<TopMotion3> sway() {
  return std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), spatial_test::yawTilt(0.3, 0.5));
}

IntegratorOptions withJacobian(JacobianKind j) {
  IntegratorOptions o;
  o.jacobian = j;
  return o;
}

// ---------------------------------------------------------------------------------------------------
// The solve: x = (I - cJ)^-1 b against the dense solve with a central-difference J, on random states.

// Central differences with step 1e-6 (positions ~1 m, rates ~1 /s): truncation ~1e-12 relative, round-off
// ~1e-16 |f| / 1e-6 = 1e-10 relative: the dense Jacobian is good to ~1e-9 relative.
constexpr double kFd = 1e-6;
// For the shipped terms the structured K, C and constraint rows are the exact Jacobian, so the two solves
// agree to the finite differences' accuracy at every c, not only as c -> 0 (measured: 1e-11..3e-9 relative,
// worst 2.6e-7 on a moving pinned inextensible line at c = 1e-2; flex joints at both ends with the bottom
// moving: up to 1.3e-7; without the flex joint's 2φ g bᵀ term: 2e-3..5e-2). A left-out term shows at 1e-4..1e-2
// (the bending damping's dependence on e: 9e-5..8e-4; the bending Hessian at θ = 0 for all θ: 1e-3..2e-2).
constexpr double kSolveAgree = 1e-6;

MatX fdJacobian(OdeSystem& sys, const VecX& y, int m) {
  MatX J(m, m);
  VecX yp = y, fp(y.size()), fm(y.size());
  for (int j = 0; j < m; ++j) {
    yp[j] = y[j] + kFd;
    sys.rhs(0.0, yp, fp);
    yp[j] = y[j] - kFd;
    sys.rhs(0.0, yp, fm);
    yp[j] = y[j];
    J.col(j) = (fp.head(m) - fm.head(m)) / (2.0 * kFd);
  }
  return J;
}

// |x_s - x_d|_inf relative to |x_d|_inf and to the correction |x_d - b|_inf at c, for one random state.
struct SolveGap {
  double c, rel, rel_correction;
};

std::vector<SolveGap> solveGaps(const LineCase& lc, unsigned seed, bool at_rest) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  Kinematics3 kin0;
  auto m = swingModel(lc, kin0);
  std::vector<Vec3> dirs(m->bodies());
  for (Vec3& d : dirs) d = Vec3(0.3 * N(rng), 0.3 * N(rng), -1.0);
  Kinematics3 kin =
      rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), at_rest ? Vec3::Zero() : Vec3(N(rng), N(rng), N(rng)));
  if (lc.pinned) m->setBottom(BottomBoundary::kPinned, kin.back().end() + Vec3(0.01, -0.02, 0.01));  // off by a gap
  if (lc.ends) {  // axes off the line's: both joints loaded
    m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, Vec3(0.3, -0.2, -1.0), 3e3, 50.0));
    if (lc.pinned) {
      m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kBottom, Vec3(-0.2, 0.4, 1.0), 2e3, 30.0));
      const Vec3 amp(0.3, -0.2, 0.1), p0 = m->bottomPoint();
      m->setBottomMotion(std::make_shared<SinusoidMotion3>(p0 - amp, amp, 2.0, Vec3(0.0, 0.5, 1.0)));
    }
  }
  if (!at_rest)
    for (BodyKinematics3& b : kin) {
      b.A_dot += 0.1 * Vec3(N(rng), N(rng), N(rng));  // joints not closed in velocity
      b.e_dot += 0.3 * Vec3(N(rng), N(rng), N(rng));
      if (lc.flexible) b.delta = 1e-4 * N(rng), b.delta_dot = 1e-2 * N(rng);
    }
  Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kMidpoint);
  sim.reset(kin, 0.0);
  VecX y = sim.state();
  const int p = sim.formulation().positionSize(), n = 2 * p;
  OdeSystem& sys = sim.system();
  const MatX J = fdJacobian(sys, y, n);
  VecX b(y.size()), x(y.size());
  for (int i = 0; i < b.size(); ++i) b[i] = N(rng);
  std::vector<SolveGap> out;
  for (double c : {1e-2, 1e-3, 1e-4}) {
    const VecX xd = (MatX::Identity(n, n) - c * J).partialPivLu().solve(b.head(n));
    sys.linearize(0.0, y);
    sys.factorShifted(c);
    sys.solveShifted(b, x);
    const double d = (x.head(n) - xd).lpNorm<Eigen::Infinity>();
    out.push_back({c, d / xd.lpNorm<Eigen::Infinity>(), d / (xd - b.head(n)).lpNorm<Eigen::Infinity>()});
  }
  return out;
}

TEST(SpatialShifted, SolveAgainstDenseFiniteDifferenceJacobian) {
  const LineCase cases[] = {{"free flexible", false, true},
                            {"pinned flexible", true, true},
                            {"pinned flexible, no bending damping", true, true, false},
                            {"free inextensible", false, false},
                            {"pinned inextensible", true, false},
                            {"free flexible, top flex joint", false, true, true, true},
                            {"pinned flexible, flex joints, moving bottom", true, true, true, true}};
  for (const LineCase& lc : cases)
    for (bool at_rest : {true, false})
      for (unsigned seed : {1u, 2u}) {
        const std::vector<SolveGap> g = solveGaps(lc, seed, at_rest);
        std::printf("[spatial shifted] %s, %s, seed %u:", lc.name, at_rest ? "at rest" : "moving", seed);
        for (const SolveGap& s : g)
          std::printf("  c = %.0e: %.1e (of the correction %.1e)", s.c, s.rel, s.rel_correction);
        std::printf("\n");
        for (const SolveGap& s : g) EXPECT_LT(s.rel, kSolveAgree) << lc.name << " c = " << s.c;
      }
}

// ---------------------------------------------------------------------------------------------------
// End to end on the swinging line.

constexpr double kDuration = 0.5;  // [s]

struct LineRun {
  AlignedVector<Vec3> p;  // A_0..A_n, E_n [m]
  double newton_per_step = 0.0;
};

LineRun run(const LineCase& lc, IntegratorKind kind, JacobianKind jac, double h) {
  Kinematics3 kin0;
  auto m = swingModel(lc, kin0);
  Simulator3 sim(m, sway(), kind, withJacobian(jac));
  sim.reset(kin0, 0.0);
  const int steps = int(std::lround(kDuration / h));
  for (int k = 0; k < steps; ++k) EXPECT_TRUE(sim.step(h)) << sim.integrator().failure();
  LineRun r;
  r.p.resize(m->bodies() + 1);
  sim.positions(r.p);
  const Integrator::Stats st = sim.integrator().stats();
  r.newton_per_step = double(st.newton) / double(steps);
  return r;
}

double maxGap(const LineRun& a, const LineRun& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.p.size(); ++i) d = std::max(d, (a.p[i] - b.p[i]).norm());
  return d;
}

const LineCase kSwings[] = {{"free", false, true}, {"pinned", true, true}};

// Newton stops at |Δz| <= 1e-11 (1 + |z|) (implicit_integrators.cpp): both Jacobians converge to the same
// stage solution to ~1e-11 m per step, ~1e-8 m over 500 steps at worst; 1e-7 m leaves a factor 10.
// Measured 1.9e-14..2.1e-13 m; Newton iterations per step 3.0..3.1 structured, 4.7..5.9 dense.
constexpr double kSameStage = 1e-7;

TEST(SpatialShifted, StructuredAndDenseNewtonGiveTheSameSteps) {
  const LineCase cases[] = {kSwings[0], kSwings[1], {"pinned inextensible", true, false}};
  for (const LineCase& lc : cases)
    for (IntegratorKind kind : {IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha}) {
      const LineRun s = run(lc, kind, JacobianKind::kStructured, 1e-3), d = run(lc, kind, JacobianKind::kDense, 1e-3);
      const double gap = maxGap(s, d);
      std::printf(
          "[spatial shifted] %s, %s, h = 1e-3 s: structured vs dense %.2e m; Newton iterations per step "
          "%.2f structured, %.2f dense\n",
          lc.name, name(kind), gap, s.newton_per_step, d.newton_per_step);
      EXPECT_LT(gap, kSameStage);
    }
}

// rosenbrock2 does not iterate: its step depends on J, and any J keeps its second order (a W-method).
// Structured and dense then differ by O(h²) like either's error: bounded by the sum of their errors
// against the rk4 reference (plus 10 % for that reference's own).
TEST(SpatialShifted, Rosenbrock2StructuredAndDenseWithinTheirErrors) {
  for (const LineCase& lc : kSwings) {
    const LineRun ref = run(lc, IntegratorKind::kRk4, JacobianKind::kStructured, 5e-5);
    const LineRun s = run(lc, IntegratorKind::kRosenbrock2, JacobianKind::kStructured, 1e-3);
    const LineRun d = run(lc, IntegratorKind::kRosenbrock2, JacobianKind::kDense, 1e-3);
    const double gap = maxGap(s, d), es = maxGap(s, ref), ed = maxGap(d, ref);
    std::printf(
        "[spatial shifted] %s, rosenbrock2, h = 1e-3 s: structured vs dense %.2e m; errors %.2e m "
        "structured, %.2e m dense\n",
        lc.name, gap, es, ed);
    EXPECT_LT(gap, 1.1 * (es + ed));
  }
}

// Order: end-of-run positions against rk4 at h = 5e-5 s (error ~1e-13 m, spatial tests), at h and h/2:
// h = 1e-3 s for the Newton schemes; rosenbrock2 (errors ~10x larger, its O(h³) terms still show at 1e-3 s:
// ratio 3.5 there) at h = 5e-4 s.
TEST(SpatialShifted, StructuredSchemesAreSecondOrder) {
  for (const LineCase& lc : kSwings) {
    const LineRun ref = run(lc, IntegratorKind::kRk4, JacobianKind::kStructured, 5e-5);
    for (IntegratorKind kind :
         {IntegratorKind::kMidpoint, IntegratorKind::kGeneralizedAlpha, IntegratorKind::kRosenbrock2}) {
      const double h = kind == IntegratorKind::kRosenbrock2 ? 5e-4 : 1e-3;
      const double e1 = maxGap(run(lc, kind, JacobianKind::kStructured, h), ref);
      const double e2 = maxGap(run(lc, kind, JacobianKind::kStructured, h / 2), ref);
      std::printf("[spatial shifted] %s, %s structured: error %.2e m (h = %.0e s), %.2e m (h/2), ratio %.2f\n", lc.name,
                  name(kind), e1, h, e2, e1 / e2);
      // Second order: 4 per halving; 3.5..4.6 allows the O(h³) terms.
      EXPECT_GT(e1 / e2, 3.5);
      EXPECT_LT(e1 / e2, 4.6);
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// A planar scene through the 3D path (midpoint, structured) against the 2D recursive formulation's
// structured midpoint. The implicit midpoint rule is not invariant under the nonlinear change of
// coordinates (natural -> chain angles), so the two runs differ by O(h²): each is within K h² of an rk4
// reference, and they agree to the sum of their errors.
TEST(SpatialShifted, PlanarSceneAgreesWithTheRecursiveMidpoint) {
  const spatial_test::LineSpec s = spec(true);
  auto m2 = spatial_test::planarModel(s);
  const Kinematics kin0 =
      spatial_test::planarChain(*m2, Vec2::Zero(), std::vector<double>(m2->bodies(), -M_PI / 2 + 0.35));
  const double T = 1.0;  // [s]
  auto end3 = [&](IntegratorKind kind, double h) {
    auto m3 = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
    Simulator3 sim(m3, std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.0), 2.0)), kind);
    sim.reset(fromPlanar(kin0), 0.0);
    for (int k = 0, n = int(std::lround(T / h)); k < n; ++k) EXPECT_TRUE(sim.step(h));
    AlignedVector<Vec3> p(m3->bodies() + 1);
    sim.positions(p);
    return p.back();
  };
  auto end2 = [&](double h) {
    SolverSettings st;
    st.dt = h;
    st.integrator = IntegratorKind::kMidpoint;
    st.formulation = FormulationKind::kRecursive;
    st.jacobian = JacobianKind::kStructured;
    Simulator sim(m2, spatial_test::topSway(Vec2(0.5, 0.0), 2.0), st);
    sim.setInitialState(kin0, 0.0);
    for (int k = 0, n = int(std::lround(T / h)); k < n; ++k) EXPECT_TRUE(sim.step());
    Kinematics kin(m2->bodies());
    sim.kinematics(kin);
    return planarPoint(kin.back().end());
  };
  const Vec3 ref = end3(IntegratorKind::kRk4, 5e-5);
  for (double h : {1e-3, 5e-4}) {
    const Vec3 p3 = end3(IntegratorKind::kMidpoint, h), p2 = end2(h);
    const double e3 = (p3 - ref).norm(), e2 = (p2 - ref).norm(), gap = (p3 - p2).norm();
    std::printf(
        "[spatial shifted] planar scene, midpoint structured, h = %.0e s: 3D natural vs 2D recursive %.2e m; "
        "errors against rk4 %.2e m (3D), %.2e m (2D); K = error / h² %.0f, %.0f m/s²\n",
        h, gap, e3, e2, e3 / (h * h), e2 / (h * h));
    EXPECT_LT(gap, 1.1 * (e3 + e2));  // 10 % for the reference's own error and round-off
    EXPECT_LT(e3, 30.0 * h * h);      // K = 3 m/s² measured for both; 10x margin, a first-order run is far off
    EXPECT_LT(e2, 30.0 * h * h);
  }
}

}  // namespace
}  // namespace riser_sim
