// Step cost of implicit midpoint on the spatial natural formulation with structured (O(n)) and dense
// (finite-difference Jacobian) solves, against the 2D recursive formulation's structured midpoint on the
// same planar scene, n = 10, 100, 300: median µs per step. A measurement, not a test (disabled; run with
// --gtest_also_run_disabled_tests): timings depend on the machine and its load.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "riser_sim/planar/simulator.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using Clock = std::chrono::steady_clock;

constexpr double kStep = 1e-3;  // [s]

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Cost {
  double us = 0.0, newton = 0.0;
};

template <class StepFn>
Cost timeSteps(int steps, StepFn&& step) {
  std::vector<double> t(steps);
  for (int k = 0; k < steps; ++k) {
    const auto a = Clock::now();
    EXPECT_TRUE(step());
    t[k] = std::chrono::duration<double, std::micro>(Clock::now() - a).count();
  }
  return Cost{median(t), 0.0};
}

void measure(int n, bool with_dense) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = n;
  auto m2 = spatial_test::planarModel(s);
  const Kinematics kin0 =
      spatial_test::planarChain(*m2, Vec2::Zero(), std::vector<double>(m2->bodies(), -M_PI / 2 + 0.35));
  auto top = [] { return spatial_test::topSway(Vec2(0.5, 0.0), 2.0); };
  const int steps = n >= 300 ? 30 : 60;

  SolverSettings st;
  st.dt = kStep;
  st.integrator = IntegratorKind::kMidpoint;
  st.formulation = FormulationKind::kRecursive;
  st.jacobian = JacobianKind::kStructured;
  Simulator sim2(m2, top(), st);
  sim2.setInitialState(kin0, 0.0);
  const Cost c2 = timeSteps(steps, [&] { return sim2.step(); });

  auto spatialCost = [&](JacobianKind jac) {
    auto m3 = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
    IntegratorOptions o;
    o.jacobian = jac;
    Simulator3 sim(m3, std::make_unique<PlanarMotion3>(top()), IntegratorKind::kMidpoint, o);
    sim.reset(fromPlanar(kin0), 0.0);
    Cost c = timeSteps(steps, [&] { return sim.step(kStep); });
    c.newton = double(sim.integrator().stats().newton) / steps;
    return c;
  };
  const Cost cs = spatialCost(JacobianKind::kStructured);
  const Cost cd = with_dense ? spatialCost(JacobianKind::kDense) : Cost{};
  std::printf(
      "[spatial shifted cost] n = %d, midpoint h = 1e-3 s: 3D structured %.0f us/step (%.2f Newton/step), "
      "3D dense %.0f us/step (%.2f Newton/step, median: between refreshes), 2D recursive structured %.0f us/step\n",
      n, cs.us, cs.newton, cd.us, cd.newton, c2.us);
}

TEST(SpatialShiftedCost, DISABLED_MidpointStepCost) {
  measure(10, true);
  measure(100, true);
  measure(300, true);
}

// Without the dense runs (for a profiler).
TEST(SpatialShiftedCost, DISABLED_MidpointStepCostStructured) {
  measure(100, false);
  measure(300, false);
}

}  // namespace
}  // namespace riser_sim
