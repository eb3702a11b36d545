// riser_sim_cli end to end: exit codes, error messages, the JSON summary and the CSV time series.
#include <gtest/gtest.h>

#include "cli_test_util.h"

using namespace cli_test;

TEST(Cli, HelpExitsZero) {
  const CliRun r = runCli("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--scene FILE"), std::string::npos);
}

TEST(Cli, BadOverrideExits2NamingTheKey) {
  const CliRun r = runCli("--scene " + kChain + " --set line.elements=0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("riser_sim_cli: error: line.elements: must be >= 1"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// --set KEY=null removes the key: the scene reads as if it were not written (its default, or "missing
// required key"); removing a key the scene does not have is an error naming it.
TEST(Cli, SetNullRemovesTheKey) {
  const std::string table1 = kScenes + "paper_table1.yaml";
  const CliRun required = runCli("--scene " + table1 + " --duration 0 --quiet --set initial.end_dx=null");
  EXPECT_EQ(required.code, 2);
  EXPECT_NE(required.err.find("initial.end_dx: missing required key"), std::string::npos) << required.err;

  std::string text = readFile(kChain);
  const size_t angle = text.find("  angle:");
  ASSERT_NE(angle, std::string::npos);
  text.erase(angle, text.find('\n', angle) + 1 - angle);
  const std::string without = writeScene("chain_without_angle", text);
  const CliRun removed = runCli("--scene " + kChain + " --duration 0 --summary --quiet --set initial.angle=null");
  const CliRun written = runCli("--scene " + without + " --duration 0 --summary --quiet");
  ASSERT_EQ(removed.code, 0) << removed.err;
  ASSERT_EQ(written.code, 0) << written.err;
  auto a = summary(removed), b = summary(written);
  for (const char* key : {"x_end", "z_end", "tension_top", "energy"}) EXPECT_EQ(a[key], b[key]) << key;
  EXPECT_NE(a["x_end"], summary(runCli("--scene " + kChain + " --duration 0 --summary --quiet"))["x_end"]);
  std::filesystem::remove(without);

  for (const auto& c : std::vector<std::pair<std::string, std::string>>{
           {"initial.nothing=null", "initial.nothing: is not in the scene: nothing to remove"},
           {"nosection.key=null", "nosection: is not in the scene: nothing to remove"}}) {
    const CliRun r = runCli("--scene " + kChain + " --duration 0 --quiet --set " + c.first);
    EXPECT_EQ(r.code, 2) << c.first;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
  }
}

TEST(Cli, BadInputExits2) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "--scene FILE is required"},
      {"--scene " + kChain + " --frobnicate", "unknown option '--frobnicate'"},
      {"--scene " + kChain + " --duration -1", "--duration: expected a number of seconds >= 0"},
      // 1e20 s at dt = 1e-4: 1e24 steps, beyond the loader's limit (and a long)
      {"--scene " + kChain + " --duration 1e20", "--duration: 1e+24 steps of solver.dt, more than 1e+09"},
      {"--scene " + kChain + " --set line.lenght=3", "line.lenght: unknown key"},
      {"--scene " + kChain + " --set solver.integrator=euler", "solver.integrator: unknown value 'euler'"},
      {"--scene /nonexistent/riser_sim.yaml", "cannot open scene file"},
      {"--scene " + kChain + " --csv /nonexistent/dir/out.csv", "--csv: cannot open"},
      {"--scene " + kChain + " --probe-rfe 2", "--probe-rfe: needs --csv"},
      {"--scene " + kChain + " --csv /dev/null --probe-rfe -1", "--probe-rfe: expected an rfe index"},
      {"--scene " + kChain + " --csv /dev/null --probe-rfe 9", "--probe-rfe: rfe 9 does not exist (rfes 0..8"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const CliRun r = runCli(c.first);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
  }
}

TEST(Cli, ShortRunWritesSummaryAndCsv) {
  const std::string csv = tempPath("chain.csv");
  // 0.5 s at dt = 1e-4 (hanging_chain.yaml): 5000 steps, a row every 0.1 s.
  const CliRun r = runCli("--scene " + kChain + " --duration 0.5 --output-dt 0.1 --summary --quiet --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << "--quiet prints nothing on success: " << r.err;

  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
  for (const char* key : {"wall_s", "cpu_s", "sim_s", "steps", "rtf", "x_end", "y_end", "z_end", "tension_top",
                          "max_constraint_error", "energy_drift", "scene", "n", "dt", "integrator", "formulation",
                          "statics_iterations", "end_force_x", "end_force_z"})
    EXPECT_EQ(j.count(key), 1u) << "summary lacks " << key << ": " << r.out;
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["scene"], "hanging_chain");
  EXPECT_EQ(j["n"], "8");
  EXPECT_EQ(j["steps"], "5000");
  EXPECT_EQ(j["integrator"], "rk4");
  EXPECT_EQ(j["formulation"], "absolute");
  EXPECT_DOUBLE_EQ(std::stod(j["sim_s"]), 0.5);
  EXPECT_GT(std::stod(j["wall_s"]), 0.0);
  EXPECT_GT(std::stod(j["cpu_s"]), 0.0);

  std::string header;
  const auto rows = csvRows(readFile(csv), header);
  EXPECT_EQ(header, kHeader);
  ASSERT_EQ(rows.size(), 6u);  // t = 0, 0.1, ..., 0.5
  for (size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), kColumns);
    EXPECT_NEAR(rows[k][0], 0.1 * k, 1e-9);  // the step count is exact; %.9g rounding only
  }
  // The summary's end point is the CSV's last row (both %.9g of the same double).
  EXPECT_EQ(std::stod(j["x_end"]), rows.back()[kXEnd]);
  EXPECT_EQ(std::stod(j["z_end"]), rows.back()[kZEnd]);
  EXPECT_EQ(std::stod(j["y_end"]), 0.0);  // a planar scene is the x-z plane
  // Released from a straight line at -45 deg: the start row is that line (L = 10 m).
  EXPECT_NEAR(rows[0][kXEnd], 10.0 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(rows[0][kYEnd], 0.0);
  EXPECT_NEAR(rows[0][kZEnd], -10.0 / std::sqrt(2.0), 1e-6);
  std::filesystem::remove(csv);
}

// --probe-rfe K: the middle of rfe K (its spring, at arc length s_K = s_begin + l1) and the axial force
// in rfe K. References: the straight unstretched start line (positions exact), and the hanging static
// state, where the spring of rfe K carries the weight below it: g (mu (L - s_K) + m_end) (a chain,
// exact at equilibrium up to the statics tolerance 1e-9 of the weight).
TEST(Cli, ProbeRfeColumns) {
  const std::string csv = tempPath("probe.csv");
  // hanging_chain.yaml: L = 10 m, n = 8 (d = 1.25 m, rfe 0 and 8 half length), mu = 2 kg/m, m_end = 5 kg.
  const double d = 1.25, mu = 2.0, m_end = 5.0, g = 9.81, L = 10.0;
  const std::vector<int> probes = {0, 4, 8};
  const auto sK = [&](int k) { return k == 0 ? 0.25 * d : (k - 0.5) * d + (k == 8 ? 0.25 * d : 0.5 * d); };
  {
    const CliRun r = runCli("--scene " + kChain +
                            " --duration 0.01 --quiet --probe-rfe 0 --probe-rfe=4 --probe-rfe 8 "
                            "--csv " +
                            csv);
    ASSERT_EQ(r.code, 0) << r.err;
    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    EXPECT_EQ(header, std::string(kHeader) +
                          ",x_rfe0,y_rfe0,z_rfe0,tension_rfe0,x_rfe4,y_rfe4,z_rfe4,"
                          "tension_rfe4,x_rfe8,y_rfe8,z_rfe8,tension_rfe8");
    ASSERT_GE(rows.size(), 1u);
    ASSERT_EQ(rows[0].size(), kColumns + 12);
    for (size_t p = 0; p < probes.size(); ++p) {  // straight at -45 deg, unstretched, at rest
      const double s = sK(probes[p]);
      EXPECT_NEAR(rows[0][kColumns + 4 * p], s / std::sqrt(2.0), 1e-7) << "rfe " << probes[p];
      EXPECT_NEAR(rows[0][kColumns + 2 + 4 * p], -s / std::sqrt(2.0), 1e-7) << "rfe " << probes[p];
      EXPECT_NEAR(rows[0][kColumns + 3 + 4 * p], 0.0, 1e-7) << "rfe " << probes[p];
    }
  }
  {
    const CliRun r = runCli("--scene " + kChain +
                            " --set initial.type=hanging --duration 0.01 --quiet "
                            "--probe-rfe 0 --probe-rfe 4 --probe-rfe 8 --csv " +
                            csv);
    ASSERT_EQ(r.code, 0) << r.err;
    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    ASSERT_GE(rows.size(), 1u);
    ASSERT_EQ(rows[0].size(), kColumns + 12);
    const double weight = g * (mu * L + m_end), strain_max = weight / 1.0e6;  // EA = 1e6 N
    for (size_t p = 0; p < probes.size(); ++p) {
      const double s = sK(probes[p]);
      EXPECT_NEAR(rows[0][kColumns + 4 * p], 0.0, 1e-9) << "rfe " << probes[p];
      EXPECT_LE(rows[0][kColumns + 2 + 4 * p], -s)
          << "rfe " << probes[p];  // stretched, but by less than the top strain
      EXPECT_GE(rows[0][kColumns + 2 + 4 * p], -s * (1.0 + strain_max)) << "rfe " << probes[p];
      EXPECT_NEAR(rows[0][kColumns + 3 + 4 * p], g * (mu * (L - s) + m_end), 1e-8 * weight) << "rfe " << probes[p];
    }
  }
  std::filesystem::remove(csv);
}

TEST(Cli, DurationFromSetAndDurationOption) {
  // --duration wins over run.duration set with --set.
  const CliRun r = runCli("--scene " + kChain + " --set run.duration=5 --duration 0.01 --summary --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
  EXPECT_EQ(j["steps"], "100");
}

TEST(Cli, DivergenceExits3AndCsvHasNoNan) {
  const std::string csv = tempPath("diverged.csv");
  // dt = 0.05 s is far beyond RK4's stability limit for this stiff line (axial period ~1e-3 s).
  const CliRun r =
      runCli("--scene " + kChain + " --set solver.dt=0.05 --duration 5 --output-dt 0.05 --summary --csv " + csv);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("diverged at t ="), std::string::npos) << r.err;
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  const std::string text = readFile(csv);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  std::string header;
  const auto rows = csvRows(text, header);  // checks every field is finite
  EXPECT_EQ(header, kHeader);
  EXPECT_GE(rows.size(), 1u);
  std::filesystem::remove(csv);
}

TEST(Cli, StaticsFailureExits3) {
  // A tolerance below round-off cannot be met: the initial statics report non-convergence.
  const CliRun r = runCli("--scene " + kScenes + "paper_table1.yaml --set initial.tolerance=1e-300 --quiet");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("riser_sim_cli: error: initial"), std::string::npos) << r.err;
}

TEST(Cli, EveryShippedSceneRuns) {
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const CliRun r = runCli("--scene " + entry.path().string() + " --duration 0.02 --summary --quiet");
    EXPECT_EQ(r.code, 0) << r.err;
    std::map<std::string, std::string> j;
    EXPECT_TRUE(parseFlatJson(r.out, j)) << r.out;
  }
}

// rk4's stability limit is estimated and reported up front; at 0.9x it the run completes, at 1.5x
// it stops with exit code 3 and a message naming the limit and a safe dt.
TEST(Cli, StabilityLimitReportedAndEnforced) {
  const std::string scene = "--scene " + kScenes + "paper_table1.yaml --set line.elements=20 --summary";
  const CliRun probe = runCli(scene + " --duration 0.001");
  ASSERT_EQ(probe.code, 0) << probe.err;
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(probe.out, j)) << probe.out;
  const double limit = std::stod(j["stable_dt_estimate"]);
  ASSERT_GT(limit, 0.0);
  EXPECT_NE(probe.err.find("stability: highest frequency"), std::string::npos) << probe.err;

  char dt[64];
  std::snprintf(dt, sizeof(dt), " --set solver.dt=%.9g", 0.9 * limit);
  const CliRun below = runCli(scene + dt + " --duration 0.5");
  EXPECT_EQ(below.code, 0) << below.err;

  std::snprintf(dt, sizeof(dt), " --set solver.dt=%.9g", 1.5 * limit);
  const CliRun above = runCli(scene + dt + " --duration 0.5");
  EXPECT_EQ(above.code, 3) << above.err;
  EXPECT_NE(above.err.find("solver.dt is above it"), std::string::npos) << "not reported up front: " << above.err;
  EXPECT_NE(above.err.find("stability limit h ~"), std::string::npos) << above.err;
  EXPECT_NE(above.err.find("a safe solver.dt is"), std::string::npos) << above.err;
  std::map<std::string, std::string> k;
  ASSERT_TRUE(parseFlatJson(above.out, k)) << above.out;
  EXPECT_EQ(k["status"], "diverged");
}

// Every output that cannot be written is an error naming it (exit code 4), never "status":"ok" and exit 0.
// /dev/full: every write fails with ENOSPC (here at the close: the rows fit the stdio buffer).

// catkin_add_gtest links gtest without gtest_main here; a main of our own works either way.
int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
