// Step cost of the spatial independent formulation (dense, O(n³)) against the natural one (O(n)) on the
// same 3D scene (rk4, n = 10 and 50): median µs per step. A measurement, not a test (disabled; run with
// --gtest_also_run_disabled_tests): timings depend on the machine and its load.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "spatial_independent_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using Clock = std::chrono::steady_clock;

constexpr double kStep = 2e-5;  // [s] rk4-stable at n = 50 (axial ω ~ 5e3 rad/s)
constexpr int kSteps = 2000;

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void measure(int n) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = n;
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  const std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.2, -1.0).normalized());
  const Kinematics3 kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
  auto top = [] { return std::make_unique<spatial_test::OscillatingTop>(Vec3(0.5, 0.4, 0.2), Vec3(3.0, 5.0, 2.0)); };
  Simulator3 nat(m, top(), IntegratorKind::kRk4);
  IndependentSimulator3 ind(m, top(), IntegratorKind::kRk4);
  nat.reset(kin0, 0.0);
  ind.reset(kin0, 0.0);
  std::vector<double> tn(kSteps), ti(kSteps);
  for (int k = 0; k < kSteps; ++k) {
    const auto a = Clock::now();
    nat.step(kStep);
    const auto b = Clock::now();
    ind.step(kStep);
    const auto c = Clock::now();
    tn[k] = std::chrono::duration<double, std::micro>(b - a).count();
    ti[k] = std::chrono::duration<double, std::micro>(c - b).count();
  }
  const double cn = median(tn), ci = median(ti);
  std::printf("[spatial independent cost] n = %d, rk4: natural %.2f us/step, independent %.2f us/step, ratio %.1f\n", n,
              cn, ci, ci / cn);
  EXPECT_TRUE(nat.state().allFinite() && ind.state().allFinite());
}

TEST(SpatialIndependentCost, DISABLED_StepCostAgainstNatural) {
  measure(10);
  measure(50);
}

}  // namespace
}  // namespace riser_sim
