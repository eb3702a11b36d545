// Sea terms in motion: a horizontal line sinking at the terminal velocity of quadratic drag, and the
// period of a submerged hanging line scaled by the added mass and the buoyancy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <yaml-cpp/yaml.h>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

constexpr double kG = 9.81;
constexpr double kRhoW = 1025.0, kRhoR = 7850.0;
constexpr double kDout = 0.3, kDin = 0.26;
const double kAout = M_PI / 4 * kDout * kDout, kAin = M_PI / 4 * kDin * kDin, kAwall = kAout - kAin;
const double kWallMass = kRhoR * kAwall;                                // [kg/m]
const double kSubmergedWeight = (kRhoR * kAwall - kRhoW * kAout) * kG;  // w [N/m]

// --- terminal velocity ----------------------------------------------------------------------------------
// A horizontal line sinking broadside in still water obeys (m + m_a) v' = w − k v², k = ½ ρ_w D C_D,
// m_a = (C_M − 1) ρ_w A_out: v(t) = v_t tanh(t/τ), v_t = sqrt(w/k), τ = (m + m_a)/(k v_t). The top of
// the line is always prescribed, so we prescribe it to sink exactly like that (velocity knots every
// 5 ms). If the model's weight, buoyancy, drag and added mass balance as the formula says, the line
// follows the top without any force at the hang-off and stays horizontal; an error of 1 % in the load
// or the inertia leaves a top force and makes the line rotate about its top.
struct SinkResult {
  double max_top_force = 0.0;  // relative to w L
  double tilt = 0.0;           // |y_end − y_top| at the end [m]
  double v_end = 0.0;          // prescribed top velocity at the end [m/s]
};

SinkResult sink(double velocity_scale, double cm) {
  const double L = 20.0, cd = 1.0;
  Scene s = parseScene(
      YAML::Load("line: {length: 20, elements: 10, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
                 " density: 7850, axial_flexibility: false}\n"
                 "environment: {water: {density: 1025, surface: 0}}\n"
                 "hydrodynamics: {drag_normal: 1.0, drag_tangential: 0.0, inertia_coefficient: " +
                 std::to_string(cm) + "}\n"));
  const double k = 0.5 * kRhoW * kDout * cd, w = kSubmergedWeight;
  const double vt = std::sqrt(w / k), tau = (kWallMass + (cm - 1.0) * kRhoW * kAout) / (k * vt);
  std::vector<VelocityProfileMotion::Knot> knots;
  const double T = 8.0 * tau;  // tanh(8) = 1 − 2e-7: at the terminal velocity
  for (double t = 0.0; t <= T + 1e-12; t += 0.005)
    knots.push_back({t, Vec2(0.0, -velocity_scale * vt * std::tanh(t / tau))});
  const Vec2 top(0.0, -10.0);
  auto model = buildModel(s);
  Simulator sim(model, std::make_unique<VelocityProfileMotion>(top, knots), s.solver);
  sim.setInitialState(straightLine(*model, top, 0.0), 0.0);  // horizontal, at rest
  SinkResult r;
  while (sim.time() < T - 1e-9) {
    if (!sim.advanceTo(sim.time() + 0.05)) ADD_FAILURE() << sim.divergenceReason();
    r.max_top_force = std::max(r.max_top_force, sim.outputs().top_force.norm() / (w * L));
  }
  const LineOutputs& o = sim.outputs();
  r.tilt = std::abs(o.points.back().y() - o.points.front().y());
  r.v_end = sim.topMotion().at(sim.time()).v.y();
  std::printf("scale %.2f C_M %.1f: v_t %.4f m/s tau %.3f s, max |F_top|/(wL) %.2e, tilt %.2e m\n", velocity_scale, cm,
              vt, tau, r.max_top_force, r.tilt);
  return r;
}

TEST(HydroDynamics, HorizontalLineSinksAtTheTerminalVelocity) {
  for (double cm : {1.0, 2.0}) {  // the approach depends on C_M, the terminal velocity does not
    const SinkResult r = sink(1.0, cm);
    // Knot spacing 5 ms: the piecewise-linear velocity's acceleration differs from tanh's by up to
    // ½ Δt |v''| ≈ 0.3 % of w/(m + m_a); measured max top force 1e-3 w L. 5e-3 leaves margin and
    // is still below what a 2 % velocity error leaves (checked below).
    EXPECT_LT(r.max_top_force, 5e-3);
    EXPECT_LT(r.tilt, 1e-2);  // [m] on L = 20 m: stays horizontal (rotation < 5e-4 rad)
    EXPECT_NEAR(-r.v_end / std::sqrt(kSubmergedWeight / (0.5 * kRhoW * kDout)), 1.0, 1e-6);
  }
  // Control: prescribing 2 % too fast a sinking leaves 4 % of the weight unbalanced; the line tilts.
  const SinkResult wrong = sink(1.02, 2.0);
  EXPECT_GT(wrong.tilt, 0.1);
}

// --- added mass --------------------------------------------------------------------------------------
// A line hanging from a fixed top (inextensible, no bending, no drag) swinging with a small amplitude:
// the motion is lateral to first order, the restoring force is the tension, set by the submerged weight
// w, and the inertia is the mass per length m plus, in the normal direction, m_a = (C_M − 1) ρ_w A_out.
// Every mode then has ω² ∝ w / ((m + m_a) L), so the whole motion is the same in the time t·sqrt(w/(m+m_a)):
// the k-th zero crossing of x_end scales by sqrt((m + m_a)/m) between C_M = 1 and C_M, and by
// sqrt(m g / w) between air and water (C_M = 1).
std::vector<double> crossings(const std::string& env_hydro) {
  Scene s = parseScene(
      YAML::Load("line: {length: 20, elements: 10, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
                 " density: 7850, axial_flexibility: false, bending: false}\n"
                 "top: {position: [0, -1]}\n"
                 "initial: {type: displaced, end_dx: 0.2}\n"
                 "solver: {dt: 1e-3}\n" +
                 env_hydro));
  auto sim = buildSimulator(s);
  std::vector<double> t, x;
  while (sim->time() < 40.0 - 1e-9) {
    if (!sim->step()) ADD_FAILURE() << sim->divergenceReason();
    t.push_back(sim->time());
    x.push_back(sim->outputs().points.back().x());
  }
  return validation::zeroCrossings(t, x);
}

TEST(HydroDynamics, AddedMassAndBuoyancyScaleThePeriod) {
  const std::string water = "environment: {water: {density: 1025, surface: 0}}\n";
  const auto air = crossings("");
  const auto cm1 = crossings(water + "hydrodynamics: {inertia_coefficient: 1.0}\n");
  const auto cm15 = crossings(water + "hydrodynamics: {inertia_coefficient: 1.5}\n");
  const auto cm2 = crossings(water + "hydrodynamics: {inertia_coefficient: 2.0}\n");
  ASSERT_GE(air.size(), 4u);
  ASSERT_GE(cm2.size(), 3u);
  const double m = kWallMass, ma = kRhoW * kAout;
  const double buoy = std::sqrt(m * kG / kSubmergedWeight);
  const double f15 = std::sqrt((m + 0.5 * ma) / m), f2 = std::sqrt((m + ma) / m);
  // The second zero crossing (~1 period of the fundamental) is compared; later crossings can be
  // near-tangent wiggles of the higher modes (the third one moves by 0.4 s between n = 10 and 20) and
  // are not a robust measure. Measured at n = 10: buoyancy 1.45038 vs 1.45038, C_M = 2: 1.23456 vs
  // sqrt((m + m_a)/m) = 1.23476. Tolerance 1e-3: the amplitude (0.2 m on 20 m, θ = 0.01 rad) brings
  // O(θ²) tangential motion that the normal-only added mass does not scale, and m_a is lumped at the
  // part centroids (no rotational added inertia of the parts), O((d/L)²/12); a missing added mass is
  // a 23 % error.
  const int k = 1;
  std::printf("crossing %d: air %.4f  C_M=1 %.4f (ratio %.5f, expected %.5f)  1.5: %.5f (%.5f)  2: %.5f (%.5f)\n",
              k + 1, air[k], cm1[k], cm1[k] / air[k], buoy, cm15[k] / cm1[k], f15, cm2[k] / cm1[k], f2);
  EXPECT_NEAR(cm1[k] / air[k] / buoy, 1.0, 1e-3);
  EXPECT_NEAR(cm15[k] / cm1[k] / f15, 1.0, 1e-3);
  EXPECT_NEAR(cm2[k] / cm1[k] / f2, 1.0, 1e-3);
}

}  // namespace
}  // namespace riser_sim
