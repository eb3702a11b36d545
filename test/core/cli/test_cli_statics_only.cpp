// --duration 0: the statics alone. No step is taken; the CSV holds the t = 0 row, the summary the initial
// state (status from the statics' and the outputs' checks), with rtf null and the step counts 0; both
// engines. The start is the one a longer run starts from.
#include <gtest/gtest.h>

#include "cli_test_util.h"

namespace {

using namespace cli_test;

TEST(CliStaticsOnly, DurationZeroReportsTheInitialStateWithoutSteps) {
  for (const char* scene : {"demo_riser.yaml", "spatial_swing.yaml"}) {
    SCOPED_TRACE(scene);
    const std::string csv = tempPath("statics_only.csv");
    const CliRun r = runCli("--scene " + kScenes + scene + " --duration 0 --summary --quiet --csv " + csv);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    auto j = summary(r);
    EXPECT_EQ(j["status"], "ok");
    EXPECT_EQ(j["steps"], "0");
    EXPECT_EQ(j["rtf"], "null");
    EXPECT_EQ(num(j, "sim_s"), 0.0);
    EXPECT_EQ(num(j, "t_last"), 0.0);
    EXPECT_EQ(num(j, "wall_s"), 0.0);
    EXPECT_EQ(num(j, "rhs_evaluations"), 0.0);
    EXPECT_EQ(num(j, "energy_drift"), 0.0);

    std::string header;
    const auto rows = csvRows(readFile(csv), header);
    EXPECT_EQ(header, kHeader);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0][0], 0.0);
    EXPECT_EQ(num(j, "x_end"), rows[0][kXEnd]);
    EXPECT_EQ(num(j, "z_end"), rows[0][kZEnd]);
    EXPECT_EQ(num(j, "tension_top"), rows[0][kTensionTop]);
    std::filesystem::remove(csv);

    // The same statics as a run's start.
    const CliRun run = runCli("--scene " + kScenes + scene + " --duration 0.01 --summary --quiet");
    ASSERT_EQ(run.code, 0) << run.err;
    auto k = summary(run);
    for (const char* key : {"statics_iterations", "statics_residual", "end_force_x", "end_force_z"})
      EXPECT_EQ(j[key], k[key]) << key;
  }
}

}  // namespace
