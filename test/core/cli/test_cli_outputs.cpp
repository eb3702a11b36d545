// riser_sim_cli end to end: outputs that cannot be lost (write errors, bounded input, output stride)
// and a finished run that says when its answer cannot be trusted.
#include <gtest/gtest.h>

#include "cli_test_util.h"

using namespace cli_test;

TEST(Cli, WriteErrorsFailNamingTheOutput) {
  const std::string run = "--scene " + kChain + " --duration 0.01 --quiet";
  struct Case {
    std::string args, named;
  };
  const std::vector<Case> cases = {
      {run + " --summary --csv /dev/full", "--csv: write to '/dev/full' failed: No space left on device"},
      // 5 s at a row per step: ~7 MB of rows; the run stops at the first failed buffer flush.
      {"--scene " + kChain + " --duration 5 --output-dt 1e-4 --quiet --summary --csv /dev/full",
       "the file is incomplete and the run was stopped"},
      {run + " --summary >/dev/full", "--summary: write to stdout failed"},
      {run + " --modes 3 >/dev/full", "--modes: write to stdout failed"},
      {run + " --modes 3 --modes-csv /dev/full >/dev/null", "--modes-csv: write to '/dev/full' failed"},
      {"--help >/dev/full", "write to stdout failed"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const CliRun r = runCli(c.args);
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("\"status\":\"ok\""), std::string::npos) << r.out;
    if (c.args.find("--summary --csv") != std::string::npos) {  // the summary says so too
      std::map<std::string, std::string> j;
      ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
      EXPECT_EQ(j["status"], "write_failed");
      EXPECT_NE(j["write_error"].find("/dev/full"), std::string::npos) << r.out;
    }
  }
}

// An output path that cannot take the data: a directory fails to open (exit 2); /proc/version opens for
// root and fails at the write (EIO, exit 4), or fails to open for other users (EACCES, exit 2).
TEST(Cli, UnwritableOutputPathFails) {
  for (const std::string& path : std::vector<std::string>{"/proc/version", testing::TempDir()}) {
    for (const std::string option : {"--csv", "--modes 2 --modes-csv"}) {
      SCOPED_TRACE(option + " " + path);
      const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet " + option + " " + path);
      EXPECT_TRUE(r.code == 2 || r.code == 4) << r.code << ": " << r.err;
      EXPECT_NE(r.err.find("'" + path + "'"), std::string::npos) << r.err;
    }
  }
}

// An endless scene input stops at the size limit at once. The old loader grew ~1 GB/s: the memory limit
// (virtual, 1 GiB; not under ASan, which reserves terabytes) and `timeout` keep a regression from taking
// the machine with it. The fixed loader reads 1 MiB in ~10 ms.
TEST(Cli, EndlessSceneFailsAtTheSizeLimit) {
#if defined(RISER_SIM_ASAN)
  const std::string prefix = "timeout 60 ";
#else
  const std::string prefix = "ulimit -v 1048576; timeout 60 ";
#endif
  for (const std::string args : {"--scene /dev/zero", "--scene /dev/stdin </dev/zero"}) {
    SCOPED_TRACE(args);
    const CliRun r = runCli(args, prefix);
    EXPECT_EQ(r.code, 2) << r.err;
    const std::string path = args.substr(8, args.find(' ', 8) - 8);
    EXPECT_NE(r.err.find("scene file '" + path + "' is larger than 1 MiB (1048576 bytes)"), std::string::npos) << r.err;
  }
}

// An --output-dt beyond the run (1e15 s / 1e-4 s = 1e19 steps: more than a long) gives the first and the
// last row only; --output-dt = the duration the same, a third of it four rows.
TEST(Cli, HugeOutputDtWritesFirstAndLastRows) {
  const std::string csv = tempPath("sparse.csv");
  const std::vector<std::pair<std::string, std::vector<double>>> cases = {
      {"1e15", {0.0, 0.01}}, {"1e300", {0.0, 0.01}}, {"0.01", {0.0, 0.01}}, {"0.004", {0.0, 0.004, 0.008, 0.01}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    // hanging_chain.yaml: dt = 1e-4 s, 100 steps.
    const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet --output-dt " + c.first + " --csv " + csv);
    ASSERT_EQ(r.code, 0) << r.err;
    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    ASSERT_EQ(rows.size(), c.second.size());
    for (size_t k = 0; k < rows.size(); ++k) EXPECT_NEAR(rows[k][0], c.second[k], 1e-12);  // whole steps
  }
  std::filesystem::remove(csv);
}

// dopri5 at a tolerance far below round-off: the step size underflows; the message gives the step as a
// number and the tolerance to loosen (it said "h = -nan s": the starting step's norms overflowed).
TEST(Cli, Dopri5UnderflowMessageIsFinite) {
  const CliRun r = runCli("--scene " + kChain +
                          " --set solver.integrator=dopri5 --set solver.tolerance=1e-300 "
                          "--duration 0.01 --quiet");
  EXPECT_EQ(r.code, 3) << r.err;
  const size_t at = r.err.find("dopri5: step size underflow (h = ");
  ASSERT_NE(at, std::string::npos) << r.err;
  char* end = nullptr;
  const double h = std::strtod(r.err.c_str() + at + 33, &end);
  EXPECT_TRUE(std::isfinite(h) && h > 0.0 && h < 1e-14) << r.err;
  EXPECT_EQ(std::string(end, 2), " s") << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("solver.tolerance = 1e-300 cannot be met; loosen solver.tolerance"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("reduce solver.dt"), std::string::npos) << "a smaller output step does not help: " << r.err;
}

// A finished run whose energy balance is off says so (status "warning" with the reason, stderr), exit 0; a
// resolved run has no warning. rosenbrock2 at h = 0.02 s on the J-lay damps its unresolved axial modes
// and loses 12 % of m g L (its top tension is 74 % off); midpoint at the same h closes to 2e-7.
TEST(Cli, UnresolvedRunWarnsOnEnergyBalance) {
  const std::string jlay = kScenes +
                           "paper_jlay_170m.yaml --set solver.formulation=recursive --set solver.dt=0.02 "
                           "--duration 10 --summary --quiet";
  const CliRun bad = runCli("--scene " + jlay + " --set solver.integrator=rosenbrock2");
  EXPECT_EQ(bad.code, 0) << bad.err;
  EXPECT_NE(bad.out.find("\"status\":\"warning\""), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("\"warning\":\"energy balance off by"), std::string::npos) << bad.out;
  EXPECT_NE(bad.err.find("warning: energy balance off by"), std::string::npos) << bad.err;
  const CliRun good = runCli("--scene " + jlay + " --set solver.integrator=midpoint");
  EXPECT_EQ(good.code, 0) << good.err;
  EXPECT_EQ(good.out.find("warning"), std::string::npos) << good.out;
  EXPECT_NE(good.out.find("\"status\":\"ok\""), std::string::npos) << good.out;
}

// Forces that the step does not resolve say so, and the advised setting resolves them. J-lay, n = 100:
// midpoint at h = 0.1 s keeps the axial modes (10.5 Hz and up) undamped and aliased into the tension
// (76 % RMS off rk4 at 2.5e-4 s; estimate 0.69); the advised generalized_alpha at rho_inf 0 damps them
// (2.7 % RMS; estimate 0.014). Both close their energy balance, so only the force estimate can tell.
TEST(Cli, UnresolvedForcesWarnAndTheAdviceResolvesThem) {
  const std::string jlay = kScenes +
                           "paper_jlay_170m.yaml --set solver.formulation=recursive --set line.elements=100 "
                           "--set solver.dt=0.1 --duration 27 --summary --quiet";
  const CliRun bad = runCli("--scene " + jlay + " --set solver.integrator=midpoint");
  EXPECT_EQ(bad.code, 0) << bad.err;
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(bad.out, j)) << bad.out;
  EXPECT_EQ(j["status"], "warning");
  EXPECT_GT(std::stod(j["force_noise_top"]), 0.3) << bad.out;
  EXPECT_NE(j["warning"].find("forces not resolved"), std::string::npos) << bad.out;
  EXPECT_EQ(j["warning"].find("energy balance"), std::string::npos) << bad.out;
  EXPECT_NE(bad.err.find("use solver.integrator generalized_alpha"), std::string::npos) << bad.err;
  const CliRun half = runCli("--scene " + jlay + " --set solver.integrator=generalized_alpha --set solver.rho_inf=0.8");
  EXPECT_NE(half.err.find("lower solver.rho_inf (now 0.8"), std::string::npos) << half.err;
  const CliRun good = runCli("--scene " + jlay + " --set solver.integrator=generalized_alpha --set solver.rho_inf=0");
  EXPECT_EQ(good.code, 0) << good.err;
  j.clear();
  ASSERT_TRUE(parseFlatJson(good.out, j)) << good.out;
  EXPECT_EQ(j["status"], "ok") << good.out;
  EXPECT_LT(std::stod(j["force_noise_top"]), 0.03) << good.out;
}

// catkin_add_gtest links gtest without gtest_main here; a main of our own works either way.
int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
