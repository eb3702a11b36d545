// initial.velocity (initial_velocity.h): a rigid motion of the line at t = 0 in either engine. References: the
// kinetic energy of a rigid rotation about the vertical through the top, ½ Ω² ∫ r² dm (r the horizontal distance
// from the axis), and of a uniform translation, ½ m v²; a whirl in vacuum (gravity and springs only) keeps its
// angular momentum about the vertical through the top (gravity is vertical and the top's reaction passes through
// the axis); a hanging equilibrium carried at a constant velocity stays the same shape (Galilean invariance).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "riser_sim/run/line_run.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

constexpr double kL = 20.0, kMu = 5.0, kEndMass = 2.0;

// A 20 m line of 5 kg/m with a 2 kg end mass in vacuum, straight at 30 deg below the horizontal (3D: in the x-z
// plane), extensible, with bending.
std::string straightLine(const std::string& space, const std::string& velocity, const std::string& extra = "") {
  return "space: " + space + R"(
line: {length: 20.0, elements: 20, mass_per_length: 5.0, end_mass: 2.0, EA: 1.0e6, EI: 50.0}
environment: {gravity: 9.81}
initial: {type: straight, angle: -30.0, velocity: )" +
         velocity + "}\nsolver: {dt: 0.001}\n" + extra;
}

// The hanging equilibrium of the same line.
std::string hangingLine(const std::string& space, const std::string& velocity, const std::string& extra = "") {
  return "space: " + space + R"(
line: {length: 20.0, elements: 20, mass_per_length: 5.0, end_mass: 2.0, EA: 1.0e6, EI: 50.0}
environment: {gravity: 9.81}
initial: {type: hanging, velocity: )" +
         velocity + "}\nsolver: {dt: 0.001}\n" + extra;
}

// L_z about the vertical through `top` of the 3D state (torsion off: y = [q; v; W]): with u the generalised velocity
// of a unit rigid rotation about that axis at the current positions, L_z = ∂T/∂Ω = vᵀ M u = (T(v + u) - T(v - u)) / 2
// (T = ½ vᵀ M v: exact).
double angularMomentumZ(spatial::Run3& run, const Vec3& top) {
  spatial::Simulator3& sim = run.simulator();
  const spatial::NaturalFormulation& f = sim.formulation();
  spatial::Kinematics3 kin(sim.model().bodies());
  sim.kinematics(kin);
  for (spatial::BodyKinematics3& b : kin) {
    b.A_dot = Vec3::UnitZ().cross(b.A - top);
    b.e_dot = Vec3::UnitZ().cross(b.e);
    b.delta_dot = 0.0;
  }
  const VecX& y = sim.state();
  VecX yu = VecX::Zero(y.size());
  f.packState(kin, yu);
  const int p = f.positionSize();
  VecX plus = y, minus = y;
  plus.segment(p, p) += yu.segment(p, p);
  minus.segment(p, p) -= yu.segment(p, p);
  return 0.5 * (f.kineticEnergy(plus) - f.kineticEnergy(minus));
}

// A straight line at angle α below the horizontal turning at Ω about the vertical through its top: r = s cos α,
// T = ½ Ω² cos²α (μ L³ / 3 + m_end L²). The rfes are thin rigid rods (their inertia about the middle μ l³ / 12 on
// each part), so the RFEM line's T is the continuum's to round-off: 1e-12 relative.
TEST(InitialVelocity, WhirlKineticEnergyIsTheRigidRotations) {
  const double omega = 0.5, c = std::cos(30.0 * M_PI / 180.0);
  const double expected = 0.5 * omega * omega * c * c * (kMu * kL * kL * kL / 3.0 + kEndMass * kL * kL);
  spatial::Run3 run(loadSceneText(straightLine("spatial", "{rotation: 0.5}"), "test"));
  const double T = run.simulator().kineticEnergy();
  EXPECT_NEAR(T, expected, 1e-12 * expected);
  EXPECT_FALSE(run.initial().equilibrium);
  EXPECT_NE(run.initial().about.find("initial.velocity"), std::string::npos) << run.initial().about;
  // Every rfe moves as the rigid body: the joints' velocities are Ω e_z × (A_i - top).
  spatial::Kinematics3 kin(run.model().bodies());
  run.simulator().kinematics(kin);
  for (const spatial::BodyKinematics3& b : kin) EXPECT_LT((b.A_dot - omega * Vec3::UnitZ().cross(b.A)).norm(), 1e-12);
}

// A uniform translation: T = ½ (μ L + m_end) v², in the 3D engine and in the planar one (absolute and independent
// formulations: the independent one takes the top's velocity from its motion, which carries the fixed top along).
TEST(InitialVelocity, TranslationKineticEnergyIsHalfMVSquared) {
  const double m = kMu * kL + kEndMass;
  {
    const Vec3 v(0.3, -0.2, 0.1);
    spatial::Run3 run(loadSceneText(hangingLine("spatial", "{translation: [0.3, -0.2, 0.1]}"), "test"));
    EXPECT_NEAR(run.simulator().kineticEnergy(), 0.5 * m * v.squaredNorm(), 1e-12 * m * v.squaredNorm());
  }
  for (const char* formulation : {"absolute", "independent"}) {
    const double v2 = 0.3 * 0.3 + 0.1 * 0.1;
    std::string text = hangingLine("planar", "{translation: [0.3, 0.1]}");
    text.replace(text.find("solver: {"), 9, std::string("solver: {formulation: ") + formulation + ", ");
    riser_sim::Run run = buildRun(loadSceneText(text, "test"));
    const LineOutputs& o = run.sim->outputs();
    EXPECT_NEAR(o.kinetic_energy, 0.5 * m * v2, 1e-12 * m * v2) << formulation;
  }
}

// A hanging equilibrium in vacuum carried at a constant velocity is a solution (Galilean invariance): after 1 s the
// fixed top has moved by v (it is carried along) and the line's shape relative to it is the start's. rk4 integrates
// the uniform motion exactly and the shape is an equilibrium to the statics' tolerance (a residual force of 1e-9 of
// the weight: accelerations below ~1e-8 m/s², ½ a t² below 5e-9 m over 1 s): the points stay within 1e-8 m
// (measured 5e-14 m; the top 8e-16 m).
TEST(InitialVelocity, TranslatedEquilibriumKeepsItsShape) {
  for (const char* space : {"spatial", "planar"}) {
    const bool spatial = std::string(space) == "spatial";
    const std::string v = spatial ? "{translation: [0.4, 0.3, -0.2]}" : "{translation: [0.4, -0.2]}";
    const Vec3 vel = spatial ? Vec3(0.4, 0.3, -0.2) : Vec3(0.4, 0.0, -0.2);
    std::unique_ptr<LineRun> run = buildLineRun(loadSceneText(hangingLine(space, v), "test"));
    const RunOutputs start = run->outputs();
    for (int k = 0; k < 1000; ++k) ASSERT_TRUE(run->step()) << space;
    const RunOutputs& o = run->outputs();
    EXPECT_LT((o.top_point - start.top_point - vel * o.t).norm(), 1e-9) << space;
    double worst = 0.0;
    for (size_t i = 0; i < o.points.size(); ++i)
      worst = std::max(worst, ((o.points[i] - o.top_point) - (start.points[i] - start.top_point)).norm());
    EXPECT_LT(worst, 1e-8) << space;
  }
}

// A whirl from the straight line in vacuum: gravity is vertical and the top's reaction acts on the axis, so L_z
// about the vertical through the top is conserved; what the run loses is rk4's truncation error, O(h⁴) over a fixed
// time. Measured over 2 s: 8.9e-8 relative at h = 2e-3 s, 5.6e-9 at 1e-3 s, 3.5e-10 at 5e-4 s (ratio 16 per
// halving). Asserted: below 2e-8 at h = 1e-3 s and falling at least 8x when h halves (fourth order, with room); a
// lost moment arm or a wrong rotation sense changes L_z by O(1) and does not fall with h.
TEST(InitialVelocity, WhirlKeepsItsAngularMomentumAboutTheVertical) {
  const double c = std::cos(30.0 * M_PI / 180.0);
  double drift[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    std::string text = straightLine("spatial", "{rotation: 0.5}");
    text.replace(text.find("dt: 0.001"), 9, k == 0 ? "dt: 0.002" : "dt: 0.001");
    spatial::Run3 run(loadSceneText(text, "test"));
    const double L0 = angularMomentumZ(run, Vec3::Zero());
    // At t = 0: L_z = Ω ∫ r² dm = 2 T / Ω.
    EXPECT_NEAR(L0, 0.5 * c * c * (kMu * kL * kL * kL / 3.0 + kEndMass * kL * kL), 1e-12 * L0);
    const int steps = k == 0 ? 1000 : 2000;
    for (int i = 0; i < steps; ++i) {
      ASSERT_TRUE(run.step());
      if (i % 10 == 9) drift[k] = std::max(drift[k], std::abs(angularMomentumZ(run, Vec3::Zero()) - L0) / L0);
    }
    // It moved: the line swung down and turned (L_z is not trivially kept by a line at rest).
    EXPECT_GT(std::abs(run.outputs().points.back().y()), 1.0);
  }
  EXPECT_LT(drift[1], 2e-8);
  EXPECT_GT(drift[0], 8.0 * drift[1]);
}

// Refused, naming the key: a rotation in a planar scene, a y component in a planar scene, a translation the top's
// motion does not have at t = 0, a velocity moving a pinned bottom; an unknown key. Accepted: a rotation with a
// pinned bottom on the axis (under the top), a translation a sinusoid's top has at t = 0.
TEST(InitialVelocity, BadInputNamesTheKey) {
  const auto key = [](const std::string& text) {
    try {
      loadSceneText(text, "test");
    } catch (const SceneError& e) {
      return e.key();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key(straightLine("planar", "{rotation: 0.5}")), "initial.velocity.rotation");
  EXPECT_EQ(key(straightLine("planar", "{rotation: 0.0}")), "(accepted)");
  EXPECT_EQ(key(straightLine("planar", "{translation: [0.1, 0.2, 0.0]}")), "initial.velocity.translation[1]");
  EXPECT_EQ(key(straightLine("spatial", "{spin: 0.5}")), "initial.velocity.spin");
  EXPECT_EQ(key(straightLine("spatial", "{rotation: fast}")), "initial.velocity.rotation");
  const std::string sinusoid =
      "top: {position: [0, 0], motion: {type: sinusoid, amplitude: [1.0, 0.0], "
      "period: 6.283185307179586, phase: -1.5707963267948966}}\n";  // v(0) = (1, 0)
  EXPECT_EQ(key(straightLine("planar", "{translation: [0.5, 0.0]}", sinusoid)), "initial.velocity.translation");
  EXPECT_EQ(key(straightLine("planar", "{translation: [1.0, 0.0]}", sinusoid)), "(accepted)");
  const std::string pinned = "bottom: {type: pinned, position: [0.0, -15.0]}\n";
  std::string between = hangingLine("spatial", "{translation: [0.1, 0.0, 0.0]}", pinned);
  between.replace(between.find("type: hanging"), 13, "type: between_points");
  EXPECT_EQ(key(between), "initial.velocity.translation");
  between.replace(between.find("{translation: [0.1, 0.0, 0.0]}"), 30, "{rotation: 0.3}");
  EXPECT_EQ(key(between), "(accepted)");  // the anchor is on the axis
  between.replace(between.find("[0.0, -15.0]"), 12, "[5.0, -15.0]");
  EXPECT_EQ(key(between), "initial.velocity.rotation");
}

// The keys with a zero motion run the start at rest: the same state bit for bit as without them.
TEST(InitialVelocity, ZeroVelocityIsTheStartAtRest) {
  for (const char* space : {"spatial", "planar"}) {
    std::unique_ptr<LineRun> a = buildLineRun(loadSceneText(hangingLine(space, "{}"), "test"));
    std::string text = hangingLine(space, "{}");
    text.replace(text.find(", velocity: {}"), 14, "");
    std::unique_ptr<LineRun> b = buildLineRun(loadSceneText(text, "test"));
    for (int k = 0; k < 50; ++k) ASSERT_TRUE(a->step() && b->step());
    EXPECT_EQ(a->outputs().points, b->outputs().points) << space;
  }
}

}  // namespace
}  // namespace riser_sim
