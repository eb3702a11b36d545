// The start's statics report their progress through buildLineRun (LineRunInputs::statics_progress) in both engines:
// every Newton iteration of the planar statics (the 3D start solves them in its plane first), the iterations
// counting up and the last report's residual the solved one's order.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

struct Report {
  std::string stage;
  int iterations;
  double residual, seconds;
};

std::vector<Report> startOf(const std::string& scene_file) {
  std::vector<Report> reports;
  LineRunInputs in;
  in.statics_progress = [&](const std::string& stage, int iterations, double residual, double seconds) {
    reports.push_back({stage, iterations, residual, seconds});
  };
  const auto run = buildLineRun(loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/" + scene_file), in);
  EXPECT_GT(run->start().statics_iterations, 0) << scene_file;
  return reports;
}

TEST(LineRunStaticsProgress, BothEnginesReportTheirStatics) {
  for (const char* scene : {"paper_table1.yaml", "demo_riser_3d.yaml"}) {
    const std::vector<Report> r = startOf(scene);
    ASSERT_FALSE(r.empty()) << scene << ": no progress reported";
    EXPECT_FALSE(r.front().stage.empty()) << scene;
    for (size_t k = 1; k < r.size(); ++k) EXPECT_GE(r[k].seconds, r[k - 1].seconds) << scene;
    EXPECT_LT(r.back().residual, 1e-6) << scene << ": the last report is the converged state's";
  }
}

}  // namespace
}  // namespace riser_sim
