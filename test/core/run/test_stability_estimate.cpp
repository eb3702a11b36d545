// The explicit step limit counts damping: RK4's stability region along each Ritz value's direction,
// checked against the region's known radii, a matrix with a known spectrum, and runs of the demo
// riser (inextensible, bending damping c_EI) over damping x n: "safe" is safe (0.9x the estimate runs)
// and not uselessly small (2x diverges).
#include <gtest/gtest.h>

#include "riser_sim/integrators/integrator.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/run/stability_estimate.h"

namespace riser_sim {
namespace {

const std::string kDemo = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/demo_riser.yaml";

Complex rk4(Complex z) { return Rk4().stabilityFunction(z); }

// RK4's region reaches 2.7853 on the negative real axis and 2√2 on the imaginary one (Hairer &
// Wanner, Solving ODEs II, IV.2); bisection to 1e-6.
TEST(StabilityEstimate, Rk4RegionRadii) {
  EXPECT_NEAR(stabilityRadius(rk4, M_PI), 2.785293563, 1e-6);
  EXPECT_NEAR(stabilityRadius(rk4, M_PI / 2), 2.0 * std::sqrt(2.0), 1e-6);
}

// A damped oscillator block and a fast real mode: Arnoldi on a 4x4 operator is exact (invariant
// subspace), so the step is the analytic min over the eigenvalues.
TEST(StabilityEstimate, KnownSpectrum) {
  MatX J = MatX::Zero(4, 4);
  J(0, 1) = 1.0;
  J(1, 0) = -100.0;  // ω = 10
  J(1, 1) = -2.0;    // ζ = 0.1
  J(2, 2) = -500.0;  // a damping-dominated mode
  J(3, 3) = -1.0;
  const auto ritz = ritzValues(4, 10, [&](const VecX& x, VecX& out) { out = J * x; });
  ASSERT_EQ(ritz.size(), 4u);
  const double h = largestStableStep(ritz, rk4);
  EXPECT_NEAR(h, 2.785293563 / 500.0, 1e-8);  // the real mode: |λ| 500 against ~10 for the oscillator
}

struct Case {
  int n;
  double damping;  // line.bending_damping [N m^2 s]
};

std::string runStatus(const Case& c, double dt) {
  Scene s = loadSceneFile(
      kDemo, {"line.elements=" + std::to_string(c.n), "line.bending_damping=" + std::to_string(c.damping)});
  s.solver.dt = dt;
  auto sim = buildSimulator(s);
  // 3000 steps or 1 s, whichever is longer: a too-large step grows by orders of magnitude within it.
  const double t_end = std::max(1.0, 3000 * dt);
  sim->advanceTo(t_end);
  return sim->diverged() ? "diverged: " + sim->divergenceReason() : "ok";
}

double estimate(const Case& c) {
  Scene s = loadSceneFile(
      kDemo, {"line.elements=" + std::to_string(c.n), "line.bending_damping=" + std::to_string(c.damping)});
  return buildSimulator(s)->stableStepEstimate();
}

// Before damping counted, n = 70 estimated 3.3 ms and diverged at 2 ms; n = 100 estimated 1.28 ms and
// diverged at 1 and 0.5 ms.
TEST(StabilityEstimate, SafeStepIsSafeOverDampingAndN) {
  for (const Case c :
       {Case{10, 0.0}, Case{30, 0.0}, Case{10, 2e5}, Case{30, 2e5}, Case{70, 2e5}, Case{100, 2e5}, Case{30, 2e6}}) {
    const double h = estimate(c);
    SCOPED_TRACE("n = " + std::to_string(c.n) + ", c_EI = " + std::to_string(c.damping) + ", estimate " +
                 std::to_string(h) + " s");
    EXPECT_EQ(runStatus(c, 0.9 * h), "ok");
    EXPECT_NE(runStatus(c, 2.0 * h), "ok") << "the estimate is more than 2x below the real limit";
  }
}

}  // namespace
}  // namespace riser_sim
