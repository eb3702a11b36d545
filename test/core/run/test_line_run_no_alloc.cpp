// LineRun (line_run.h) steps and fills its outputs without allocating, over both engines: the planar
// adapter and the 3D one (with torsion: the material frames), each stepped and read (outputs() with its frames,
// bending moments and energy drift) after a warm-up, and with a live top fed a sample every step.
// Global operator new is replaced by a counting one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene_yaml.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

constexpr int kWarmup = 3, kCounted = 30;

long countAllocations(const std::string& scene_file, const std::vector<std::string>& overrides, bool live = false) {
  const Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/" + scene_file, overrides);
  LineRunInputs in;
  if (live) in.top = HolderStart{buildLineRun(scene)->outputs().top_point, Eigen::Quaterniond::Identity(), 0.0};
  auto run = buildLineRun(scene, in);
  double sum = 0.0;
  const auto feed = [&](int k) {  // the top drifts 1 mm per step along x, rolling slowly
    if (!live) return;
    const Eigen::Quaterniond q(Eigen::AngleAxisd(1e-4 * k, Vec3::UnitX()));
    EXPECT_TRUE(run->addSample(Holder::kTop, (k + 1) * run->dt(), in.top->point + Vec3(1e-3 * k, 0.0, 0.0), q));
  };
  for (int k = 0; k < kWarmup; ++k) {
    feed(k);
    EXPECT_TRUE(run->step()) << run->divergenceReason();
    sum += run->outputs().top_tension;
  }
  const long before = g_allocations.load();
  bool ok = true;
  for (int k = 0; k < kCounted && ok; ++k) {
    feed(kWarmup + k);
    ok = run->step();
    const RunOutputs& o = run->outputs();
    sum += o.top_tension + o.energy_drift + o.springs.back().z() + o.axial_force.front() + o.frames.back().w() +
           o.bending_moment_vector.back().norm() + o.curvature.front() + o.elongations.back();
  }
  const long allocations = g_allocations.load() - before;
  EXPECT_TRUE(ok) << run->divergenceReason();
  EXPECT_TRUE(std::isfinite(sum));
  return allocations;
}

TEST(LineRunNoAlloc, PlanarStepAndOutputs) { EXPECT_EQ(countAllocations("hanging_chain.yaml", {}), 0); }

TEST(LineRunNoAlloc, SpatialStepAndOutputs) { EXPECT_EQ(countAllocations("spatial_swing.yaml", {}), 0); }

TEST(LineRunNoAlloc, LiveTopsAndMaterialFrames) {
  EXPECT_EQ(countAllocations("hanging_chain.yaml", {}, true), 0);
  EXPECT_EQ(countAllocations("spatial_swing.yaml", {"line.torsion={stiffness: 200.0, polar_inertia: 0.01}"}, true), 0);
}

}  // namespace
}  // namespace riser_sim
