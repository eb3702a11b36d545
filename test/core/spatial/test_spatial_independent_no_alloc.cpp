// IndependentSimulator3::step() (rk4, free and pinned, chart switches included; torsion off, held and free
// top) and its per-step outputs allocate nothing after construction. Global operator new is replaced by a counting one.
#include <gtest/gtest.h>

#include "spatial_independent_util.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kStep = 1e-3;  // [s] rk4-stable at n = 10 (axial ω ≤ 900 rad/s: ω h ≤ 0.9)
constexpr int kWarmup = 3, kCounted = 300;

// torsion: 0 off, 1 held top, 2 free top.
long countAllocations(bool pinned, long* switches, int torsion = 0) {
  const spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  if (torsion > 0) {
    TorsionProperties t;
    t.stiffness = 1e3;
    t.polar_inertia = 0.05;
    t.damping = 2.0;
    t.free_top = torsion == 2;
    m->setTorsion(t);
  }
  std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.2, -1.0));
  const Kinematics3 kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3(0.0, 0.0, 0.5));
  if (pinned) m->setBottom(BottomBoundary::kPinned, kin0.back().end());
  IndependentSimulator3 sim(m, std::make_unique<spatial_test::OscillatingTop>(Vec3(0.5, 0.3, 0.1), Vec3(3, 4, 5)),
                            IntegratorKind::kRk4);
  sim.reset(kin0, 0.0);
  if (torsion > 0) sim.setTwist(VecX::LinSpaced(m->bodies(), 0.0, 1.0), VecX::Constant(m->bodies(), 2.0));
  sim.setChartThreshold(0.05);  // frequent switches
  AlignedVector<Vec3> p(m->bodies() + 1);
  for (int k = 0; k < kWarmup; ++k) EXPECT_TRUE(sim.step(kStep));
  const long before = g_allocations.load();
  double sink = 0.0;
  for (int k = 0; k < kCounted; ++k) {
    EXPECT_TRUE(sim.step(kStep));
    sim.positions(p);
    sink += sim.energy() + sim.work() + sim.constraintError() + sim.evaluate().reactions.top.norm();
  }
  const long count = g_allocations.load() - before;
  EXPECT_TRUE(std::isfinite(sink));
  *switches = sim.chartSwitches();
  return count;
}

TEST(SpatialIndependentNoAlloc, StepAllocatesNothing) {
  for (bool pinned : {false, true}) {
    long switches = 0;
    const long count = countAllocations(pinned, &switches);
    std::printf("[spatial independent no alloc] %s: %ld allocations in %d steps, %ld chart switches\n",
                pinned ? "pinned" : "free", count, kCounted, switches);
    EXPECT_EQ(count, 0);
    EXPECT_GT(switches, 0);
  }
  for (int torsion : {1, 2}) {  // the twist charts move with the sphere charts
    long switches = 0;
    const long count = countAllocations(false, &switches, torsion);
    std::printf("[spatial independent no alloc] torsion, %s top: %ld allocations in %d steps, %ld chart switches\n",
                torsion == 1 ? "held" : "free", count, kCounted, switches);
    EXPECT_EQ(count, 0);
    EXPECT_GT(switches, 0);
  }
}

}  // namespace
}  // namespace riser_sim
