// The spatial stepping allocates nothing after construction: Simulator3::step() with rk4, dopri5
// and generalized_alpha (dense Jacobian), free and pinned, and the per-step outputs (energy, positions,
// constraint error, one evaluation for the reactions). Global operator new is replaced by a counting one.
#include <gtest/gtest.h>

#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kStep = 1e-3;  // [s] rk4-stable at n = 10 (axial ω ≤ 900 rad/s: ω h ≤ 0.9)
constexpr int kWarmup = 3, kCounted = 30;

// moving: the bottom pinned to a sinusoid, flex joints at both ends.
long countAllocations(IntegratorKind kind, bool pinned, bool moving = false) {
  const spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0.3, 0.2, -s.g));
  std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.2, -1.0));
  const Kinematics3 kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
  if (pinned) m->setBottom(BottomBoundary::kPinned, kin0.back().end());
  if (moving) {
    const Vec3 amp(0.3, 0.2, 0.1);
    m->setBottomMotion(std::make_shared<SinusoidMotion3>(kin0.back().end() - amp, amp, 2.0, Vec3::Zero()));
    m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, Vec3(0, 0, -1), 1e3, 10.0));
    m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kBottom, Vec3(0, 0, 1), 1e3, 10.0));
  }
  IntegratorOptions options;
  options.jacobian = JacobianKind::kDense;  // the structured solves: test_spatial_shifted_no_alloc.cpp
  options.tolerance = 1e-8;
  Simulator3 sim(m, std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 2.0)), kind, options);
  sim.reset(kin0, 0.0);
  AlignedVector<Vec3> p(m->bodies() + 1);
  for (int k = 0; k < kWarmup; ++k) EXPECT_TRUE(sim.step(kStep));
  const long before = g_allocations.load();
  double sink = 0.0;
  for (int k = 0; k < kCounted; ++k) {
    EXPECT_TRUE(sim.step(kStep)) << sim.integrator().failure();
    sim.positions(p);
    sink += sim.energy() + sim.work() + sim.constraintError() + sim.evaluate().reactions.top.norm();
  }
  const long count = g_allocations.load() - before;
  EXPECT_TRUE(std::isfinite(sink));
  return count;
}

TEST(SpatialNoAlloc, Rk4Free) { EXPECT_EQ(countAllocations(IntegratorKind::kRk4, false), 0); }
TEST(SpatialNoAlloc, Rk4Pinned) { EXPECT_EQ(countAllocations(IntegratorKind::kRk4, true), 0); }
TEST(SpatialNoAlloc, Dopri5Pinned) { EXPECT_EQ(countAllocations(IntegratorKind::kDopri5, true), 0); }
TEST(SpatialNoAlloc, GeneralizedAlphaDense) {
  EXPECT_EQ(countAllocations(IntegratorKind::kGeneralizedAlpha, false), 0);
}

TEST(SpatialNoAlloc, Rk4MovingBottomFlexJoints) { EXPECT_EQ(countAllocations(IntegratorKind::kRk4, true, true), 0); }

// The counter counts (the test above could not pass by a dead counter).
TEST(SpatialNoAlloc, CounterCounts) {
  const long before = g_allocations.load();
  auto v = std::make_unique<VecX>(100);
  EXPECT_GT(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace riser_sim
