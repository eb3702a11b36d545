// LineRun (line_run.h) steps and fills its outputs without allocating, over both engines: the planar
// adapter and the 3D one, each stepped and read (outputs() with its energy drift) after a warm-up.
// Global operator new is replaced by a counting one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "riser_sim/line_run.h"
#include "riser_sim/scene_yaml.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

constexpr int kWarmup = 3, kCounted = 30;

long countAllocations(const std::string& scene_file, const std::vector<std::string>& overrides) {
  const Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/" + scene_file, overrides);
  auto run = buildLineRun(scene);
  double sum = 0.0;
  for (int k = 0; k < kWarmup; ++k) {
    EXPECT_TRUE(run->step()) << run->divergenceReason();
    sum += run->outputs().top_tension;
  }
  const long before = g_allocations.load();
  bool ok = true;
  for (int k = 0; k < kCounted && ok; ++k) {
    ok = run->step();
    const RunOutputs& o = run->outputs();
    sum += o.top_tension + o.energy_drift + o.springs.back().z() + o.axial_force.front();
  }
  const long allocations = g_allocations.load() - before;
  EXPECT_TRUE(ok) << run->divergenceReason();
  EXPECT_TRUE(std::isfinite(sum));
  return allocations;
}

TEST(LineRunNoAlloc, PlanarStepAndOutputs) {
  EXPECT_EQ(countAllocations("hanging_chain.yaml", {}), 0);
}

TEST(LineRunNoAlloc, SpatialStepAndOutputs) {
  EXPECT_EQ(countAllocations("spatial_swing.yaml", {}), 0);
}

}  // namespace
}  // namespace riser_sim
