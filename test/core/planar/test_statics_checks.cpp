// Statics that used to fail or return wrong answers as converged, and checkEquilibrium() itself:
// a pinned end carrying a heavy end mass (was: residual NaN), an anchor at the hang-off point (was: the
// line folded on itself, ±125 kN in a 20 kg chain), degenerate anchors, waves (was: the statics took
// the wave at t = 0, or NaN in deep water), and states the check must refuse.
#include <gtest/gtest.h>

#include <cstdio>

#include "riser_sim/planar/modal.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// A 12 m chain (1.5 kg/m) pinned between the top and an anchor.
Scene pinnedChain(const Vec2& anchor, double end_mass, bool axial) {
  Scene s;
  s.length = 12.0;
  s.elements = 12;
  s.line.mass_per_length = 1.5;
  s.line.EA = 2e5;
  s.options.bending = false;
  s.options.axial_flexibility = axial;
  s.end_mass = end_mass;
  s.bottom = BottomBoundary::kPinned;
  s.bottom_point = inSpace(anchor);
  s.initial.type = InitialKind::kBetweenPoints;
  return s;
}

// The end mass sits on the anchor: the line's shape is that without it, the anchor's vertical reaction
// larger by its weight. Checked against the catenary through both points with the solver's end force
// (test_statics' reference and bound, < 1e-3 L at n = 40) and against the solution without the mass
// (same equations, Newton to 1e-9 of the weight: 1e-7 L / 1e-7 of the weight).
TEST(StaticsChecks, PinnedEndWithHeavyEndMass) {
  for (bool axial : {true, false}) {
    const double line_mass = 12.0 * 1.5, end_mass = 4.5 * line_mass;  // above the old limit (~2.6x)
    Scene s = pinnedChain(Vec2(5.0, -8.0), end_mass, axial), bare = pinnedChain(Vec2(5.0, -8.0), 0.0, axial);
    s.elements = bare.elements = 40;
    auto m = buildModel(s), mb = buildModel(bare);
    const StaticsResult st = solveStatics(*m, staticsProblem(s)), sb = solveStatics(*mb, staticsProblem(bare));
    ASSERT_TRUE(st.converged) << st.message;
    ASSERT_TRUE(sb.converged) << sb.message;
    const double g = s.gravity, W = (line_mass + end_mass) * g;
    EXPECT_NEAR(st.end_force.y() - sb.end_force.y(), end_mass * g, 1e-7 * W);
    EXPECT_NEAR(st.end_force.x(), sb.end_force.x(), 1e-7 * W);
    double shape = 0.0;
    for (int i = 0; i < m->bodies(); ++i) shape = std::max(shape, (st.kin[i].A - sb.kin[i].A).norm());
    EXPECT_LT(shape, 1e-7 * s.length);
    validation::Catenary c{s.length, 1.5 * g, axial ? s.line.EA : INFINITY, end_mass * g, st.end_force};
    const double err = validation::catenaryShapeError(*m, st.kin, c);
    std::printf("[pinned end mass %s] end force (%.4f, %.4f) N, catenary error %.2e m\n", axial ? "elastic" : "inext.",
                st.end_force.x(), st.end_force.y(), err);
    EXPECT_LT(err, 1e-3 * s.length);
  }
}

// Both ends at the hang-off point: a U of two hanging legs, each holding half the line (symmetry), the
// anchor the end mass too; no force anywhere beyond the line's weight. Also an anchor 3 cm beside the
// top and one straight below it (the mirror-image U shapes). Before: with n = 8 the anchor below the
// top gave a line folded on itself with 8 kN in an 18 kg chain.
TEST(StaticsChecks, AnchorAtOrNearTheHangOff) {
  for (const Vec2& anchor : {Vec2(0.0, 0.0), Vec2(0.03, 0.0), Vec2(0.0, -4.0)})
    for (int n : {8, 12})  // even: a rod at the bottom of the U
      for (bool axial : {true, false}) {
        Scene s = pinnedChain(anchor, 2.0, axial);
        s.elements = n;
        StaticsResult st;
        auto sim = buildSimulator(s, &st);
        ASSERT_TRUE(st.converged) << st.message;
        const double g = s.gravity, w = 1.5 * g, W = w * s.length + 2.0 * g;
        const LineOutputs& o = sim->outputs();
        std::printf("[anchor (%.2f, %.2f) n %d %s] end force (%.4f, %.4f) N, top tension %.4f N, max %.4f N\n",
                    anchor.x(), anchor.y(), n, axial ? "elastic" : "inext.", st.end_force.x(), st.end_force.y(),
                    o.top_tension, o.max_tension);
        EXPECT_LT(o.max_tension, W);
        EXPECT_LT(std::abs(st.end_force.x()), 0.5 * w * s.length);
        if (anchor.norm() == 0.0) EXPECT_NEAR(st.end_force.y(), 2.0 * g + 0.5 * w * s.length, 1e-7 * W);
        EXPECT_NEAR((st.kin.back().end() - anchor).norm(), 0.0, 1e-9);
      }
}

// Refused, naming bottom.position: an inextensible line pinned at exactly its length, and one whose
// ends are at one point with a joint at mid-length (n = 11): it folds there into two coinciding
// vertical legs, and how the weight splits between them is not determined (nor is the top reaction
// of a run: the pinned end's constraints are singular there).
TEST(StaticsChecks, DegenerateAnchorsAreRefused) {
  for (const Vec2& anchor : {Vec2(7.2, -9.6), Vec2(0.0, -12.0)}) {
    Scene s = pinnedChain(anchor, 0.0, false);
    auto m = buildModel(s);
    const StaticsResult st = solveStatics(*m, staticsProblem(s));
    EXPECT_FALSE(st.converged);
    EXPECT_EQ(st.message.rfind("bottom.position", 0), 0u) << st.message;
  }
  Scene s = pinnedChain(Vec2(0.0, 0.0), 2.0, false);
  s.elements = 11;
  auto m = buildModel(s);
  const StaticsResult st = solveStatics(*m, staticsProblem(s));
  EXPECT_FALSE(st.converged);
  EXPECT_NE(st.message.find("degenerate"), std::string::npos) << st.message;
  EXPECT_NE(st.message.find("bottom.position"), std::string::npos) << st.message;
}

// A 40 m steel pipe hanging in a current, with waves: the statics are those of the current alone
// (same arithmetic without the wave term: equal to round-off), in deep water too (T = 2.2 s in 1000 m:
// k h = 830, was NaN), and the modes are taken about that state (residual at round-off).
TEST(StaticsChecks, WavesDoNotChangeTheStatics) {
  Scene s;
  s.length = 40.0;
  s.elements = 10;
  s.line = LineProperties::fromGeometry(0.2, 0.17, 2.07e11, 7850.0);
  s.options.axial_flexibility = false;
  s.end_mass = 300.0;
  s.water.enabled = true;
  s.water.current.velocity = Eigen::Vector3d(0.7, 0.0, 0.0);
  s.hydro.enabled = true;
  s.hydro.drag_normal = 1.1;
  s.hydro.inertia_coefficient = 1.8;
  auto calm = buildModel(s);
  const StaticsResult ref = solveStatics(*calm, staticsProblem(s));
  ASSERT_TRUE(ref.converged) << ref.message;
  for (const auto& wave : {std::pair<double, double>{3.0, 7.0}, {1.0, 2.2}}) {
    Scene w = s;
    w.water.waves.height = wave.first;
    w.water.waves.period = wave.second;
    w.water.waves.depth = 1000.0;
    auto m = buildModel(w);
    const StaticsResult st = solveStatics(*m, staticsProblem(w));
    ASSERT_TRUE(st.converged) << "T " << wave.second << ": " << st.message;
    double diff = 0.0;
    for (int i = 0; i < m->bodies(); ++i) diff = std::max(diff, std::abs(st.kin[i].phi - ref.kin[i].phi));
    EXPECT_LT(diff, 1e-12) << "T " << wave.second;
    ModalOptions mo;
    mo.modes = 2;
    const ModalResult modes = sceneModes(w, mo);
    EXPECT_LT(modes.equilibrium_residual, 1e-9) << "T " << wave.second;
  }
}

// checkEquilibrium() on states that balance (or do not) but are no resting state: each is refused by
// the check that names it. The inverted and the buried columns are exact equilibria of an inextensible
// chain (every force along the rods); solveStatics used to return the buried one.
TEST(StaticsChecks, CheckNamesWhatIsWrong) {
  Scene s = pinnedChain(Vec2::Zero(), 0.0, false);
  s.bottom = BottomBoundary::kFree;
  s.initial.type = InitialKind::kHanging;
  s.seabed.enabled = true;
  s.seabed.level = -7.0;
  s.seabed.stiffness_normal = 1e5;
  auto m = buildModel(s);
  const StaticsProblem p = staticsProblem(s);
  const StaticsResult st = solveStatics(*m, p);
  ASSERT_TRUE(st.converged) << st.message;
  EXPECT_TRUE(checkEquilibrium(*m, p, st.kin, st.end_force).ok);
  auto expectCheck = [&](const Kinematics& kin, const std::string& check) {
    const EquilibriumCheck c = checkEquilibrium(*m, p, kin, Vec2::Zero());
    EXPECT_FALSE(c.ok) << check;
    EXPECT_EQ(c.message.rfind(check + ":", 0), 0u) << c.message;
  };
  Kinematics nan = st.kin;
  nan[4].phi = NAN;
  expectCheck(nan, "finite");
  Kinematics off = st.kin;
  off[2].phi += 1e-3;
  expectCheck(off, "residual");
  expectCheck(straightLine(*m, p.top, -M_PI / 2), "seabed");    // 5 m into the seabed, held up by it
  expectCheck(straightLine(*m, p.top, M_PI / 2), "stability");  // balanced upside down
}

// demo_riser_3d.yaml in a 3 m/s current towards its anchor, n = 12: Newton can turn an rfe a full turn past its
// neighbour, where the planar bending spring (on φ_i - φ_{i-1} as it is) holds a moment no geometry has; such a
// "solution" balanced 75 kN m at one joint and was accepted. The check refuses it (fold), the statics go on to a
// state of the line, and the 3D engine (directors: no angle to wind) agrees on it: the anchor's force to 1e-6 of it
// (both stop their statics at initial.tolerance 1e-9 of the weight; the 3D one relaxes to 1e-2 of its rest bound).
TEST(StaticsChecks, AJointWoundAFullTurnIsNoState) {
  const std::string file = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/demo_riser_3d.yaml";
  const Scene planar = loadSceneFile(file, {"space=planar", "line.elements=12", "environment.waves=null",
                                            "environment.current.profile=[[0, 3], [100, 0.985634]]",
                                            "seabed.friction_axial=null", "seabed.friction_lateral=null"});
  const riser_sim::Run run = buildRun(planar);
  const Kinematics& kin = run.initial.kin;
  for (size_t i = 1; i < kin.size(); ++i) EXPECT_LE(std::abs(kin[i].phi - kin[i - 1].phi), M_PI) << "joint " << i;
  const Scene in3d =
      loadSceneFile(file, {"line.elements=12", "environment.current.profile=[[0, 3, 0], [100, 0.985634, 0]]"});
  const spatial::InitialState3 init = spatial::solveInitialState3(in3d, in3d.top.position);
  const Vec2 f3(init.end_force.x(), init.end_force.z());
  EXPECT_LT((run.initial.end_force - f3).norm(), 1e-6 * f3.norm())
      << "planar " << run.initial.end_force.transpose() << ", 3D " << f3.transpose();
  EXPECT_LT(std::abs(init.end_force.y()), 1e-9 * f3.norm());
  // The same state with rfes 10.. turned a full turn: the same geometry, refused naming the joint.
  Kinematics wound = kin;
  for (size_t i = 10; i < wound.size(); ++i) wound[i].phi += 2.0 * M_PI;
  const StaticsProblem p = staticsProblem(planar);
  const EquilibriumCheck c = checkEquilibrium(*run.model, p, wound, run.initial.end_force);
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.message.rfind("fold: rfe 10 is turned", 0), 0u) << c.message;
  EXPECT_TRUE(checkEquilibrium(*run.model, p, kin, run.initial.end_force).ok);
}

}  // namespace
}  // namespace riser_sim
