// line.axial_damping_ratio: each element's damper from the damping ratio ζ of its own axial mode, the spring
// k_i = EA / l_i between its two halves (m_r = m1 m2 / (m1 + m2)). Reference: for a uniform line both halves
// are μ l / 2, so m_r = μ l / 4 and c_i = 2 ζ sqrt(k_i m_r) = ζ sqrt(EA μ) for every element, the half-length
// ends included, whatever l (closed form, by hand). The end mass is not part of the element's mode. Also the
// keys, and what it damps (the element modes, hardly the line's lowest one).
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/planar/model.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/simulator.h"

namespace riser_sim {
namespace {

TEST(AxialDampingRatio, EveryElementGetsTheRatioOfItsOwnMode) {
  LineProperties p;
  p.EA = 3e8;
  p.mass_per_length = 90.0;
  p.content_mass_per_length = 30.0;  // moves with the pipe: part of the element's mass
  p.axial_damping_ratio = 0.05;
  const Model m(100.0, 7, p, ModelOptions(), 400.0, 9.81);
  const double expected = 0.05 * std::sqrt(p.EA * (p.mass_per_length + p.content_mass_per_length));
  for (int i = 0; i < m.bodies(); ++i) EXPECT_NEAR(m.rfe(i).axial_damping, expected, 1e-12 * expected) << "rfe " << i;
  // Added to a given coefficient (the model allows both; a scene gives one).
  p.axial_damping = 2e5;
  const Model both(100.0, 7, p, ModelOptions(), 0.0, 9.81);
  EXPECT_NEAR(both.rfe(3).axial_damping, expected + 2e5 / both.rfe(3).length, 1e-12 * expected);
}

// What the ratio damps: element-level damping is stiffness-proportional in effect (c_i / k_i = ζ l_i / c_w,
// c_w = sqrt(EA / μ)), so the line's own axial mode k gets ζ_k = ζ d ω_k / (2 c_w): the element modes near ζ,
// the lowest one only ζ π / (4 n) (0.8 % at ζ = 0.1, n = 10). A line hanging from a fixed top released
// unstretched rings axially; the top force's ring over the 2nd second falls as ζ grows, but the lowest mode
// (ω_1 = π c_w / 2L = 14 rad/s) keeps e^{-ζ_1 ω_1 t} ~ 0.9 of it per second at ζ = 0.1: bounds from that.
TEST(AxialDampingRatio, DampsTheElementModesNotTheLineMode) {
  const std::string base = R"(line: {length: 50.0, elements: 10, EA: 1.0e7, EI: 1.0e3, mass_per_length: 50.0}
initial: {type: straight, angle: -90.0}
solver: {integrator: rk4, dt: 0.0005}
)";
  double ring[3];
  const double zetas[3] = {0.0, 0.02, 0.1};
  for (int r = 0; r < 3; ++r) {
    const Scene s = loadSceneText(base, "ratio", {"line.axial_damping_ratio=" + std::to_string(zetas[r])});
    std::unique_ptr<Simulator> sim = buildSimulator(s);
    double lo = 1e300, hi = -1e300;
    for (int k = 1; k <= 4000; ++k) {
      ASSERT_TRUE(sim->step());
      if (k <= 2000) continue;
      const double T = sim->outputs().top_tension;
      lo = std::min(lo, T), hi = std::max(hi, T);
    }
    ring[r] = hi - lo;
  }
  const double W = 50.0 * 50.0 * 9.81;
  EXPECT_GT(ring[0], 0.1 * W);  // undamped: the drop rings on
  EXPECT_LT(ring[1], 0.99 * ring[0]);
  EXPECT_LT(ring[2], 0.9 * ring[1]);
  EXPECT_GT(ring[2], 0.5 * ring[0]);  // the lowest mode is barely damped (ζ_1 = 0.8 %)
  std::printf("[ measured ] top-force ring over the 2nd second: %.4g N (zeta 0), %.4g (0.02), %.4g (0.1); W = %.4g N\n",
              ring[0], ring[1], ring[2], W);
}

TEST(AxialDampingRatio, Keys) {
  const std::string line = "line: {length: 50.0, elements: 10, EA: 1.0e7, EI: 1.0e3, mass_per_length: 50.0";
  EXPECT_EQ(loadSceneText(line + ", axial_damping_ratio: 0.03}\n", "k").line.axial_damping_ratio, 0.03);
  for (const std::string& bad : {std::string(", axial_damping_ratio: 3}"), std::string(", axial_damping_ratio: -0.1}"),
                                 std::string(", axial_damping: 1.0e4, axial_damping_ratio: 0.03}")}) {
    try {
      loadSceneText(line + bad + "\n", "k");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("line.axial_damping_ratio"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace riser_sim
