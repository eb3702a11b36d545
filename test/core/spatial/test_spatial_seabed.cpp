// The seabed in 3D (spatial/forces/seabed.h):
// - the normal spring against its energy, the dampers' and the friction's power (FD, random states half below
//   the level, tilted gravity);
// - Coulomb limits: the law on a line sliding along and across itself (μ_a N, μ_l N); a line lying on the
//   seabed dragged by both ends at 0.5 m/s along itself and sideways: the holders feel μ N (the smoothing's
//   v / sqrt(v² + v_s²) = 1 - 2e-4);
// - a planar scene with a seabed (touchdown, a moving top) yawed into 3D gives the planar core's result rotated;
// - the friction keys are refused in a planar scene, the anchored springs in a 3D one, naming the key;
// - a straight start inside the seabed is refused in both engines.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/simulator.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_force_checks.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

TEST(SpatialSeabed, AgainstItsEnergyAndPower) {
  spatial_test::LineSpec ls = spatial_test::flexibleLine();
  ls.segments = 5;
  auto m = spatial_test::spatialModel(ls, Vec3(1.2, -0.7, -9.5));
  SeabedSpec spec;
  spec.enabled = true;
  spec.level = 4.0;  // along up = -g/|g|: the random states span heights ~ -1 .. 10, about half below
  spec.stiffness_normal = 1e5;
  spec.damping_normal = 300.0;
  spec.damping_tangential = 50.0;
  spec.friction_axial = 0.4;
  spec.friction_lateral = 0.9;
  spec.friction_velocity = 0.05;
  const spatial::Seabed bed(spec, m->gravity());
  spatial_test::checkGradient(bed, *m);
  spatial_test::checkPower(bed, *m);
  // The check has teeth: points are in contact on those states.
  std::mt19937 rng(7);
  const NaturalFormulation f(*m, 50.0);
  Kinematics3 kin(m->bodies());
  f.kinematics(spatial_test::randomState(*m, rng, false), kin);
  EXPECT_GE(bed.contacts(*m, kin), 2);
}

// The rate Jacobian C = -∂Q/∂q' (the normal damper, the tangential damper, the friction's rate dependence and
// its coupling through the normal force's damper) against central differences of Q in each rate, on states
// sliding in every direction (μ_a ≠ μ_l: C is not symmetric). Q is smooth in the rates away from F_n = 0, which
// random states avoid: bound 1e-6 of the largest entry (measured ~1e-9: the differences' truncation).
TEST(SpatialSeabed, RateJacobianAgainstDifferences) {
  spatial_test::LineSpec ls = spatial_test::flexibleLine();
  ls.segments = 5;
  auto m = spatial_test::spatialModel(ls, Vec3(1.2, -0.7, -9.5));
  SeabedSpec spec;
  spec.enabled = true;
  spec.level = 4.0;
  spec.stiffness_normal = 1e5;
  spec.damping_normal = 300.0;
  spec.damping_tangential = 50.0;
  spec.friction_axial = 0.4;
  spec.friction_lateral = 0.9;
  spec.friction_velocity = 0.05;
  const spatial::Seabed bed(spec, m->gravity());
  const NaturalFormulation f(*m, 50.0);
  std::mt19937 rng(5);
  double worst = 0.0;
  for (int trial = 0; trial < 4; ++trial) {
    const VecX y = spatial_test::randomState(*m, rng, true);
    Kinematics3 kin(m->bodies());
    f.kinematics(y, kin);
    EXPECT_GT(bed.contacts(*m, kin), 0);
    const double err = spatial_test::rateJacobianError(bed, *m, y, 0.0);
    EXPECT_LT(err, 1e-6) << "trial " << trial;
    worst = std::max(worst, err);
  }
  std::printf("[ measured ] seabed rate Jacobian vs differences: %.2e of the largest entry\n", worst);
}

// The friction law on a line lying flat and sliding rigidly at v (one state, no run): along the line the
// contact points feel μ_a N, across it μ_l N, times v / sqrt(v² + v_s²). Round-off bound.
TEST(SpatialSeabed, FrictionAlongAndAcrossTheLine) {
  spatial_test::LineSpec ls = spatial_test::flexibleLine();
  ls.segments = 8;
  auto m = spatial_test::spatialModel(ls, Vec3(0.0, 0.0, -9.81));
  SeabedSpec spec;
  spec.enabled = true;
  spec.level = 0.0;
  spec.stiffness_normal = 1e5;
  spec.friction_axial = 0.3;
  spec.friction_lateral = 0.9;
  spec.friction_velocity = 0.02;
  const spatial::Seabed bed(spec, m->gravity());
  const Vec3 dir = Vec3(std::cos(0.4), std::sin(0.4), 0.0);  // the line's heading
  for (const bool across : {false, true}) {
    const double v = 0.3;
    const Vec3 vel = v * (across ? Vec3(Vec3::UnitZ().cross(dir)) : dir);
    std::vector<Vec3> dirs(m->bodies(), dir);
    const Kinematics3 kin = rigidChain(m->line(), Vec3(0.0, 0.0, -1e-3), dirs, vel, Vec3::Zero());  // 1 mm in
    VecX Q = VecX::Zero(m->dofs());
    bed.addForces(*m, kin, 0.0, Q);
    Vec3 F = Vec3::Zero();
    for (int i = 0; i < m->bodies(); ++i) F += Q.segment<3>(kDofPerBody3 * i + kA);
    const double N = spec.stiffness_normal * 1e-3 * (m->bodies() + 1);
    const double mu = across ? spec.friction_lateral : spec.friction_axial;
    const Vec3 expected = -mu * N * v / std::hypot(v, spec.friction_velocity) * vel.normalized();
    EXPECT_LE((F.head<2>() - expected.head<2>()).norm(), 1e-12 * N) << (across ? "across" : "along");
    EXPECT_NEAR(F.z(), N, 1e-12 * N);
  }
}

// A 20 m line lying straight on a seabed (C_n = 1e6 N/m per point), both ends pinned at the level and driven at
// the same velocity (ramped to 0.5 m/s over 1 s), midpoint 2 ms: along the line (μ_a = 0.5, μ_l = 1) and across
// it (isotropic μ = 1: once the bowed line's points all slide at v, the law sums to μ N whatever the bow). Over
// the 4th second the holders feel μ N v / sqrt(v² + v_s²), N = W + F_z the seabed's share of the weight (F_z:
// what the pins carry). The bow's lateral mode is damped by a high axial damping; what is left of it over the
// window was 1.4e-4 (6.9e-4 over the 8th second): bound 2e-3. Along: 6e-14.
TEST(SpatialSeabed, DraggedAlongAndSideways) {
  const double v = 0.5, vs = 0.01, W = 50.0 * 20.0 * 9.81;
  for (const bool across : {false, true}) {
    const std::string vel = across ? "[0.0, 0.5, 0.0]" : "[0.5, 0.0, 0.0]";
    const std::string knots = "[[0.0, [0.0, 0.0, 0.0]], [1.0, " + vel + "], [100.0, " + vel + "]]";
    const double mu_a = across ? 1.0 : 0.5, mu_l = 1.0;
    const Scene s = loadSceneText(
        R"(space: spatial
line: {length: 20.0, elements: 10, EA: 1.0e7, EI: 1.0e3, mass_per_length: 50.0, axial_damping: 1.0e6, bending_damping: 10.0}
top: {position: [0.0, 0.0, 0.0], motion: {type: velocity_profile, knots: )" +
            knots + R"(}}
bottom: {type: pinned, position: [20.0, 0.0, 0.0], motion: {type: velocity_profile, knots: )" +
            knots + R"(}}
initial: {type: straight, angle: 0.0}
seabed: {level: 0.0, stiffness_normal: 1.0e6, damping_normal: 2.0e3, friction_velocity: 0.01}
solver: {integrator: midpoint, dt: 0.002}
)",
        "test_spatial_seabed",
        {"seabed.friction_axial=" + std::to_string(mu_a), "seabed.friction_lateral=" + std::to_string(mu_l)});
    Run3 run(s);
    Vec3 sum = Vec3::Zero();
    int samples = 0;
    for (int k = 1; k <= 2000; ++k) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      if (k <= 1500) continue;
      const LineOutputs3& o = run.outputs();
      sum += o.top_force + o.bottom_force;
      ++samples;
    }
    const Vec3 F = sum / samples;
    const double N = W + F.z();
    const double expected = (across ? mu_l : mu_a) * N * v / std::sqrt(v * v + vs * vs);
    const double back = -(across ? F.y() : F.x());  // the line pulls the holders back
    EXPECT_NEAR(back, expected, 2e-3 * expected);
    EXPECT_GT(N, 0.9 * W);  // the seabed carries the line
    std::printf(
        "[ measured ] dragged %s at 0.5 m/s: holders' force %.6g N against mu N v/sqrt(v^2+vs^2) = %.6g N "
        "(%.2e); the seabed carries %.4g of W\n",
        across ? "sideways" : "along", back, expected, std::abs(back / expected - 1.0), N / W);
  }
}

Mat3 yaw(double deg) { return Eigen::AngleAxisd(deg * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix(); }

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof(b), "%.17g", v);
  return b;
}

// A 60 m line from z = 0 touching down on a seabed at -50 m (normal spring and damping, tangential damping:
// the planar law without anchored springs), the top swaying along x; yawed by 25 deg into 3D. rk4 at 1e-3 and
// 5e-4 s, 3 s: the difference is the two schemes' truncation (fourth order), below 1e-9 m at 5e-4 s.
TEST(SpatialSeabed, YawedPlanarTouchdownMatchesThePlanarCore) {
  const char* line =
      R"(line: {length: 60.0, elements: 12, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0, axial_damping: 1.0e4, bending_damping: 100.0}
seabed: {level: -50.0, stiffness_normal: 2.0e5, damping_normal: 2.0e3, damping_tangential: 500.0}
initial: {type: displaced, end_dx: 20.0, end_force: hold}
solver: {integrator: rk4}
)";
  const Mat3 R = yaw(25.0);
  const Vec3 amp = R * Vec3(2.0, 0.0, 0.5);
  const double c = std::cos(25.0 * M_PI / 180.0), s = std::sin(25.0 * M_PI / 180.0);
  const std::string planar =
      "top: {position: [0.0, 0.0], motion: {type: sinusoid, amplitude: [2.0, 0.5], period: 4.0}}\n";
  const std::string spatial3 =
      "space: spatial\ntop: {position: [0.0, 0.0, 0.0], motion: {type: sinusoid, amplitude: [" + num(amp.x()) + ", " +
      num(amp.y()) + ", " + num(amp.z()) + "], period: 4.0}}\n";
  double worst[2] = {0.0, 0.0};
  int touching = 0;
  for (int r = 0; r < 2; ++r) {
    const std::vector<std::string> dt = {r == 0 ? "solver.dt=0.001" : "solver.dt=0.0005"};
    riser_sim::Run p = buildRun(loadSceneText(std::string(line) + planar, "planar", dt));
    std::string text = std::string(line) + spatial3;
    text.replace(text.find("end_dx: 20.0"), 12, "end_offset: [" + num(20.0 * c) + ", " + num(20.0 * s) + "]");
    const Scene s3 = loadSceneText(text, "spatial", dt);
    Run3 run(s3);
    touching = 0;
    for (const Vec3& q : run.outputs().points) touching += q.z() < -50.0;
    Kinematics kin2(p.model->bodies());
    const long steps = std::lround(3.0 / run.dt());
    for (long k = 0; k <= steps; ++k) {
      if (k > 0) {
        ASSERT_TRUE(p.sim->step());
        ASSERT_TRUE(run.step()) << run.divergenceReason();
      }
      if (k % 100) continue;
      p.sim->kinematics(kin2);
      const LineOutputs3& o = run.outputs();
      for (int i = 0; i < p.model->bodies(); ++i)
        worst[r] = std::max(worst[r], (o.points[i] - planarPoint(kin2[i].A, R)).norm());
    }
  }
  EXPECT_GE(touching, 2);  // the seabed carries part of the line
  EXPECT_LE(worst[1], 1e-9);
  EXPECT_GT(worst[0] / worst[1], 8.0);
  std::printf(
      "[ measured ] planar touchdown yawed 25 deg vs the planar core, 3 s: %.2e m (h = 1e-3 s), %.2e m "
      "(5e-4 s); %d points on the seabed at rest\n",
      worst[0], worst[1], touching);
}

TEST(SpatialSeabed, KeysRefusedWhereTheyDoNotApply) {
  const std::string base = "line: {length: 60.0, elements: 12, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0}\n";
  try {
    loadSceneText(base + "seabed: {level: -50.0, stiffness_normal: 1.0e5, friction_axial: 0.3}\n", "planar");
    ADD_FAILURE() << "friction accepted in a planar scene";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("seabed.friction_axial"), std::string::npos) << e.what();
  }
  try {
    loadSceneText(
        base + "space: spatial\nseabed: {level: -50.0, stiffness_normal: 1.0e5, stiffness_tangential: 1.0e5}\n",
        "spatial");
    ADD_FAILURE() << "anchored springs accepted in a 3D scene";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("seabed.stiffness_tangential"), std::string::npos) << e.what();
  }
}

// A straight start is no equilibrium, but nothing of it may start inside the seabed, in either engine: the same
// scene is refused naming the seabed planar and in 3D (level and sloped), and runs once it clears the plane.
TEST(SpatialSeabed, StraightStartInsideTheSeabedRefusedInBothEngines) {
  const std::string base =
      "line: {length: 60.0, elements: 12, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0, outer_diameter: 0.3}\n"
      "environment: {water: {density: 1025.0, surface: 0.0}}\n"
      "initial: {type: straight, angle: -90.0}\n";
  const auto refusal = [](const Scene& scene) -> std::string {
    try {
      if (scene.space == SpaceKind::kSpatial)
        solveInitialState3(scene, scene.top.position);
      else
        solveInitialState(scene, *buildModel(scene), inPlane(scene.top.position));
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  for (const char* space : {"planar", "spatial"}) {
    const std::string sp = std::string("space: ") + space + "\n";
    const Scene deep = loadSceneText(base + sp + "seabed: {level: -40.0, stiffness_normal: 1.0e5}\n", space);
    const std::string why = refusal(deep);
    EXPECT_NE(why.find("below the seabed"), std::string::npos) << space << ": " << why;
    EXPECT_NE(why.find("rfe"), std::string::npos) << space << ": " << why;
    const Scene clear = loadSceneText(base + sp + "seabed: {level: -61.0, stiffness_normal: 1.0e5}\n", space);
    EXPECT_EQ(refusal(clear), "") << space;
  }
  // 3D, sloped: the plane rises along +x through level -61 on the origin's vertical; at the line's x = 30 m a 5°
  // slope lifts it to -61 + 30 tan 5° = -58.4 m, above the line's lower end at -60 m.
  const Scene sloped = loadSceneText(base +
                                         "space: spatial\ntop: {position: [30.0, 0.0, 0.0]}\n"
                                         "seabed: {level: -61.0, stiffness_normal: 1.0e5, slope: 5.0}\n",
                                     "sloped");
  EXPECT_NE(refusal(sloped).find("below the seabed"), std::string::npos) << refusal(sloped);
}

}  // namespace
}  // namespace riser_sim
