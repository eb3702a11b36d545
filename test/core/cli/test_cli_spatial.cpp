// space: spatial end to end: the shipped planar scenes through the 3D path (their comparison with the planar
// CLI: test_cli_shipped_scenes), frame invariance of a yawed scene, the 3D statics (rotated planar equilibria
// checked in the 3D model), bad input naming the key, the shipped 3D example.
#include <gtest/gtest.h>

#include "cli_test_util.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

using namespace cli_test;
using riser_sim::Scene;
using riser_sim::spatial::Run3;
using Vec3 = Eigen::Vector3d;

namespace {

// A function, not a namespace-scope string built from kScenes: clang-14 (the sanitizer build) initialised such a
// string before the inline kScenes it reads.
const std::string& swingScene() {
  static const std::string path = kScenes + "spatial_swing.yaml";
  return path;
}

Eigen::Matrix3d yaw(double deg) { return Eigen::AngleAxisd(deg * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix(); }

std::string vec(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "[%.17g,%.17g,%.17g]", v.x(), v.y(), v.z());
  return buf;
}

// A shipped scene without its initial.end_dx line (so that initial.end_offset can be set), with overrides.
Scene withoutEndDx(const std::string& file, const std::vector<std::string>& sets) {
  std::string text = readFile(kScenes + file);
  const size_t at = text.find("  end_dx:");
  if (at != std::string::npos) text.erase(at, text.find('\n', at) - at + 1);
  return riser_sim::loadSceneText(text, file, sets);
}

// Steps a spatial run for `seconds` and returns its outputs.
riser_sim::spatial::LineOutputs3 runFor(Run3& run, double seconds) {
  const long steps = std::lround(seconds / run.dt());
  for (long k = 0; k < steps; ++k) EXPECT_TRUE(run.step()) << run.divergenceReason();
  return run.outputs();
}

}  // namespace

// Every shipped planar scene with --set space=spatial for 0.02 s: its 3D statics and first steps (the run the
// sanitizer build checks; test_cli_shipped_scenes compares 0.5 s of it with the planar CLI in Release): exit 0
// with status ok and the line in the plane y = 0 (the 3D core keeps a planar scene in its plane to 5e-13 m,
// docs/spatial.md), or the refusal naming the section the 3D core lacks.
TEST(CliSpatial, PlanarScenesRunThroughTheSpatialPath) {
  int ran = 0, refused = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string text = readFile(entry.path().string());
    if (text.find("\nspace: spatial") != std::string::npos) continue;  // not a planar scene
    SCOPED_TRACE(entry.path().string());
    const CliRun r =
        runCli("--scene " + entry.path().string() + " --duration 0.02 --summary --quiet --set space=spatial");
    if (r.code == 2) {
      ++refused;
      EXPECT_NE(r.err.find("not available with space: spatial yet"), std::string::npos) << r.err;
      continue;
    }
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = summary(r);
    EXPECT_EQ(j["status"], "ok") << r.out;
    EXPECT_EQ(j["space"], "spatial");
    EXPECT_NEAR(num(j, "y_end"), 0.0, 1e-12);
    ++ran;
  }
  EXPECT_GE(ran, 4);      // hanging_chain, paper_table1, demo_riser, paper_riser_500m
  EXPECT_GE(refused, 1);  // paper_jlay_170m (internal flow, anchored seabed springs)
}

// The same scene yawed by 30 deg about z (top position and amplitude, initial heading / end offset rotated)
// gives the rotated result: 0.5 s of a moving top, in process (the CSV's 9 digits are too coarse).
TEST(CliSpatial, YawedSceneGivesTheRotatedResult) {
  const Eigen::Matrix3d R = yaw(30.0);
  struct Case {
    std::string file;
    std::vector<std::string> sets;
    Vec3 position, amplitude;
    Eigen::Vector2d offset;  // initial.end_offset (displaced) or zero
  };
  const std::vector<Case> cases = {
      {"hanging_chain.yaml", {"run.duration=0.5"}, Vec3(2.0, 0.0, 1.0), Vec3(0.5, 0.0, 0.2), Eigen::Vector2d::Zero()},
      {"paper_table1.yaml",
       {"run.duration=0.5"},
       Vec3(1.0, 0.0, -2.0),
       Vec3(0.3, 0.0, 0.1),
       Eigen::Vector2d(-50.0, 0.0)},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const auto scene = [&](const Eigen::Matrix3d& Q, double heading) {
      std::vector<std::string> sets = c.sets;
      sets.push_back("space=spatial");
      sets.push_back("top.position=" + vec(Q * c.position));
      sets.push_back("top.motion.type=sinusoid");
      sets.push_back("top.motion.period=1.5");
      sets.push_back("top.motion.amplitude=" + vec(Q * c.amplitude));
      if (c.offset.norm() > 0.0) {
        const Vec3 o = Q * Vec3(c.offset.x(), c.offset.y(), 0.0);
        char buf[96];
        std::snprintf(buf, sizeof(buf), "initial.end_offset=[%.17g,%.17g]", o.x(), o.y());
        sets.push_back(buf);
      } else {
        sets.push_back("initial.heading=" + std::to_string(heading));
      }
      return withoutEndDx(c.file, sets);
    };
    Scene s0, s1;
    ASSERT_NO_THROW(s0 = scene(Eigen::Matrix3d::Identity(), 0.0));
    ASSERT_NO_THROW(s1 = scene(R, 30.0));
    Run3 r0(s0), r1(s1);
    const auto o0 = runFor(r0, 0.5);
    const auto o1 = runFor(r1, 0.5);
    double dp = 0.0, df = 0.0;
    for (size_t i = 0; i < o0.points.size(); ++i) dp = std::max(dp, (o1.points[i] - R * o0.points[i]).norm());
    df = (o1.top_force - R * o0.top_force).norm();
    const double L = s0.length;
    EXPECT_LE(dp, 1e-9 * L);
    EXPECT_LE(df, 1e-9 * o0.top_tension);
    EXPECT_NEAR(o1.max_tension, o0.max_tension, 1e-9 * o0.max_tension);
    std::printf("[ measured ] %s yawed 30 deg: positions %.3g m (L = %g m), top force %.3g of the tension\n",
                c.file.c_str(), dp, L, df / o0.top_tension);
  }
}

// initial.type displaced with the end along (1, 1)/sqrt(2): the planar statics in that vertical plane,
// rotated. The 3D model's accelerations at rest are within the builder's bound, the end force is the 2D
// one (end_dx = 50 m) rotated, and held (end_force: hold) the line stays at rest in 3D.
TEST(CliSpatial, DisplacedStaticsAlongTheDiagonal) {
  const double a = 50.0 / std::sqrt(2.0);
  char off[96];
  std::snprintf(off, sizeof(off), "initial.end_offset=[%.17g,%.17g]", a, a);
  const Scene s3 = withoutEndDx("paper_table1.yaml", {"space=spatial", off, "initial.end_force=hold"});
  const Scene s2 = riser_sim::loadSceneFile(kScenes + "paper_table1.yaml", {"initial.end_dx=50"});
  Run3 run(s3);
  const auto& init = run.initial();
  EXPECT_TRUE(init.equilibrium);
  EXPECT_LE(init.max_acceleration, init.acceleration_bound);
  const riser_sim::Run planar = riser_sim::buildRun(s2);
  const Eigen::Vector2d f2 = planar.initial.end_force;
  const Vec3 expected(f2.x() / std::sqrt(2.0), f2.x() / std::sqrt(2.0), f2.y());
  EXPECT_LE((init.end_force - expected).norm(), 1e-9 * f2.norm());
  EXPECT_NEAR(init.plane_direction.x(), 1.0 / std::sqrt(2.0), 1e-15);
  // The end where asked, and the rotated 2D end.
  const Vec3 end = init.kin.back().end();
  EXPECT_NEAR(end.x(), a, 1e-9 * 50.0);
  EXPECT_NEAR(end.y(), a, 1e-9 * 50.0);
  const Eigen::Vector2d end2 = planar.initial.kin.back().end();
  EXPECT_NEAR(end.z(), end2.y(), 1e-9 * 100.0);
  // The check has teeth: without the end force (what initial.end_force: release does at t = 0) the same
  // state accelerates, by ~ F / m_end at the end.
  int where = -1;
  const Vec3 top = init.kin.front().A;
  const double released = riser_sim::spatial::restAcceleration(s3, init.kin, Vec3::Zero(), top, where);
  EXPECT_GT(released, 1e4 * init.acceleration_bound);
  EXPECT_NEAR(released, f2.norm() / s3.end_mass, 0.1 * f2.norm() / s3.end_mass);  // measured 6.69 of 6.74 m/s^2
  EXPECT_EQ(where, s3.elements);
  const Vec3 start = run.outputs().points.back();
  const auto later = runFor(run, 0.1);
  const double moved = (later.points.back() - start).norm();
  EXPECT_LE(moved, 1e-6);
  std::printf(
      "[ measured ] diagonal displaced: acceleration at rest %.3g m/s^2 (bound %.3g; %.3g without the end "
      "force), end force |F3 - R F2| %.3g N of %.6g N, end moved %.3g m in 0.1 s held\n",
      init.max_acceleration, init.acceleration_bound, released, (init.end_force - expected).norm(), f2.norm(), moved);
}

// between_points anywhere: the anchor off both axes, pinned; the run stays at rest and the anchor force
// balances the weight with the top force.
TEST(CliSpatial, BetweenPointsAnywhere) {
  const Scene s = riser_sim::loadSceneFile(
      kScenes + "paper_table1.yaml", {"space=spatial", "top.position=[3,-4,2]", "bottom.type=pinned",
                                      "bottom.position=[40,35,-70]", "initial.type=between_points", "line.end_mass=0"});
  Run3 run(s);
  EXPECT_LE(run.initial().max_acceleration, run.initial().acceleration_bound);
  const auto o0 = run.outputs();
  // The statics' end condition holds the end within initial.tolerance x line.length (1e-7 m) of the anchor.
  const double gap = (o0.points.back() - Vec3(40, 35, -70)).norm();
  EXPECT_LE(gap, 1e-9 * s.length);
  const double W = run.model().line().totalMass() * s.gravity;
  // The line's weight is carried by its two ends: the forces on the holders sum to the weight, downwards.
  EXPECT_LE((o0.top_force + o0.bottom_force - Vec3(0, 0, -W)).norm(), 1e-6 * W);
  const auto o1 = runFor(run, 0.1);
  EXPECT_LE((o1.points[s.elements / 2] - o0.points[s.elements / 2]).norm(), 1e-6);
  std::printf(
      "[ measured ] between points: end %.3g m from bottom.position, acceleration at rest %.3g m/s^2 (bound "
      "%.3g), |F_top + F_bottom - W| %.3g of W\n",
      gap, run.initial().max_acceleration, run.initial().acceleration_bound,
      (o0.top_force + o0.bottom_force - Vec3(0, 0, -W)).norm() / W);
}

TEST(CliSpatial, BadInputNamesTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set top.position=[1,2,3]", "top.position[1]: y = 2 points out of the vertical x-z plane"},
      {"--set top.position=[1,2,3]", "set space: spatial"},
      {"--set bottom.position=[1,0.5,-3]", "bottom.position[1]: y = 0.5"},
      {"--set initial.end_offset=[1,2]", "initial.end_offset[1]: dy = 2"},
      {"--set initial.heading=30", "initial.heading: turns the straight line out of"},
      {"--set top.motion.phase=[0,1,0]", "top.motion.phase: a phase per axis"},
      {"--set space=spatial --set top.position=[1,2,3,4]", "top.position: expected [x, z]"},
      {"--set top.position=[1,2,3,4]", "top.position: expected [x, z]"},
      {"--set space=spatial --set top.position=[.nan,0,0]", "top.position[0]: must be a finite number"},
      {"--set space=spatial --set top.motion.amplitude=[0,.inf,0]", "top.motion.amplitude[1]: must be a finite"},
      {"--set space=cubic", "space: unknown value 'cubic' (accepted: planar, spatial)"},
      {"--set space=spatial --set solver.integrator=midpoint --set solver.jacobian=dense --set line.elements=600",
       "line.elements: must be <= 570 with a dense midpoint Jacobian"},
      {"--set space=spatial --set solver.formulation=recursive", "solver.formulation: 'recursive' is planar"},
      {"--set space=spatial --set initial.type=displaced --set initial.end_offset=[8,8]",
       "initial.end_offset: must be shorter than line.length"},
      {"--set space=spatial --set initial.type=displaced --set initial.end_offset=[3,3] --set initial.end_dx=1",
       "initial.end_offset: give either"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet " + c.first);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  // A 3-vector with y = 0 keeps a planar scene planar: the same run as its 2-vector.
  const CliRun a = runCli("--scene " + kChain + " --duration 0.05 --summary --quiet --set top.position=[1,0,2]");
  const CliRun b = runCli("--scene " + kChain + " --duration 0.05 --summary --quiet --set top.position=[1,2]");
  ASSERT_EQ(a.code, 0) << a.err;
  auto ja = summary(a), jb = summary(b);
  EXPECT_EQ(ja["x_end"], jb["x_end"]);
  EXPECT_EQ(ja["y_end"], jb["y_end"]);
  EXPECT_EQ(ja["tension_top"], jb["tension_top"]);
}

// The top motions in 3D, from the CSV: a velocity profile with 3D knots (position integrated exactly: a
// ramp to (1, 0.5, -0.2) m/s over 1 s covers half of it, then 0.5 s at that velocity), and a horizontal
// circle from a phase per axis (x = R cos wt, y = R cos(wt - pi/2): |p_h| = R at every row).
TEST(CliSpatial, TopMotionsIn3D) {
  const std::string csv = tempPath("motion3.csv");
  const std::string base = "--scene " + swingScene() + " --quiet --output-dt 0.1 --csv " + csv;
  {
    const CliRun r = runCli(base +
                            " --duration 1.5 --set top.motion.type=velocity_profile "
                            "--set 'top.motion.knots=[[0,[0,0,0]],[1,[1,0.5,-0.2]]]'");
    ASSERT_EQ(r.code, 0) << r.err;
    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    ASSERT_EQ(rows.size(), 16u);
    EXPECT_NEAR(rows.back()[1], 0.5 * 1.0 + 0.5 * 1.0, 1e-9);
    EXPECT_NEAR(rows.back()[2], 0.5 * 0.5 + 0.5 * 0.5, 1e-9);
    EXPECT_NEAR(rows.back()[3], 0.5 * -0.2 + 0.5 * -0.2, 1e-9);
  }
  {
    const CliRun r = runCli(base +
                            " --duration 2 --set 'top.motion.amplitude=[2,2,0]' "
                            "--set 'top.motion.phase=[0,-1.5707963267948966,0]'");
    ASSERT_EQ(r.code, 0) << r.err;
    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    ASSERT_EQ(rows.size(), 21u);
    // x_top, y_top are A_0 of the state: the circle starts with v_y = R w while the line is at rest, and
    // the Baumgarte terms (w_c = 50 rad/s, critically damped) pull A_0 onto it: 3.3e-4 m off at t = 0.1 s,
    // 1.3e-7 m at 0.3 s (measured); from 0.5 s on it is on the circle.
    for (const auto& row : rows) {
      if (row[0] >= 0.5) {
        EXPECT_NEAR(std::hypot(row[1], row[2]), 2.0, 1e-8) << "t = " << row[0];
      }
    }
    EXPECT_NEAR(rows[20][1], -2.0, 1e-8);  // t = 2 s, half the 4 s period: x = R cos(pi)
    EXPECT_NEAR(rows[10][2], 2.0, 1e-8);   // t = 1 s, a quarter: y = R sin(pi/2)
  }
  std::filesystem::remove(csv);
}

// The planar builder never runs a 3D scene (it would drop y): it refuses naming the key.
TEST(CliSpatial, PlanarBuilderRefusesSpatialScenes) {
  const Scene s = riser_sim::loadSceneFile(kChain, {"space=spatial", "top.position=[0,1,0]"});
  try {
    riser_sim::buildRun(s);
    ADD_FAILURE() << "buildRun accepted a spatial scene";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("space: ", 0), 0u) << e.what();
  }
}

// The shipped 3D example: status ok, the 3D CSV columns, a motion out of every vertical plane, and the
// energy balance |E - E0 - W| within 1e-3 of m g L (docs/spatial.md).
TEST(CliSpatial, ExampleSceneRuns) {
  const std::string csv = tempPath("swing.csv");
  const CliRun r = runCli("--scene " + swingScene() + " --summary --csv " + csv + " --probe-rfe 10");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("largest acceleration at rest"), std::string::npos) << r.err;
  auto j = summary(r);
  EXPECT_EQ(j["status"], "ok") << r.out;
#if !defined(RISER_SIM_ASAN)  // "well under a second": 0.1 s measured in Release (2.5 s under ASan)
  EXPECT_LT(num(j, "wall_s"), 1.0);
#endif
  std::string header;
  const auto rows = csvRows(readFile(csv), header);
  EXPECT_EQ(header,
            "t,x_top,y_top,z_top,x_end,y_end,z_end,top_fx,top_fy,top_fz,bottom_fx,bottom_fy,bottom_fz,top_mx,top_my,"
            "top_mz,bottom_mx,bottom_my,bottom_mz,tension_top,tension_max,energy,work,energy_drift,constraint_error,"
            "x_rfe10,y_rfe10,z_rfe10,tension_rfe10");
  ASSERT_EQ(rows.size(), 51u);  // 5 s every 0.1 s
  const double E0 = rows.front()[21], mgl = num(j, "energy_scale");
  const double balance = (num(j, "energy") - E0 - num(j, "work")) / mgl;
  EXPECT_LE(std::abs(balance), 1e-3);
  // The end starts 4 m to the side (+y) of the top at (1, 0.5, 0) and swings out of that plane.
  EXPECT_NEAR(rows.front()[4], 1.0, 1e-9);
  EXPECT_NEAR(rows.front()[5], 4.5, 1e-9);
  double min_y = INFINITY;
  for (const auto& row : rows) min_y = std::min(min_y, row[5] - row[2]);
  EXPECT_LT(min_y, -1.0);
  std::printf("[ measured ] spatial_swing: energy balance %.3g of m g L, wall %.3g s, end y - top y down to %.3g m\n",
              balance, num(j, "wall_s"), min_y);
  std::filesystem::remove(csv);
}

// Every integrator of the planar path runs the 3D example; the implicit ones with the structured O(n)
// solves (auto) and with the dense Jacobian. midpoint and generalized_alpha iterate Newton to 1e-11, so both
// solves give the same end point (the core measures 1e-13 m; bound 1e-6 m, the summary's 9 digits on ~20 m).
TEST(CliSpatial, EveryIntegratorRuns) {
  for (const std::string integ : {"rk4", "dopri5", "rosenbrock2", "midpoint", "generalized_alpha"}) {
    // The explicit ones at the scene's 2 ms (rk4's limit is set by the bending springs), the implicit at 10 ms.
    const bool explicit_scheme = integ == "rk4" || integ == "dopri5";
    const std::string dt = explicit_scheme ? "0.002" : "0.01";
    Vec3 end[2];
    for (const std::string jac : {"auto", "dense"}) {
      if (explicit_scheme && jac == "dense") continue;
      SCOPED_TRACE(integ + " " + jac);
      const CliRun r =
          runCli("--scene " + swingScene() + " --duration 0.5 --summary --quiet --set solver.integrator=" + integ +
                 " --set solver.dt=" + dt + " --set solver.jacobian=" + jac);
      ASSERT_EQ(r.code, 0) << r.err;
      auto j = summary(r);
      EXPECT_TRUE(j["status"] == "ok" || j["status"] == "warning") << r.out;
      EXPECT_EQ(j["integrator"], integ);
      end[jac == "dense"] = Vec3(num(j, "x_end"), num(j, "y_end"), num(j, "z_end"));
      std::printf("[ measured ] %s (%s) at %s s: status %s, energy drift %s, wall %s s\n", integ.c_str(), jac.c_str(),
                  dt.c_str(), j["status"].c_str(), j["energy_drift"].c_str(), j["wall_s"].c_str());
    }
    if (integ == "midpoint" || integ == "generalized_alpha") EXPECT_LT((end[0] - end[1]).norm(), 1e-6) << integ;
  }
}

// A finished run whose energy balance is off says so, as the planar CLI: rosenbrock2 damps what 20 ms does
// not resolve (measured: 1.4 % of m g L over 2 s): status warning, exit 0, a warning line on stderr.
TEST(CliSpatial, UnresolvedStepWarns) {
  const CliRun r = runCli("--scene " + swingScene() +
                          " --duration 2 --summary --quiet --set solver.integrator=rosenbrock2 "
                          "--set solver.dt=0.02");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = summary(r);
  EXPECT_EQ(j["status"], "warning");
  EXPECT_GT(std::abs(num(j, "energy_drift")), 1e-3);
  EXPECT_NE(j["warning"].find("energy balance off by"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("riser_sim_cli: warning: energy balance off by"), std::string::npos) << r.err;
}

// A step far too large stops with exit code 3 naming solver.dt, and the CSV has no NaN.
TEST(CliSpatial, DivergenceExits3NamingTheStep) {
  const std::string csv = tempPath("spatial_diverged.csv");
  const CliRun r = runCli("--scene " + kChain +
                          " --set space=spatial --set solver.dt=0.05 --duration 5 "
                          "--output-dt 0.05 --summary --csv " +
                          csv);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("solver.dt"), std::string::npos) << r.err;
  auto j = summary(r);
  EXPECT_EQ(j["status"], "diverged");
  const std::string text = readFile(csv);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  std::string header;
  csvRows(text, header);
  std::filesystem::remove(csv);
}

// The 3D stability estimate and force-noise warning, as the planar CLI's (test_cli.cpp, test_cli_outputs.cpp).
// rk4's limit is estimated and reported up front on the 3D swing; at 0.8x the run completes, at 1.5x it
// stops with exit code 3 naming the limit and a safe solver.dt (test_spatial_stability measures both
// margins on the core).
TEST(CliSpatial, StabilityLimitReportedAndEnforced) {
  const std::string scene = "--scene " + kScenes + "spatial_swing.yaml --summary";
  const CliRun probe = runCli(scene + " --duration 0.002");
  ASSERT_EQ(probe.code, 0) << probe.err;
  auto j = summary(probe);
  const double limit = num(j, "stable_dt_estimate");
  ASSERT_GT(limit, 0.0);
  EXPECT_GT(num(j, "omega_max"), 0.0);
  EXPECT_NE(probe.err.find("stability: highest frequency"), std::string::npos) << probe.err;
  EXPECT_NE(probe.err.find("rk4 stable for solver.dt <= ~"), std::string::npos) << probe.err;
  EXPECT_EQ(probe.err.find("no step-size estimate"), std::string::npos) << probe.err;

  char dt[64];
  std::snprintf(dt, sizeof(dt), " --set solver.dt=%.9g", 0.8 * limit);
  const CliRun below = runCli(scene + dt + " --duration 2");
  EXPECT_EQ(below.code, 0) << below.err;
  EXPECT_EQ(below.err.find("solver.dt is above it"), std::string::npos) << below.err;

  std::snprintf(dt, sizeof(dt), " --set solver.dt=%.9g", 1.5 * limit);
  const CliRun above = runCli(scene + dt + " --duration 2");
  EXPECT_EQ(above.code, 3) << above.err;
  EXPECT_NE(above.err.find("solver.dt is above it"), std::string::npos) << "not reported up front: " << above.err;
  EXPECT_NE(above.err.find("stability limit h ~"), std::string::npos) << above.err;
  EXPECT_NE(above.err.find("a safe solver.dt is"), std::string::npos) << above.err;
  auto k = summary(above);
  EXPECT_EQ(k["status"], "diverged");

  // An implicit scheme has no such limit: rk4's is given for reference.
  const CliRun implicit = runCli(scene + " --set solver.integrator=midpoint --duration 0.002");
  EXPECT_NE(implicit.err.find("(rk4 would need solver.dt <= ~"), std::string::npos) << implicit.err;
}

// A steel line dropped unstretched (test_spatial_stability: axial modes ringing at ~0.7 of the tension
// under midpoint at 20 ms) warns "forces not resolved" with status "warning" and exit 0; the advised
// generalized_alpha at rho_inf 0 is "ok" with noise below 3 %.
TEST(CliSpatial, UnresolvedForcesWarn) {
  const std::string scene = "--scene " + kScenes +
                            "spatial_swing.yaml --set line.axial_flexibility=true "
                            "--set line.elements=20 --set initial.type=straight --set initial.angle=-80 "
                            "--set solver.dt=0.02 --duration 5 --summary --quiet";
  const CliRun bad = runCli(scene + " --set solver.integrator=midpoint");
  EXPECT_EQ(bad.code, 0) << bad.err;
  auto j = summary(bad);
  EXPECT_EQ(j["status"], "warning");
  EXPECT_GT(num(j, "force_noise_top"), 0.3) << bad.out;
  EXPECT_GT(num(j, "force_noise_max_axial"), 0.3) << bad.out;
  EXPECT_NE(j["warning"].find("forces not resolved"), std::string::npos) << bad.out;
  EXPECT_NE(bad.err.find("use solver.integrator generalized_alpha"), std::string::npos) << bad.err;
  const CliRun good = runCli(scene + " --set solver.integrator=generalized_alpha --set solver.rho_inf=0");
  EXPECT_EQ(good.code, 0) << good.err;
  auto g = summary(good);
  EXPECT_EQ(g["status"], "ok") << good.out;
  EXPECT_LT(num(g, "force_noise_top"), 0.03) << good.out;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
