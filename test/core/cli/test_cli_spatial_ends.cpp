// The 3D ends through the CLI (docs/spatial.md, "Ends"): a flex joint's moment at rest against the weight's
// moment about the hang-off, a pinned bottom's force and moment against the line's statics, a driven
// (ROV-like) bottom on its circle with the energy balance, two ends translating together along a straight
// inextensible line (rigid motion: no deformation), bad keys refused. --modes in 3D: test_cli_spatial_modes.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <fstream>

#include "cli_test_util.h"

using namespace cli_test;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr double kG = 9.81;

// A CSV with its columns by name.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int col(const std::string& n) const {
    for (size_t k = 0; k < names.size(); ++k)
      if (names[k] == n) return int(k);
    ADD_FAILURE() << "no column " << n;
    return 0;
  }
  double at(size_t row, const std::string& n) const { return rows[row][col(n)]; }
  // (x_<p>, y_<p>, z_<p>) or (<p>x, <p>y, <p>z) of a row.
  Vec3 vec(size_t row, const std::string& x, const std::string& y, const std::string& z) const {
    return Vec3(at(row, x), at(row, y), at(row, z));
  }
};

Table readTable(const std::string& path) {
  Table t;
  std::string header;
  t.rows = csvRows(readFile(path), header);
  std::stringstream ss(header);
  for (std::string f; std::getline(ss, f, ',');) t.names.push_back(f);
  return t;
}

// The 10 m line of these tests: 10 kg/m, n = 6, inextensible, so each rfe's mass sits at its middle, the
// CSV's probe point (half-length end rfes: 10/12 m, the others 10/6 m).
const char* kLine =
    "line: {length: 10, elements: 6, mass_per_length: 10, EI: 1.0e5, axial_flexibility: false, "
    "bending_damping: 300";

// Σ_p (x_p - A_0) × m_p g of the row [N m]: the rfes' masses at their middles (probes 0..6), the end mass at
// the end.
Vec3 weightMoment(const Table& t, size_t row, double end_mass) {
  const Vec3 A0 = t.vec(row, "x_top", "y_top", "z_top"), g(0, 0, -kG);
  Vec3 M = end_mass * (t.vec(row, "x_end", "y_end", "z_end") - A0).cross(g);
  for (int i = 0; i <= 6; ++i) {
    const std::string K = std::to_string(i);
    const double m = 10.0 * (i == 0 || i == 6 ? 10.0 / 12.0 : 10.0 / 6.0);
    M += m * (t.vec(row, "x_rfe" + K, "y_rfe" + K, "z_rfe" + K) - A0).cross(g);
  }
  return M;
}

std::string probes() {
  std::string p;
  for (int i = 0; i <= 6; ++i) p += " --probe-rfe " + std::to_string(i);
  return p;
}

// A line hanging off a top flex joint whose axis is 40° off the vertical toward (1, 1)/√2, started straight
// along the axis (joint unloaded) and brought to rest by the joint's and the bending dampers (40 s). At rest
// the moment on the hang-off balances the weight's moment about it (statics of the whole line: the top
// force acts at A_0), computed from the CSV's points alone.
TEST(CliSpatialEnds, FlexJointTopMomentBalancesTheWeight) {
  const double k = 2.0 * (100.0 + 50.0) * kG * 10.0;  // 2 m g L: the line sags well below the axis
  const double a = 40.0 * M_PI / 180.0;
  const Vec3 axis(std::sin(a) / std::sqrt(2.0), std::sin(a) / std::sqrt(2.0), -std::cos(a));
  char top[256];
  std::snprintf(top, sizeof(top),
                "top: {position: [1, 2, 3], flex_joint: {stiffness: %.17g, damping: 2.0e4, "
                "axis: [%.17g, %.17g, %.17g]}}\n",
                k, axis.x(), axis.y(), axis.z());
  const std::string scene = writeScene(
      "flex_top", std::string("name: flex_top\nspace: spatial\n") + kLine + ", end_mass: 50}\n" + top +
                      "initial: {type: straight, angle: -50, heading: 45}\nsolver: {integrator: rk4, dt: 5.0e-4}\n");
  const std::string csv = tempPath("flex_top.csv");
  const CliRun r =
      runCli("--scene " + scene + " --duration 40 --output-dt 1 --summary --quiet --csv " + csv + probes());
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = summary(r);
  const Table t = readTable(csv);
  ASSERT_EQ(t.rows.size(), 41u);
  const size_t last = t.rows.size() - 1;
  const Vec3 M(num(j, "top_moment_x"), num(j, "top_moment_y"), num(j, "top_moment_z"));
  const Vec3 W = weightMoment(t, last, 50.0);
  const double rest = (t.vec(last, "x_end", "y_end", "z_end") - t.vec(last - 1, "x_end", "y_end", "z_end")).norm();
  std::printf("[flex top] |M| = %.6e N m, |M - W| / |W| = %.2e, end moved %.1e m in the last second, max |M| %.6e\n",
              M.norm(), (M - W).norm() / W.norm(), rest, num(j, "top_moment_max"));
  // Measured 6.3e-6 |W| (what is left of the motion after 40 s; the probes are printed to 9 digits). A wrong
  // sign or lever is O(|W|).
  EXPECT_LT((M - W).norm(), 3e-5 * W.norm());
  EXPECT_GT(W.norm(), 0.05 * 150.0 * kG * 10.0);  // the joint really carries the weight
  EXPECT_LT(rest, 1e-4);
  EXPECT_EQ(M.x(), t.at(last, "top_mx"));
  EXPECT_GE(num(j, "top_moment_max"), M.norm());
  EXPECT_EQ(num(j, "bottom_moment_x"), 0.0);  // free bottom
}

// Pinned both ends between (0, 0, 0) and (5, 5, -6) m. Without a flex joint, at the start (the statics'
// equilibrium): the bottom's moment is 0 and its force's moment about the hang-off balances the weight's,
// (E - A_0) × F_b = Σ (x_p - A_0) × m_p g. With a bottom flex joint whose axis is vertical, brought to rest
// by damping: the anchor's force and moment close the statics, F_t + F_b = m g and
// M_b + (E - A_0) × F_b = Σ (x_p - A_0) × m_p g.
TEST(CliSpatialEnds, PinnedBottomForceAndMoment) {
  const std::string base = std::string("name: pinned_ends\nspace: spatial\n") + kLine +
                           "}\ntop: {position: [0, 0, 0]}\ninitial: {type: between_points}\n"
                           "solver: {integrator: rk4, dt: 5.0e-4}\n";
  const Vec3 weight(0, 0, -100.0 * kG);
  for (const bool flex : {false, true}) {
    SCOPED_TRACE(flex ? "flex joint" : "pinned");
    const std::string scene = writeScene(
        "pinned_ends", base + (flex ? "bottom: {type: pinned, position: [5, 5, -6], flex_joint: {stiffness: 5.0e3, "
                                      "damping: 5.0e3, axis: [0, 0, 1]}}\n"
                                    : "bottom: {type: pinned, position: [5, 5, -6]}\n"));
    const std::string csv = tempPath("pinned_ends.csv");
    const CliRun r = runCli("--scene " + scene + " --duration " + (flex ? "40" : "0.001") +
                            " --output-dt 1 --summary --quiet --csv " + csv + probes());
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = summary(r);
    const Table t = readTable(csv);
    const size_t row = flex ? t.rows.size() - 1 : 0;
    const Vec3 Ft = t.vec(row, "top_fx", "top_fy", "top_fz"), Fb = t.vec(row, "bottom_fx", "bottom_fy", "bottom_fz");
    const Vec3 Mb = t.vec(row, "bottom_mx", "bottom_my", "bottom_mz");
    const Vec3 E = t.vec(row, "x_end", "y_end", "z_end") - t.vec(row, "x_top", "y_top", "z_top");
    const Vec3 W = weightMoment(t, row, 0.0);
    const double moment_error = (Mb + E.cross(Fb) - W).norm() / W.norm();
    std::printf("[pinned%s] |F_t + F_b - m g| / m g = %.2e, |M_b| = %.4e N m, moment balance %.2e of |W|\n",
                flex ? " + flex joint" : "", (Ft + Fb - weight).norm() / weight.norm(), Mb.norm(), moment_error);
    EXPECT_EQ(t.vec(row, "top_mx", "top_my", "top_mz"), Vec3::Zero());  // a pinned top carries no moment
    // Start: the statics' residual (initial.tolerance 1e-9 of the weight) and 9-digit output. At rest after
    // 40 s: what is left of the motion, as the top joint's test.
    EXPECT_LT((Ft + Fb - weight).norm(), 3e-5 * weight.norm());
    EXPECT_LT(moment_error, 3e-5);
    if (flex) {
      EXPECT_GT(Mb.norm(), 0.05 * W.norm());  // the joint holds the line off its vertical axis
      EXPECT_GE(num(j, "bottom_moment_max"), Mb.norm());
    } else {
      EXPECT_EQ(Mb, Vec3::Zero());
      EXPECT_EQ(j.count("bottom_moment_max"), 0u);
    }
  }
}

// An ROV-like bottom driving a 10 m line around a horizontal circle of radius 1 m (period 8 s) while the top
// is fixed: the bottom joint on its prescribed path and the energy balance E - E0 - W (W with the bottom's
// work) over the run after the start (the circle starts with a velocity jump the Baumgarte terms take out,
// docs/spatial.md), rk4 and midpoint with the structured solves.
TEST(CliSpatialEnds, DrivenBottomFollowsItsCircle) {
  const std::string scene =
      writeScene("rov",
                 "name: rov\nspace: spatial\nline: {length: 10, elements: 10, mass_per_length: 10, EA: 1.0e7, "
                 "EI: 1.0e4, axial_damping: 1.0e3}\ntop: {position: [0, 0, 0]}\n"
                 "bottom: {type: pinned, position: [4, 0, -8], motion: {type: sinusoid, amplitude: [1, 1, 0], "
                 "period: 8, phase: [0, -1.5707963267948966, 0]}}\ninitial: {type: between_points}\n"
                 "solver: {integrator: rk4, dt: 5.0e-4}\n");
  for (const std::string integrator : {"rk4", "midpoint"}) {
    SCOPED_TRACE(integrator);
    const std::string csv = tempPath("rov.csv");
    const std::string set = integrator == "rk4" ? "" : " --set solver.integrator=midpoint --set solver.dt=2.0e-3";
    const CliRun r = runCli("--scene " + scene + " --duration 8 --output-dt 0.1 --summary --quiet --csv " + csv + set);
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = summary(r);
    // Midpoint at 2 ms leaves the axial modes (~2e3 rad/s, hω ~ 4) that the start excites ringing: the
    // largest axial force has 15 % step-to-step noise (the CSV's tension_max at every step gives the same),
    // which the 3D force-noise monitor reports; the energy balance is not in the warning.
    if (integrator == "rk4")
      EXPECT_EQ(j["status"], "ok");
    else
      EXPECT_TRUE(j["status"] == "ok" || j["warning"].rfind("forces not resolved", 0) == 0) << r.out;
    const Table t = readTable(csv);
    ASSERT_EQ(t.rows.size(), 81u);
    const double mgl = num(j, "energy_scale"), w = 2.0 * M_PI / 8.0;
    size_t r1 = 0;
    while (t.at(r1, "t") < 1.0 - 1e-9) ++r1;
    double path = 0.0, gap = 0.0, balance = 0.0;
    for (size_t k = 0; k < t.rows.size(); ++k) {
      const double s = t.at(k, "t");
      const Vec3 pb = t.vec(k, "x_bottom", "y_bottom", "z_bottom");
      path = std::max(path, (pb - Vec3(4.0 + std::cos(w * s), std::sin(w * s), -8.0)).norm());
      if (k < r1) continue;
      gap = std::max(gap, (t.vec(k, "x_end", "y_end", "z_end") - pb).norm());
      balance = std::max(balance,
                         std::abs(t.at(k, "energy") - t.at(r1, "energy") - t.at(k, "work") + t.at(r1, "work")) / mgl);
    }
    std::printf(
        "[rov %s] path %.2e m, end-joint gap after 1 s %.2e m, |ΔE - ΔW| after 1 s %.2e of m g L, "
        "energy_drift from 0 %.2e\n",
        integrator.c_str(), path, gap, balance, num(j, "energy_drift"));
    EXPECT_LT(path, 1e-9 * 10.0);  // the anchor is the prescribed circle (shifted by the statics' end gap)
    // Measured by breaking the code: W without the bottom's work gives |ΔE - ΔW| = 8.1e-2 of m g L; the
    // bottom without its prescribed acceleration, a gap of 2.5e-4 m.
    EXPECT_LT(gap, 1e-6);
    EXPECT_LT(balance, integrator == "rk4" ? 1e-6 : 1e-3);
  }
}

// Top and bottom moving together along a straight vertical line pretensioned between them (sinusoid of 2 m
// in z, same phase, period 4 s): the reference is the rigid translation of the initial line. The only
// deformation is the axial response to the line's own inertia, -μ a along it: at most μ a L² / (8 EA) =
// 6.2e-7 m quasi-statically (a = 4.93 m/s², EA = 1e9 N), twice that as the sudden start's ringing (no
// damping). Across the line that inertia would bend it (a sag μ a L² / 8T): the test moves along it.
TEST(CliSpatialEnds, EndsTranslatingTogetherKeepTheLineRigid) {
  const std::string scene =
      writeScene("rigid",
                 "name: rigid\nspace: spatial\nline: {length: 10, elements: 6, mass_per_length: 10, EA: 1.0e9, "
                 "EI: 1.0e5}\ntop: {position: [1, 2, 0], motion: {type: sinusoid, amplitude: [0, 0, 2], period: 4}}\n"
                 "bottom: {type: pinned, position: [1, 2, -10.001], motion: {type: sinusoid, amplitude: [0, 0, 2], "
                 "period: 4}}\ninitial: {type: between_points}\nsolver: {integrator: rk4, dt: 1.0e-4}\n");
  const std::string csv = tempPath("rigid.csv");
  const CliRun r =
      runCli("--scene " + scene + " --duration 4 --output-dt 0.05 --summary --quiet --csv " + csv + probes());
  ASSERT_EQ(r.code, 0) << r.err;
  const Table t = readTable(csv);
  double dev = 0.0, travel = 0.0;
  for (size_t k = 0; k < t.rows.size(); ++k) {
    const Vec3 move = t.vec(k, "x_top", "y_top", "z_top") - t.vec(0, "x_top", "y_top", "z_top");
    travel = std::max(travel, move.norm());
    const auto moved = [&](const std::string& x, const std::string& y, const std::string& z) {
      return (t.vec(k, x, y, z) - t.vec(0, x, y, z) - move).norm();
    };
    dev = std::max({dev, moved("x_end", "y_end", "z_end"), moved("x_bottom", "y_bottom", "z_bottom")});
    for (int i = 0; i <= 6; ++i) {
      const std::string K = std::to_string(i);
      dev = std::max(dev, moved("x_rfe" + K, "y_rfe" + K, "z_rfe" + K));
    }
  }
  std::printf("[rigid translation] ends travel %.3f m; largest deviation from the translated line %.2e m\n", travel,
              dev);
  EXPECT_GT(travel, 3.9);
  // Bound: 4x the quasi-static axial response + the CSV's 9 digits of ~10 m. A bottom without its prescribed
  // acceleration lags by ~a/ω² ~ 2e-3 m (ω = 50 rad/s Baumgarte; measured by breaking the code: 3.0e-3 m).
  EXPECT_LT(dev, 4.0 * 10.0 * 4.93 * 100.0 / 8e9 + 1e-7);
}

TEST(CliSpatialEnds, BadKeysAreRefusedNamingTheKey) {
  const std::string pinned =
      " --set space=spatial --set bottom.type=pinned --set bottom.position=[0,0,-9.9]"
      " --set initial.type=between_points";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set top.flex_joint.stiffness=1e4", "top.flex_joint: needs space: spatial"},
      {"--set space=spatial --set top.flex_joint.damping=1", "top.flex_joint.stiffness: missing"},
      {"--set space=spatial --set top.flex_joint.stiffness=-1", "top.flex_joint.stiffness: must be > 0"},
      {"--set space=spatial --set top.flex_joint.stiffness=1 --set top.flex_joint.damping=-1",
       "top.flex_joint.damping: must be >= 0"},
      {"--set space=spatial --set top.flex_joint.stiffness=1 --set top.flex_joint.axis=[0,0,0]",
       "top.flex_joint.axis: must be a non-zero vector"},
      {"--set space=spatial --set top.flex_joint.stiffness=1 --set top.flex_joint.axis=[0,1]",
       "top.flex_joint.axis: expected [x, y, z]"},
      {"--set space=spatial --set top.flex_joint.stifness=1", "top.flex_joint.stifness: unknown key"},
      {"--set space=spatial --set bottom.flex_joint.stiffness=1", "bottom.flex_joint: needs bottom.type: pinned"},
      {"--set space=spatial --set bottom.motion.type=sinusoid", "bottom.motion: needs bottom.type: pinned"},
      {pinned + " --set bottom.motion.type=sinusoid", "bottom.motion.amplitude: missing"},
      {pinned + " --set bottom.motion.type=sway", "bottom.motion.type: unknown value 'sway'"},
      {"--set bottom.type=pinned --set bottom.position=[0,-9.9] --set initial.type=between_points "
       "--set bottom.motion.type=velocity_profile --set bottom.motion.knots=[[0,[1,0]]]",
       "bottom.motion.type: needs space: spatial"},
      {"--set space=spatial --set bottom.type=pinned --set bottom.position=[0,0,-9] --set initial.type=straight",
       "m from the end of the straight initial line"},
      {pinned + " --set bottom.motion.type=sinusoid --set bottom.motion.amplitude=[1,0,0] --set bottom.motion.period=5 "
                "--modes 3",
       "bottom.motion: the modes with space: spatial need a fixed or free bottom"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet " + c.first);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
  }
}

// A 3D straight start pinned where it ends runs (the chain at -45°, anchored at its end), and an external
// bottom motion is held at bottom.position offline: no anchor columns, the end stays at the anchor.
TEST(CliSpatialEnds, StraightPinnedStartAndExternalBottomRun) {
  char end[128];
  std::snprintf(end, sizeof(end), "[%.17g,0,%.17g]", 10.0 * std::cos(M_PI / 4.0), -10.0 * std::sin(M_PI / 4.0));
  const std::string set = " --set space=spatial --set bottom.type=pinned --set bottom.position=" + std::string(end);
  for (const std::string motion : {"", " --set bottom.motion.type=external"}) {
    SCOPED_TRACE(motion);
    const std::string csv = tempPath("straight_pinned.csv");
    const CliRun r = runCli("--scene " + kChain + " --duration 0.2 --summary --quiet --csv " + csv + set + motion);
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = summary(r);
    EXPECT_EQ(j["status"], "ok");
    EXPECT_EQ(j.count("x_bottom"), 0u);
    const Table t = readTable(csv);
    const size_t last = t.rows.size() - 1;
    EXPECT_LT(
        (t.vec(last, "x_end", "y_end", "z_end") - Vec3(10.0 * std::cos(M_PI / 4.0), 0, -10.0 * std::sin(M_PI / 4.0)))
            .norm(),
        1e-6);
    EXPECT_GT(t.vec(last, "bottom_fx", "bottom_fy", "bottom_fz").norm(), 0.0);
  }
}

}  // namespace
