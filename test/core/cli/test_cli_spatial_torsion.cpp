// Torsion through the CLI: --modes with line.torsion lists the torsional modes (the shaft against its exact
// frequency equation), the bending rows are torsion-off's; top.torsion: free and the top flex joint's
// torsional stiffness; the hang-off's twisting moment in the CSV and the summary, a spin's divergence named;
// bad keys named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cli_test_util.h"

using namespace cli_test;

namespace {

struct Row {
  double f;  // [Hz], 0 for a zero mode
  std::string character;
};
std::vector<Row> table(const std::string& out) {
  std::vector<Row> rows;
  std::istringstream in(out);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string k, period, f, omega, character;
    ls >> k >> period >> f >> omega >> character;
    rows.push_back({f == "-" ? 0.0 : std::stod(f), character});  // zero / unstable rows: no frequency
  }
  return rows;
}

// test_spatial_torsion's shaft: L = 10 m, 16 rfes, no bending, inextensible, GJ = 1e4 N m², ρI_p = 1 kg m,
// J_end = 10 kg m² (x tan x = 1 held; tan x = -x free).
std::string shaftScene(const std::string& name, const std::string& torsion, const std::string& top = "") {
  return writeScene(name, "name: " + name +
                              "\nspace: spatial\nline: {length: 10, elements: 16, mass_per_length: 10, "
                              "bending: false, axial_flexibility: false, end_mass: 50" +
                              torsion +
                              "}\ntop: {position: "
                              "[0, 0, 0]" +
                              top + "}\ninitial: {type: hanging}\n");
}
const std::string kTorsion = ", torsion: {stiffness: 1.0e4, polar_inertia: 1, end_polar_inertia: 10}";

double firstRoot(double lo, double hi, double (*g)(double)) {
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (lo + hi);
    (g(lo) * g(m) <= 0.0 ? hi : lo) = m;
  }
  return 0.5 * (lo + hi);
}

// Torsion on: the first torsional row is the shaft's mode; the error of 16 rfes is the discretisation's
// (test_spatial_torsion_modes: 2.1e-4 at n = 16, order 2) plus 6 printed digits.
TEST(CliSpatialTorsion, ModesListTheTorsionalModes) {
  const CliRun off = runCli("--scene " + shaftScene("shaft_off", "") + " --quiet --modes 40");
  const CliRun on = runCli("--scene " + shaftScene("shaft_on", kTorsion) + " --quiet --modes 60");
  ASSERT_EQ(off.code, 0) << off.err;
  ASSERT_EQ(on.code, 0) << on.err;
  std::vector<Row> bending, twist;
  for (const Row& r : table(on.out)) (r.character == "torsional" ? twist : bending).push_back(r);
  const std::vector<Row> plain = table(off.out);
  ASSERT_EQ(twist.size(), 16u);  // one per spinning rfe (17 rfes, rfe 0 held)
  ASSERT_EQ(bending.size(), plain.size());
  for (size_t k = 0; k < plain.size(); ++k) {  // straight: no coupling, the same printed digits
    EXPECT_EQ(bending[k].f, plain[k].f) << k;
    EXPECT_EQ(bending[k].character, plain[k].character) << k;
  }
  const double x = firstRoot(1e-9, 0.5 * M_PI - 1e-9, [](double v) { return v * std::tan(v) - 1.0; });
  const double f = x * std::sqrt(1e4 / 1.0) / 10.0 / (2.0 * M_PI);
  std::printf("[cli torsion modes] first torsional %.6g Hz vs the exact %.6g Hz (%.2e)\n", twist[0].f, f,
              twist[0].f / f - 1.0);
  EXPECT_NEAR(twist[0].f / f, 1.0, 5e-4);
}

// top.torsion: free: the rigid spin is a zero row, then tan x = -x; the top flex joint's torsional stiffness
// k_t = GJ/L: ω = 5.559684307 rad/s exact (springRoots in test_spatial_torsion_modes, κ = 1).
TEST(CliSpatialTorsion, FreeAndSpringHeldTops) {
  const CliRun fr = runCli("--scene " + shaftScene("shaft_free", kTorsion, ", torsion: free") + " --quiet --modes 60");
  ASSERT_EQ(fr.code, 0) << fr.err;
  std::vector<Row> twist;
  int zero = 0;
  for (const Row& r : table(fr.out)) {
    if (r.character == "torsional") twist.push_back(r);
    if (r.f == 0.0) ++zero;
  }
  EXPECT_EQ(zero, 1);
  ASSERT_EQ(twist.size(), 16u);  // 17 spins, the rigid one printed as zero
  const double x = firstRoot(0.5 * M_PI + 1e-9, M_PI, [](double v) { return std::tan(v) + v; });
  const double f = x * 100.0 / 10.0 / (2.0 * M_PI);
  std::printf("[cli torsion modes] free top: first torsional %.6g Hz vs the exact %.6g Hz (%.2e)\n", twist[0].f, f,
              twist[0].f / f - 1.0);
  EXPECT_NEAR(twist[0].f / f, 1.0, 2e-3);  // 16 rfes, order 2 (test_spatial_torsion_modes), + 6 digits

  const CliRun sp = runCli("--scene " +
                           shaftScene("shaft_spring", kTorsion,
                                      ", flex_joint: {stiffness: 1.0e9, "
                                      "torsional_stiffness: 1.0e3}") +
                           " --quiet --modes 60");
  ASSERT_EQ(sp.code, 0) << sp.err;
  std::vector<Row> held;
  for (const Row& r : table(sp.out))
    if (r.character == "torsional") held.push_back(r);
  ASSERT_EQ(held.size(), 17u);
  const double fs = 5.559684307 / (2.0 * M_PI);
  std::printf("[cli torsion modes] top spring k_t = GJ/L: first torsional %.6g Hz vs the exact %.6g Hz (%.2e)\n",
              held[0].f, fs, held[0].f / fs - 1.0);
  EXPECT_NEAR(held[0].f / fs, 1.0, 1e-4);  // 16 rfes: 2.0e-5 (test_spatial_torsion_modes) + 6 digits
}

// The shaft's top circling (0.5 m, 2 s): the line swings in 3D and twists. The CSV's top_twist is the
// hang-off's twisting moment τ, and top_m·h = τ (top_twist_moment = τ (h + e_0)/(1 + h·e_0), h = -z here: the
// line hangs straight down at t = 0), in every row; the summary's is the last row's. At dt = 0.02 s rk4 is
// beyond the twist's stability limit (~8.7e-3 s: ω_max ~ 2 sqrt(GJ/d / ρI_p d) = 320 rad/s) but within the
// swing's (~39 rad/s): the run stops with exit 3 naming the spin.
TEST(CliSpatialTorsion, TopTwistColumnAndSpinDivergence) {
  const std::string scene = shaftScene("shaft_whirl", kTorsion,
                                       ", motion: {type: sinusoid, amplitude: [0.5, 0.5, 0.0], "
                                       "period: 2.0, phase: [0.0, -1.5708, 0.0]}");
  const std::string csv = tempPath("shaft_whirl.csv");
  const CliRun r = runCli("--scene " + scene + " --duration 2 --quiet --summary --csv " + csv +
                          " --set solver.integrator=rk4 --set solver.dt=0.001");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const std::vector<std::vector<double>> rows = csvRows(readFile(csv), header);
  const std::string tail = ",top_twist";
  ASSERT_EQ(header.substr(header.size() - tail.size()), tail) << header;
  ASSERT_NE(header.find(",top_mz,"), std::string::npos) << header;
  const auto column = [&](size_t at) { return size_t(std::count(header.begin(), header.begin() + at, ',')); };
  const size_t twist = column(header.size()), mz = column(header.find(",top_mz,") + 1);
  double big = 0.0, worst = 0.0;
  for (const auto& row : rows) big = std::max(big, std::abs(row[twist]));
  for (const auto& row : rows) worst = std::max(worst, std::abs(row[twist] + row[mz]));
  EXPECT_GT(big, 1e-3);          // the swing twists the line
  EXPECT_LE(worst, 1e-8 * big);  // 9 printed digits
  std::map<std::string, std::string> j = summary(r);
  EXPECT_NEAR(num(j, "top_twist"), rows.back()[twist], 1e-8 * big);  // the CSV's 9 digits
  std::printf("[cli torsion] whirling shaft: max |top_twist| %.4g N m, |top_twist - top_m·h| %.1e of it\n", big,
              worst / big);

  const CliRun d =
      runCli("--scene " + scene + " --duration 2 --quiet --set solver.integrator=rk4 --set solver.dt=0.02");
  EXPECT_EQ(d.code, 3) << d.err;
  EXPECT_NE(d.err.find("spins by"), std::string::npos) << d.err;
}

// The shipped flat umbilical (bending axes between the catenary's plane and its normal): its twisted start is at
// rest (the builder's check, printed in the summary), the run keeps the energy balance and twists the hang-off,
// and --modes about the twisted state lists no unstable mode.
TEST(CliSpatialTorsion, FlatUmbilicalScene) {
  const std::string scene = kScenes + "spatial_flat_umbilical.yaml";
  const CliRun r = runCli("--scene " + scene + " --duration 10 --summary --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, std::string> j = summary(r);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_LE(num(j, "initial_acceleration"), num(j, "initial_acceleration_bound"));
  EXPECT_LE(num(j, "initial_twist_moment"), num(j, "initial_twist_moment_bound"));
  EXPECT_LT(std::abs(num(j, "energy_drift")), 1e-7);  // of m g L; ~4e-9 measured
  EXPECT_GT(std::abs(num(j, "top_twist")), 1.0);      // [N m]
  const CliRun m = runCli("--scene " + scene + " --quiet --modes 12");
  ASSERT_EQ(m.code, 0) << m.err;
  const std::vector<Row> rows = table(m.out);
  ASSERT_EQ(rows.size(), 12u) << m.out;
  for (const Row& row : rows) EXPECT_NE(row.character, "unstable") << m.out;
  std::printf("[cli torsion] flat umbilical: energy drift %s, top twist %s N m; lowest mode %.4f Hz (%s)\n",
              j["energy_drift"].c_str(), j["top_twist"].c_str(), rows[0].f, rows[0].character.c_str());
}

TEST(CliSpatialTorsion, BadKeysAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set space=spatial --set top.torsion=free", "top.torsion: needs line.torsion"},
      {"--set space=spatial --set line.torsion.stiffness=1e4 --set line.torsion.polar_inertia=1 "
       "--set top.torsion=loose",
       "top.torsion: unknown value 'loose'"},
      {"--set space=spatial --set top.flex_joint.stiffness=1e4 --set top.flex_joint.torsional_stiffness=1e3",
       "top.flex_joint.torsional_stiffness: needs line.torsion"},
      {"--set space=spatial --set line.torsion.stiffness=1e4 --set line.torsion.polar_inertia=1 --set top.torsion=free "
       "--set top.flex_joint.stiffness=1e4 --set top.flex_joint.torsional_stiffness=1e3",
       "top.flex_joint.torsional_stiffness: contradicts top.torsion: free"},
      {"--set space=spatial --set line.torsion.stiffness=1e4 --set line.torsion.polar_inertia=1 "
       "--set top.flex_joint.stiffness=1e4 --set top.flex_joint.torsional_stiffness=-1",
       "top.flex_joint.torsional_stiffness: must be > 0"},
      {"--set space=spatial --set line.torsion.stiffness=1e4 --set line.torsion.polar_inertia=1 "
       "--set top.flex_joint.stiffness=1e4 --set top.flex_joint.torsional_damping=5",
       "top.flex_joint.torsional_damping: needs torsional_stiffness"},
      {"--set space=spatial --set line.torsion.stiffness=1e4 --set line.torsion.polar_inertia=1 "
       "--set top.flex_joint.stiffness=1e4 --set top.flex_joint.torsional_stiffness=1e3 "
       "--set top.flex_joint.torsional_damping=-1",
       "top.flex_joint.torsional_damping: must be >= 0"},
      {"--set space=spatial --set line.bending=true --set 'line.EI=[4e4, 4e3]' --set 'line.bending_axis=[0, 1, 0]'",
       "line.EI: [EI_1, EI_2] needs line.torsion"},
      {"--set 'line.EI=[4e4, 4e3]'", "line.EI: [EI_1, EI_2] needs space: spatial"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet " + c.first);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
  }
}

}  // namespace
