// The sea in 3D (buoyancy, Morison drag, the Froude-Krylov force; current and waves with a heading):
// - each term against its energy and power (FD, random states crossing the surface, tilted gravity), the drag's
//   damping matrix against central differences in the rates;
// - a planar sea scene yawed into 3D (current profile, waves, drag, buoyancy, a moving top) gives the planar
//   core's result rotated, to 1e-9 m: the 2D terms are validated against the paper (docs/validation.md);
// - out of any plane: waves and current from different headings, the energy balance E - E0 = W;
// - the statics in a current lean downstream at any heading; a displaced end in a current across its plane;
// - no allocation per step with the sea on (rk4, structured midpoint).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/forces/buoyancy.h"
#include "riser_sim/spatial/forces/froude_krylov.h"
#include "riser_sim/spatial/forces/morison_drag.h"
#include "riser_sim/spatial/relaxation.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/planar/simulator.h"
#include "spatial_force_checks.h"
#include "spatial_sea_scenes.h"
#include "spatial_test_util.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

using namespace spatial;

using spatial_test::kSeaLine;

Scene seaScene(const std::string& rest, const std::vector<std::string>& sets = {}) {
  return loadSceneText(std::string(kSeaLine) + rest, "test_spatial_sea", sets);
}

Mat3 yaw(double deg) { return spatial_test::yawDeg(deg); }

spatial_test::LineSpec termLine() {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = 5;
  s.props.outer_diameter = 0.3;
  return s;
}

WaterSpec movingWater() {
  WaterSpec w;
  w.enabled = true;
  w.surface = -4.0;  // the random states span z ~ 1 .. -11: parts cross it
  w.current.velocity = Vec3(0.7, -0.4, 0.05);
  w.current.acceleration = Vec3(0.02, 0.01, 0.0);
  return w;
}

// Buoyancy against its potential energy; drag and Froude-Krylov have none: Q·q' = P (the power they report).
TEST(SpatialSea, TermsAgainstTheirEnergyAndPower) {
  auto m = spatial_test::spatialModel(termLine(), Vec3(1.2, -0.7, -9.5));
  const Water3 water(movingWater(), m->gravity());
  const Buoyancy lift(water);
  const MorisonDrag drag(water, 0.3, 1.1);
  const FroudeKrylov fk(water, 1.8, 1.3);
  spatial_test::checkGradient(lift, *m);
  for (const ForceTerm3* t : {static_cast<const ForceTerm3*>(&lift), static_cast<const ForceTerm3*>(&drag),
                              static_cast<const ForceTerm3*>(&fk)})
    spatial_test::checkPower(*t, *m);
  // The check has teeth: the lift is not zero on these states.
  std::mt19937 rng(7);
  const NaturalFormulation f(*m, 50.0);
  Kinematics3 kin(m->bodies());
  f.kinematics(spatial_test::randomState(*m, rng, false), kin);
  VecX Q = VecX::Zero(m->dofs());
  lift.addForces(*m, kin, 0.0, Q);
  EXPECT_GT(Q.cwiseAbs().maxCoeff(), 100.0);
}

// The drag's C = -∂Q/∂q' against central differences of Q in each rate (Q is quadratic in the rates, so the
// differences are exact up to round-off and the kinks of |v| at 0, which random states avoid): bound 1e-7
// of the largest entry.
TEST(SpatialSea, DragDampingMatrixAgainstDifferences) {
  auto m = spatial_test::spatialModel(termLine(), Vec3(0.0, 0.0, -9.81));
  const Water3 water(movingWater(), m->gravity());
  const MorisonDrag drag(water, 0.3, 1.1);
  std::mt19937 rng(3);
  double worst = 0.0;
  for (int trial = 0; trial < 3; ++trial) {
    const double err = spatial_test::rateJacobianError(drag, *m, spatial_test::randomState(*m, rng, true), 0.3);
    EXPECT_LT(err, 1e-7) << "trial " << trial;
    worst = std::max(worst, err);
  }
  std::printf("[ measured ] drag damping matrix vs differences: %.2e of the largest entry\n", worst);
}

// The planar sea yawed by 35 deg: top, current (a profile) and wave heading rotated; the planar core's run
// rotated into 3D must match to 1e-9 m (the planar-through-3D bound of docs/spatial.md). 4 s of rk4, the
// waves ramped in over 2 s.
TEST(SpatialSea, YawedPlanarSeaMatchesThePlanarCore) {
  const double psi = 35.0;
  const Mat3 R = yaw(psi);
  const double c = std::cos(psi * M_PI / 180.0);
  const spatial_test::YawedSea sea = spatial_test::yawedSea(psi);
  // The two cores discretise the same ODE differently (angles vs directors): their rk4 results differ by
  // their truncation errors, O(h^4). At h = 2e-3 s and 1e-3 s the difference falls ~16x to below 1e-9 m.
  double worst[2] = {0.0, 0.0}, lean = 0.0;
  for (int r = 0; r < 2; ++r) {
    const std::vector<std::string> dt = {r == 0 ? "solver.dt=0.002" : "solver.dt=0.001"};
    riser_sim::Run planar = buildRun(seaScene(sea.planar, dt));
    Run3 run(seaScene(sea.spatial, dt));
    // The statics lean the line downstream in both (the 3D one in the current's plane).
    EXPECT_NEAR(run.initial().plane_direction.x(), c, 1e-15);
    EXPECT_LE(run.initial().max_acceleration, run.initial().acceleration_bound);
    worst[r] = spatial_test::planarVs3D(planar, run, R, 4.0, &lean);
  }
  EXPECT_LE(worst[1], 1e-9);
  EXPECT_GT(worst[0] / worst[1], 8.0);  // the difference is truncation (fourth order), not a modelling one
  EXPECT_GT(lean, 1.0);                 // the current moves the end downstream by metres: the test sees the sea
  std::printf(
      "[ measured ] planar sea yawed %g deg through 3D vs the planar core, 4 s: %.2e m (h = 2e-3 s), %.2e m "
      "(1e-3 s); end leans %.3g m downstream at rest\n",
      psi, worst[0], worst[1], lean);
}

// Waves from 60 deg, the current towards -30 deg and the top circling: the line moves out of every plane.
// E - E0 - W (W: the drag's, the Froude-Krylov force's and the top's work) stays at rk4's truncation
// level: measured at two steps, it falls by ~16x per halving (fourth order). Bound 1e-6 of m g L.
TEST(SpatialSea, EnergyBalanceOutOfPlane) {
  const std::string sea = R"(space: spatial
top:
  position: [0.0, 0.0, 5.0]
  motion: {type: sinusoid, amplitude: [1.0, 1.0, 0.3], period: 5.0}
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {velocity: [0.6, -0.35, 0.0]}
  waves: {height: 4.0, period: 6.0, depth: 150.0, ramp: 1.0, heading: 60.0}
)";
  double drift[2];
  for (int r = 0; r < 2; ++r) {
    Scene sc = seaScene(sea);
    sc.solver.dt = r == 0 ? 0.01 : 0.005;
    Run3 run(sc);
    const long steps = std::lround(3.0 / sc.solver.dt);
    double worst = 0.0;
    for (long k = 0; k < steps; ++k) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      worst = std::max(worst, std::abs(run.energyDrift()));
    }
    const LineOutputs3& o = run.outputs();
    EXPECT_GT(std::abs(o.points.back().y()), 0.5);  // out of the x-z plane by metres
    drift[r] = worst;
  }
  EXPECT_LE(drift[1], 1e-6);
  EXPECT_GT(drift[0] / drift[1], 8.0);
  std::printf("[ measured ] 3D sea energy balance |E - E0 - W| / m g L: %.2e (h = 0.01 s), %.2e (0.005 s)\n", drift[0],
              drift[1]);
}

// Irregular waves (JONSWAP Hs 4 m, Tp 8 s, 60 components) towards 120 deg across a current towards 30 deg, the
// top fixed: the line moves out of its plane; E - E0 - W at rk4's truncation level, and the planar core's sea
// (the same seed) yawed gives the same kinematics at every depth (Water3 vs WaterKinematics, 1e-12 of |v|).
TEST(SpatialSea, IrregularWavesAtAHeading) {
  const std::string sea = R"(space: spatial
top: {position: [0.0, 0.0, 3.0]}
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {velocity: [0.52, 0.3, 0.0]}
  waves: {type: jonswap, significant_height: 4.0, peak_period: 8.0, components: 60, seed: 5, depth: 120.0, ramp: 2.0, heading: 120.0}
)";
  Scene sc = seaScene(sea);
  sc.solver.dt = 0.005;
  Run3 run(sc);
  double worst = 0.0;
  for (int k = 0; k < 800; ++k) {
    ASSERT_TRUE(run.step()) << run.divergenceReason();
    worst = std::max(worst, std::abs(run.energyDrift()));
  }
  EXPECT_LE(worst, 1e-6);
  // Out of the current's vertical plane (normal (-0.5, 0.866)): the waves push across it.
  const Vec3 end = run.outputs().points.back();
  EXPECT_GT(std::abs(Vec2(-0.5, 0.8660254037844386).dot(end.head<2>())), 0.01);  // measured 0.036 m
  WaterSpec spec2 = sc.water;
  spec2.waves.heading = 0.0;
  spec2.current = CurrentSpec();
  const WaterKinematics planar(spec2, sc.gravity);
  Water3 w3(sc.water, Vec3(0.0, 0.0, -sc.gravity));
  const Vec3 d(std::cos(120.0 * M_PI / 180.0), std::sin(120.0 * M_PI / 180.0), 0.0);
  double err = 0.0, vmax = 0.0;
  for (double z : {-0.5, -10.0, -60.0})
    for (double s : {0.0, 37.0}) {
      const Vec3 p = s * d + Vec3(-3.0 * d.y(), 3.0 * d.x(), z);  // off the line through the origin too
      Vec3 v3, a3;
      w3.at(p, 7.3, v3, a3);
      Vec2 v2, a2;
      planar.at(Vec2(s, z), 7.3, v2, a2);
      const Vec3 expected = v2.x() * d + Vec3(0.0, 0.0, v2.y()) + sc.water.current.velocity;
      err = std::max(err, (v3 - expected).norm());
      vmax = std::max(vmax, v3.norm());
    }
  EXPECT_LE(err, 1e-12 * vmax);
  std::printf(
      "[ measured ] JONSWAP towards 120 deg in 3D: energy balance %.2e of m g L over 4 s (rk4 5 ms); "
      "Water3 vs the planar kinematics along the heading %.2e of |v|\n",
      worst, err / vmax);
}

// A line hanging in a current at heading 120 deg leans that way and starts at rest (the planar statics in the
// current's plane); a wave heading in a planar scene is refused naming the key.
TEST(SpatialSea, StaticsInACurrentAtAnyHeading) {
  const Scene s = seaScene(R"(space: spatial
environment:
  water: {}
  current: {velocity: [-0.5, 0.8660254037844386, 0.0]}
)");
  Run3 run(s);
  const Vec3 end0 = run.outputs().points.back();
  EXPECT_NEAR(std::atan2(end0.y(), end0.x()) * 180.0 / M_PI, 120.0, 1e-9);
  EXPECT_GT(Vec2(end0.x(), end0.y()).norm(), 1.0);
  for (int k = 0; k < 100; ++k) ASSERT_TRUE(run.step()) << run.divergenceReason();
  const double moved = (run.outputs().points.back() - end0).norm();
  EXPECT_LE(moved, 1e-6);  // the equilibrium holds in 3D (the builder's check, at rest, and 1 s of motion)
  std::printf(
      "[ measured ] hanging in a current at 120 deg: end %.4g m downstream, acceleration at rest %.2e m/s^2 "
      "(bound %.2e), moved %.2e m in 1 s\n",
      Vec2(end0.x(), end0.y()).norm(), run.initial().max_acceleration, run.initial().acceleration_bound, moved);

  // A heading in a planar scene is refused naming it.
  EXPECT_THROW(seaScene("environment: {water: {}, waves: {height: 1.0, period: 5.0, heading: 30.0}}\n"), SceneError);
}

// The 3D relaxation (relaxation.h) against the planar statics: the line hanging in a current towards 120 deg,
// relaxed from the still-water equilibrium (straight down, 25 m from the answer), reaches the planar statics'
// shape in the current's plane. The relaxation stops at 1 % of the builder's acceleration bound; the
// slowest mode's stiffness (ω1² L ~ g) turns that into ~1e-6 m: bound 1e-5 m.
TEST(SpatialSea, RelaxationReachesThePlanarStatics) {
  const Scene s =
      seaScene("space: spatial\nenvironment:\n  water: {}\n  current: {velocity: [-0.5, 0.8660254037844386, 0.0]}\n");
  Run3 run(s);  // the planar statics in the current's plane
  const Scene still = seaScene("space: spatial\nenvironment: {water: {}}\n");
  Run3 hang(still);
  const Vec3 top = run.initial().kin.front().A;
  const Relaxed3 r = relaxToRest(s, hang.initial().kin, top, run.initial().acceleration_bound);
  double d = 0.0;
  for (size_t i = 0; i < r.kin.size(); ++i) d = std::max(d, (r.kin[i].end() - run.initial().kin[i].end()).norm());
  EXPECT_LE(d, 1e-5);
  EXPECT_LE(r.acceleration, 0.01 * run.initial().acceleration_bound);
  std::printf(
      "[ measured ] relaxation from straight down vs the planar statics in a 120 deg current: %.2e m after "
      "%.3g s (%d steps), acceleration %.2e m/s^2\n",
      d, r.time, r.steps, r.acceleration);
}

// What the planar statics cannot solve: a profile veering from 0 deg at the surface to 90 deg at 40 m, and a
// current across a pinned line. Relaxed in 3D, both start at rest (1 s of motion) and bend the right way.
TEST(SpatialSea, VeeringAndCrossCurrentsRelaxedIn3D) {
  const Scene veer = seaScene(
      "space: spatial\nenvironment:\n  water: {}\n  current: {profile: [[0.0, 0.8, 0.0], [40.0, 0.0, 0.8]]}\n");
  const Scene cross = seaScene(
      "space: spatial\nbottom: {type: pinned, position: [30.0, 0.0, -45.0]}\n"
      "initial: {type: between_points}\nenvironment:\n  water: {}\n  current: {velocity: [0.0, 0.5, 0.0]}\n");
  for (const Scene* sc : {&veer, &cross}) {
    Run3 run(*sc);
    EXPECT_NE(run.initial().about.find("relaxed in 3D"), std::string::npos) << run.initial().about;
    EXPECT_LE(run.initial().max_acceleration, 0.01 * run.initial().acceleration_bound);
    const AlignedVector<Vec3> p0 = run.outputs().points;
    for (int k = 0; k < 100; ++k) ASSERT_TRUE(run.step()) << run.divergenceReason();
    double moved = 0.0;
    for (size_t i = 0; i < p0.size(); ++i) moved = std::max(moved, (run.outputs().points[i] - p0[i]).norm());
    EXPECT_LE(moved, 1e-6);
    const Vec3 mid = p0[p0.size() / 2], end = p0.back();
    if (sc == &veer) {  // the deep part drifts towards +y, the shallow towards +x
      EXPECT_GT(end.y(), 1.0);
      EXPECT_GT(end.x(), 0.1);
    } else {  // bowed downstream (+y), the ends on their pins
      EXPECT_GT(mid.y(), 0.5);
      EXPECT_LE((end - Vec3(30.0, 0.0, -45.0)).norm(), 1e-6);
    }
    std::printf("[ measured ] %s: %s; mid (%.3g, %.3g, %.3g) m, end (%.3g, %.3g, %.3g) m; moved %.2e m in 1 s\n",
                sc == &veer ? "veering profile" : "pinned, current across", run.initial().about.c_str(), mid.x(),
                mid.y(), mid.z(), end.x(), end.y(), end.z(), moved);
  }
}

// A displaced end (held 20 m along x by a horizontal force, initial.end_force: hold) in a current with a part
// across that plane: Newton in 3D from the planar statics, the force the multiplier of the end's horizontal
// position. Checks: the builder's rest check with that force as a dead load, the end where asked, still for 1 s,
// bowed downstream and held upstream. Against the planar statics: with a cross part of 1e-7 of the current the
// problem is the planar one perturbed, so the Newton result's in-plane coordinates and end force are the planar
// path's (the change is second order; the two solvers' tolerances leave ~1e-10 m) and its out-of-plane ones
// ~1e-7 of the full cross current's.
TEST(SpatialSea, DisplacedEndInACrossCurrent) {
  const auto scene = [](double vy) {
    char v[40];
    std::snprintf(v, sizeof(v), "%.17g", vy);
    return seaScene(
        "space: spatial\ninitial: {type: displaced, end_offset: [20.0, 0.0], end_force: hold}\n"
        "environment:\n  water: {}\n  current: {velocity: [0.3, " +
        std::string(v) + ", 0.0]}\n");
  };
  Run3 run(scene(0.5));
  const InitialState3& init = run.initial();
  EXPECT_NE(init.about.find("Newton in 3D"), std::string::npos) << init.about;
  EXPECT_LE(init.max_acceleration, init.acceleration_bound);
  const AlignedVector<Vec3> p0 = run.outputs().points;
  const Vec3 mid = p0[p0.size() / 2], end = p0.back();
  EXPECT_LE((end.head<2>() - Vec2(20.0, 0.0)).norm(), 1e-9);
  EXPECT_EQ(init.end_force.z(), 0.0);
  EXPECT_LT(init.end_force.y(), 0.0);  // holding the end against the current
  EXPECT_GT(mid.y(), 0.5);             // bowed downstream
  double moved = 0.0;
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(run.step()) << run.divergenceReason();
    for (size_t i = 0; i < p0.size(); ++i) moved = std::max(moved, (run.outputs().points[i] - p0[i]).norm());
  }
  EXPECT_LE(moved, 1e-6);
  // A cross part of 5e-8 m/s (Newton) against none (the planar statics rotated).
  Run3 planar(scene(0.0)), nudged(scene(5e-8));
  EXPECT_EQ(planar.initial().about.find("Newton"), std::string::npos) << planar.initial().about;
  EXPECT_NE(nudged.initial().about.find("Newton"), std::string::npos) << nudged.initial().about;
  double in_plane = 0.0, across = 0.0;
  const AlignedVector<Vec3>& a = planar.outputs().points;
  const AlignedVector<Vec3>& b = nudged.outputs().points;
  for (size_t i = 0; i < a.size(); ++i) {
    in_plane = std::max({in_plane, std::abs(a[i].x() - b[i].x()), std::abs(a[i].z() - b[i].z())});
    across = std::max(across, std::abs(b[i].y()));
  }
  // The force's in-plane part (x; z is 0): its y part is first order in the cross current, as the positions'.
  const double dF =
      std::abs(planar.initial().end_force.x() - nudged.initial().end_force.x()) / planar.initial().end_force.norm();
  EXPECT_LE(in_plane, 1e-9);
  EXPECT_LE(dF, 1e-9);
  EXPECT_LE(across, 1e-7 * std::abs(mid.y()) * 10.0);  // linear in the cross current, with room
  std::printf(
      "[ measured ] displaced end in a current with 0.5 m/s across its plane: %s; acceleration at rest %.2e "
      "m/s^2 (bound %.2e); mid (%.3g, %.3g, %.3g) m; moved %.2e m in 1 s. Cross part 5e-8 m/s vs the planar "
      "statics: in-plane %.2e m, end force (x) %.2e relative, across %.2e m\n",
      init.about.c_str(), init.max_acceleration, init.acceleration_bound, mid.x(), mid.y(), mid.z(), moved, in_plane,
      dF, across);
}

// No allocation per step with every sea term on (waves, a sheared current, drag, buoyancy, Froude-Krylov, added
// mass across and along, the seabed with friction under the end).
TEST(SpatialSea, NoAllocationPerStep) {
  const std::string sea = R"(space: spatial
top:
  position: [0.0, 0.0, 5.0]
  motion: {type: sinusoid, amplitude: [1.0, 0.5, 0.3], period: 5.0}
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {profile: [[0.0, 0.6, 0.2], [40.0, 0.3, 0.1]]}
  waves: {height: 2.0, period: 6.0, heading: 45.0}
seabed: {level: -52.0, stiffness_normal: 1.0e5, damping_normal: 1.0e3, friction_axial: 0.3, friction_lateral: 0.6}
)";
  for (const char* integrator : {"rk4", "midpoint"}) {
    Scene sc = seaScene(sea, {"hydrodynamics.inertia_coefficient=2", "hydrodynamics.axial_added_mass=0.5"});
    sc.solver.integrator = *parseChoice<IntegratorKind>(integrator);
    Run3 run(sc);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(run.step()) << run.divergenceReason();
    const long before = g_allocations.load();
    double sink = 0.0;
    for (int k = 0; k < 20; ++k) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      sink += run.outputs().top_tension + run.energyDrift();
    }
    EXPECT_EQ(g_allocations.load() - before, 0) << integrator;
    EXPECT_TRUE(std::isfinite(sink));
    EXPECT_LT(run.outputs().points.back().z(), -52.0) << "the end is not on the seabed";
  }
}

}  // namespace
}  // namespace riser_sim
