// Sea terms at rest: submerged weight at the top, the static drag shape in a uniform current (against
// an independently integrated cable), the seabed sinking under the weight per contact point, and
// terms that are off leave the core's results bit-for-bit unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <yaml-cpp/yaml.h>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

constexpr double kG = 9.81;
constexpr double kRhoW = 1025.0, kRhoR = 7850.0, kRhoF = 840.0;
constexpr double kDout = 0.3, kDin = 0.26;
const double kAout = M_PI / 4 * kDout * kDout, kAin = M_PI / 4 * kDin * kDin, kAwall = kAout - kAin;

// Steel pipe of Table 3's cross-section, L = 100 m, in water with the surface at y = 0. line_extra is
// appended inside line: {...}, env replaces the environment section, extra is appended.
Scene pipeScene(const std::string& line_extra, const std::string& extra,
                const std::string& env = "{water: {density: 1025, surface: 0}}") {
  const std::string yaml =
      "line: {length: 100, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
      " density: 7850, " +
      line_extra +
      "}\n"
      "environment: " +
      env + "\n" + extra;
  return parseScene(YAML::Load(yaml));
}

// --- vertical riser at rest -----------------------------------------------------------------------
// Top 1 m below the surface so that every rfe is fully submerged. Reference: statics of a straight
// vertical line, T_top = (ρ_r A_wall + ρ_f A_in − ρ_w A_out) g L + m_s g (the point end mass has no
// volume, so no buoyancy).
TEST(HydroStatics, VerticalRiserTopTensionIsSubmergedWeight) {
  const double m_s = 500.0, L = 100.0;
  const double expected = (kRhoR * kAwall + kRhoF * kAin - kRhoW * kAout) * kG * L + m_s * kG;
  for (bool extensible : {false, true}) {
    const Scene s =
        pipeScene(std::string("elements: 20, end_mass: 500, axial_flexibility: ") + (extensible ? "true" : "false"),
                  "internal_fluid: {density: 840}\n"
                  "top: {position: [0, -1]}\n");
    auto sim = buildSimulator(s);
    const LineOutputs& o = sim->outputs();
    // Inextensible: exact up to the statics tolerance (1e-9 of the weight). Extensible: the displaced
    // volume follows the stretched length (A_out constant, no Poisson effect), so buoyancy grows by
    // the mean strain T/(2EA) ≈ 1e-5; 5e-5 bounds it.
    const double tol = extensible ? 5e-5 : 1e-9;
    EXPECT_NEAR(o.top_tension / expected, 1.0, tol) << "extensible=" << extensible;
    EXPECT_NEAR(o.top_force.x(), 0.0, 1e-9 * expected);
    EXPECT_LT(o.top_force.y(), 0.0);  // the line pulls the hang-off down
    // It stays at rest: 1 s of dynamics changes the tension by round-off only (relative 1e-9).
    ASSERT_TRUE(sim->advanceTo(1.0));
    EXPECT_NEAR(sim->outputs().top_tension / expected, 1.0, tol + 1e-9);
  }
}

// Partly emerged top rfe: the top at y = +1 m leaves the top 1 m of the line in air.
TEST(HydroStatics, TopPartlyInAirCarriesItsWeightInAir) {
  const Scene s = pipeScene("elements: 20, axial_flexibility: false", "top: {position: [0, 1]}\n");
  auto sim = buildSimulator(s);
  const double expected = (kRhoR * kAwall * 100.0 - kRhoW * kAout * 99.0) * kG;
  EXPECT_NEAR(sim->outputs().top_tension / expected, 1.0, 1e-9);  // statics tolerance
}

// --- static drag shape in a uniform current -------------------------------------------------------
// Independent reference: the inextensible cable equations integrated from the end upward,
// dP/ds = −f(t̂), t̂ = P/|P|, dr/ds = t̂, with P the force the upper part exerts on the lower part,
// P(0) = (0, m_s g) at the end and f = (0, −w) + k |U⊥| U⊥, U⊥ = U − (U·t̂) t̂, k = ½ ρ_w D C_D
// (normal drag only). The force on the hang-off is −P(L); the top is at r(L) from the end.
struct CableResult {
  Vec2 top_from_end, top_force;
};
CableResult dragCable(double L, double w, double W_end, double k, const Vec2& U, int steps) {
  auto f = [&](const Vec2& P) {
    const Vec2 t = P.normalized();
    const Vec2 up = U - U.dot(t) * t;
    return Vec2(Vec2(0.0, -w) + k * up.norm() * up);
  };
  Vec2 P(0.0, W_end), r = Vec2::Zero();
  const double h = L / steps;
  for (int k4 = 0; k4 < steps; ++k4) {  // RK4 on (P, r)
    const Vec2 kP1 = -f(P), kr1 = P.normalized();
    const Vec2 P2 = P + 0.5 * h * kP1, kP2 = -f(P2), kr2 = P2.normalized();
    const Vec2 P3 = P + 0.5 * h * kP2, kP3 = -f(P3), kr3 = P3.normalized();
    const Vec2 P4 = P + h * kP3, kP4 = -f(P4), kr4 = P4.normalized();
    P += h / 6 * (kP1 + 2 * kP2 + 2 * kP3 + kP4);
    r += h / 6 * (kr1 + 2 * kr2 + 2 * kr3 + kr4);
  }
  return {r, -P};
}

TEST(HydroStatics, UniformCurrentGivesTheDragCableShape) {
  const double L = 100.0, m_s = 500.0, U = 1.5, cd = 1.0;
  const double w = (kRhoR * kAwall - kRhoW * kAout) * kG, k = 0.5 * kRhoW * kDout * cd;
  const CableResult ref = dragCable(L, w, m_s * kG, k, Vec2(U, 0.0), 20000);
  double prev_err = 0.0;
  for (int n : {20, 40}) {
    const Scene s =
        pipeScene("elements: " + std::to_string(n) + ", end_mass: 500, axial_flexibility: false, bending: false",
                  "hydrodynamics: {drag_normal: 1.0, drag_tangential: 0.0}\n"
                  "top: {position: [0, -1]}\n",
                  "{water: {density: 1025, surface: 0}, current: {velocity: [1.5, 0]}}");
    auto sim = buildSimulator(s);  // the statics include the drag of the current on the line at rest
    const LineOutputs& o = sim->outputs();
    const Vec2 top_from_end = o.points.front() - o.points.back();
    const double err = (top_from_end - ref.top_from_end).norm() / L;
    std::printf("n=%d top-end (%.4f, %.4f) ref (%.4f, %.4f) Fx %.2f ref %.2f Fy %.2f ref %.2f err %.2e\n", n,
                top_from_end.x(), top_from_end.y(), ref.top_from_end.x(), ref.top_from_end.y(), o.top_force.x(),
                ref.top_force.x(), o.top_force.y(), ref.top_force.y(), err);
    // RFEM vs continuous cable: drag and weight lumped at part centroids, an O(d²) discretisation
    // error (measured 4.3e-4 L at n = 20, 1.5e-4 L at n = 40: order ~1.5). 1e-3 L bounds both.
    EXPECT_LT(err, 1e-3);
    // Horizontal reaction = integrated normal drag: against the continuous cable (same discretisation
    // error), and against the sum of the model's own drag forces on the static shape (global balance in
    // x: only the drag pushes sideways; exact up to the statics tolerance, 1e-9 of the weight).
    EXPECT_NEAR(o.top_force.x() / ref.top_force.x(), 1.0, 1e-3);
    EXPECT_NEAR(o.top_force.y() / ref.top_force.y(), 1.0, 1e-3);
    {
      const Model& model = sim->model();
      Kinematics kin(model.bodies());
      sim->kinematics(kin);
      VecX Q = VecX::Zero(model.dofs());
      ASSERT_NE(model.findTerm("morison_drag"), nullptr);
      model.findTerm("morison_drag")->addForces(model, nullptr, kin, 0.0, Q);
      double drag_x = 0.0;
      for (int i = 0; i < model.bodies(); ++i) drag_x += Q[4 * i + kX];
      const double weight = w * L + m_s * kG;
      EXPECT_NEAR(o.top_force.x(), drag_x, 1e-8 * weight) << "integrated drag " << drag_x;
      EXPECT_GT(drag_x, 0.01 * weight);  // the current really pushes (+x)
    }
    if (prev_err > 0.0) EXPECT_LT(err, 0.5 * prev_err);  // converges with n (measured ratio 0.34)
    prev_err = err;
    // The shape is an equilibrium of the dynamics: after 5 s the reaction moves by < 1e-6 of itself
    // (integration/round-off; a missing or mis-signed drag term would move it by O(1)).
    const Vec2 F0 = o.top_force;
    ASSERT_TRUE(sim->advanceTo(5.0));
    EXPECT_LT((sim->outputs().top_force - F0).norm() / F0.norm(), 1e-6);
  }
}

// --- seabed -----------------------------------------------------------------------------------------
// Inextensible line without bending lying straight on the seabed (top held at the seabed level). Each
// rfe's submerged weight goes half to each of its end points (rfe 0 and rfe n are half length):
// A_1 and A_n carry 3wd/4, A_2..A_{n-1} carry wd, the end point wd/4; each sinks by its load / C_y.
TEST(HydroStatics, LineOnSeabedSinksByWeightPerContactPointOverStiffness) {
  const double level = -80.0, Cy = 1e6, L = 100.0;
  const int n = 20;
  const double d = L / n;
  const Scene s = pipeScene("elements: 20, axial_flexibility: false, bending: false",
                            "seabed: {level: -80, stiffness_normal: 1.0e6, stiffness_tangential: 1.0e7,"
                            " damping_normal: 3.0e4, damping_tangential: 3.0e4}\n"
                            "top: {position: [0, -80]}\n"
                            "initial: {type: straight, angle: 0}\n"
                            "solver: {dt: 1e-3}\n");
  auto sim = buildSimulator(s);
  ASSERT_TRUE(sim->advanceTo(10.0));  // damping ~0.6 of critical per point: settled in ~1 s
  const LineOutputs& o = sim->outputs();
  const double w = (kRhoR * kAwall - kRhoW * kAout) * kG;
  for (int j = 1; j <= n + 1; ++j) {
    const double load = (j == 1 || j == n) ? 0.75 * w * d : (j == n + 1 ? 0.25 * w * d : w * d);
    const double sink = level - o.points[j].y();
    // Small-angle statics: the rfes tilt by ~(wd/C_y)/d ≈ 6e-4 rad, changing the load shares by
    // O(angle²) ~ 4e-7; 1e-4 relative also covers the residual decay after 10 s.
    EXPECT_NEAR(sink / (load / Cy), 1.0, 1e-4) << "contact point " << j;
  }
}

// --- displaced initial state: the end force released or held ---------------------------------------
// initial.end_force: hold keeps the statics' end force as a constant load, so the displaced state is an
// equilibrium: with the top fixed nothing moves (reference: the statics themselves; their residual
// 1e-9 of the weight moves the line by ~1e-9 m in 1 s). release lets the end swing back (metres).
TEST(HydroStatics, DisplacedEndHeldStaysReleasedSwings) {
  const std::string yaml =
      "line: {length: 100, elements: 10, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
      " density: 7850, end_mass: 200}\n"
      "environment: {water: {density: 1025, surface: 0}}\n"
      "hydrodynamics: {drag_normal: 0.7, inertia_coefficient: 2}\n"
      "solver: {dt: 1e-3}\n";
  double moved[2];
  for (int hold = 0; hold < 2; ++hold) {
    const Scene s = parseScene(
        YAML::Load(yaml + "initial: {type: displaced, end_dx: -30, end_force: " + (hold ? "hold" : "release") + "}\n"));
    auto sim = buildSimulator(s);
    EXPECT_EQ(sim->model().findTerm("end_load") != nullptr, hold == 1);
    const AlignedVector<Vec2> p0 = sim->outputs().points;
    ASSERT_TRUE(sim->advanceTo(1.0));
    moved[hold] = 0.0;
    for (size_t j = 0; j < p0.size(); ++j)
      moved[hold] = std::max(moved[hold], (sim->outputs().points[j] - p0[j]).norm());
  }
  std::printf("[hydro_statics] largest point motion in 1 s: released %.3g m, held %.3g m\n", moved[0], moved[1]);
  EXPECT_LT(moved[1], 1e-6);
  EXPECT_GT(moved[0], 0.1);
}

// --- terms that are off -------------------------------------------------------------------------------
std::vector<VecX> trajectory(const Scene& s, std::vector<std::string>* names) {
  auto sim = buildSimulator(s);
  if (names)
    for (const auto& t : sim->model().terms()) names->push_back(t->name());
  std::vector<VecX> out;
  for (int k = 1; k <= 20; ++k) {
    sim->advanceTo(0.1 * k);
    out.push_back(sim->state());
  }
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(HydroStatics, TermsThatAreOffAreNotBuiltAndChangeNothing) {
  const std::string base =
      "line: {length: 100, elements: 10, outer_diameter: 0.3, inner_diameter: 0.26, youngs_modulus: 2.07e11,"
      " density: 7850, end_mass: 200}\n"
      "environment: {water: {density: 1025, surface: 0}}\n"
      "initial: {type: displaced, end_dx: -30}\n"
      "solver: {dt: 1e-3}\n";
  std::vector<std::string> names_ref, names_off;
  const auto ref = trajectory(parseScene(YAML::Load(base)), &names_ref);
  // Drag 0, C_M = 1, no current, internal fluid at rest, a seabed far below the line.
  const auto off = trajectory(
      parseScene(YAML::Load(base + "hydrodynamics: {drag_normal: 0, drag_tangential: 0, inertia_coefficient: 1}\n"
                                   "internal_fluid: {density: 0, velocity: 0}\n")),
      &names_off);
  EXPECT_EQ(names_ref, names_off);
  EXPECT_FALSE(has(names_off, "morison_drag"));
  EXPECT_FALSE(has(names_off, "hydro_inertia"));
  EXPECT_FALSE(has(names_off, "internal_flow"));
  ASSERT_EQ(ref.size(), off.size());
  for (size_t k = 0; k < ref.size(); ++k) EXPECT_TRUE(ref[k] == off[k]) << "sample " << k;  // bit-for-bit

  // Internal fluid of density ρ_f at u = 0: only the content mass, no flow term.
  std::vector<std::string> names_fluid;
  trajectory(parseScene(YAML::Load(base + "internal_fluid: {density: 840, velocity: 0}\n")), &names_fluid);
  EXPECT_FALSE(has(names_fluid, "internal_flow"));

  // A seabed 1 km below: the term is built, never in contact, adds exact zeros.
  std::vector<std::string> names_bed;
  const auto bed = trajectory(
      parseScene(YAML::Load(base + "seabed: {level: -1000, stiffness_normal: 1e6, stiffness_tangential: 1e7}\n")),
      &names_bed);
  EXPECT_TRUE(has(names_bed, "seabed"));
  for (size_t k = 0; k < ref.size(); ++k) EXPECT_TRUE(ref[k] == bed[k]) << "sample " << k;
}

}  // namespace
}  // namespace riser_sim
