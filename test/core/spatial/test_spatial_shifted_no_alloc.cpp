// The implicit schemes with the spatial formulation's structured solves allocate nothing per step
// (midpoint, generalized_alpha, rosenbrock2; free and pinned). Global operator new is replaced by a
// counting one (as test_spatial_no_alloc.cpp).
#include <gtest/gtest.h>

#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kStep = 1e-3;  // [s]
constexpr int kWarmup = 3, kCounted = 30;

// moving: the bottom pinned to a sinusoid, flex joints at both ends.
long countAllocations(IntegratorKind kind, bool pinned, bool moving = false) {
  const spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0.3, 0.2, -s.g));
  std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.2, -1.0));
  for (int i = m->bodies() / 2; i < m->bodies(); ++i) dirs[i] = Vec3(-0.3, 0.1, -1.0);  // slack when pinned
  const Kinematics3 kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
  if (pinned) m->setBottom(BottomBoundary::kPinned, kin0.back().end());
  if (moving) {
    const Vec3 amp(0.3, 0.2, 0.1);
    m->setBottomMotion(std::make_shared<SinusoidMotion3>(kin0.back().end() - amp, amp, 2.0, Vec3::Zero()));
    m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, Vec3(0, 0, -1), 1e3, 10.0));
    m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kBottom, Vec3(0, 0, 1), 1e3, 10.0));
  }
  IntegratorOptions options;
  options.jacobian = JacobianKind::kStructured;
  Simulator3 sim(m, std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 2.0)), kind, options);
  sim.reset(kin0, 0.0);
  for (int k = 0; k < kWarmup; ++k) EXPECT_TRUE(sim.step(kStep));
  const long before = g_allocations.load();
  for (int k = 0; k < kCounted; ++k) EXPECT_TRUE(sim.step(kStep)) << sim.integrator().failure();
  const long count = g_allocations.load() - before;
  EXPECT_TRUE(sim.state().allFinite());
  return count;
}

TEST(SpatialShiftedNoAlloc, MidpointFree) { EXPECT_EQ(countAllocations(IntegratorKind::kMidpoint, false), 0); }
TEST(SpatialShiftedNoAlloc, MidpointPinned) { EXPECT_EQ(countAllocations(IntegratorKind::kMidpoint, true), 0); }
TEST(SpatialShiftedNoAlloc, GeneralizedAlphaPinned) {
  EXPECT_EQ(countAllocations(IntegratorKind::kGeneralizedAlpha, true), 0);
}
TEST(SpatialShiftedNoAlloc, Rosenbrock2Pinned) { EXPECT_EQ(countAllocations(IntegratorKind::kRosenbrock2, true), 0); }

TEST(SpatialShiftedNoAlloc, MidpointMovingBottomFlexJoints) {
  EXPECT_EQ(countAllocations(IntegratorKind::kMidpoint, true, true), 0);
}

TEST(SpatialShiftedNoAlloc, CounterCounts) {
  const long before = g_allocations.load();
  auto v = std::make_unique<VecX>(100);
  EXPECT_GT(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace riser_sim
