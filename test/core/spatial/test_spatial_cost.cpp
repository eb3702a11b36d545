// Step cost of the spatial natural formulation against the planar absolute one on the same planar scene
// (rk4, n = 10 and 100): median µs per step. A measurement, not a test (disabled; run with
// --gtest_also_run_disabled_tests): timings depend on the machine and its load.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using Clock = std::chrono::steady_clock;

constexpr double kStep = 1e-5;  // [s] rk4-stable at n = 100 (axial ω ~ 1e4 rad/s)
constexpr int kSteps = 3000;

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void measure(int n) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = n;
  auto m2 = spatial_test::planarModel(s);
  const Kinematics kin0 =
      spatial_test::planarChain(*m2, Vec2::Zero(), std::vector<double>(m2->bodies(), -M_PI / 2 + 0.35));
  auto top = [] { return spatial_test::topSway(Vec2(0.5, 0.0), 2.0); };
  spatial_test::PlanarOde ode2(m2, top());
  Rk4 rk2;
  VecX y2 = ode2.state(kin0);
  rk2.reset(StateLayout{int(y2.size()), m2->dofs()});
  auto m3 = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  Simulator3 sim(m3, std::make_unique<PlanarMotion3>(top()), IntegratorKind::kRk4);
  sim.reset(fromPlanar(kin0), 0.0);
  std::vector<double> t2(kSteps), t3(kSteps);
  double t = 0.0;
  for (int k = 0; k < kSteps; ++k, t += kStep) {
    const auto a = Clock::now();
    rk2.step(ode2, t, y2, kStep);
    const auto b = Clock::now();
    sim.step(kStep);
    const auto c = Clock::now();
    t2[k] = std::chrono::duration<double, std::micro>(b - a).count();
    t3[k] = std::chrono::duration<double, std::micro>(c - b).count();
  }
  const double c2 = median(t2), c3 = median(t3);
  std::printf("[spatial cost] n = %d, rk4: planar absolute %.2f us/step, spatial natural %.2f us/step, ratio %.2f\n", n,
              c2, c3, c3 / c2);
  EXPECT_TRUE(y2.allFinite() && sim.state().allFinite());
}

TEST(SpatialCost, DISABLED_StepCostAgainstPlanarAbsolute) {
  measure(10);
  measure(100);
}

}  // namespace
}  // namespace riser_sim
