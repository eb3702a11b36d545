// The statics' stability check with drag: a start is accepted only if its linearisation (drag's damping and
// its non-symmetric stiffness included) has no growing mode, in both engines (linear_stability.h).
#include <gtest/gtest.h>

#include <string>

#include "riser_sim/run/linear_stability.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/planar/statics.h"

namespace riser_sim {
namespace {

const std::string kDpRiser = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/dp_riser.yaml";
const std::string kCurrent10 = "environment.current.profile=[[0.0, 10, 0.0], [200.0, 10, 0.0]]";

bool names(const std::string& message, const std::string& what) { return message.find(what) != std::string::npos; }

// dp_riser (2 t end mass) in a 10 m/s current: Newton from the straight guess balances the line standing 35 m
// above its hang-off, on a bending spring wound six turns (one joint at -38.8 rad: no geometry has that moment).
// The check refuses that state naming the fold before anything else; whatever the statics return is either
// refused naming why or hangs below the hang-off.
TEST(StaticsStability, UpturnedLineInStrongCurrentIsRefusedPlanar) {
  const Scene s = loadSceneFile(kDpRiser, {"space=planar", kCurrent10});
  const auto model = buildModel(s);
  StaticsProblem direct = staticsProblem(s);
  direct.continuation = false;  // the first guess's Newton only: the upturned state
  const StaticsResult up = solveStatics(*model, direct);
  ASSERT_FALSE(up.converged);
  EXPECT_TRUE(names(up.message, "fold: rfe")) << up.message;
  EXPECT_GT(up.kin.back().end().y(), s.top.position.z() + 10.0);  // the refused state stands above the top
  // Balanced (residual at the tolerance): only the wound spring's moment holds it.
  const EquilibriumCheck c = checkEquilibrium(*model, direct, up.kin, up.end_force);
  EXPECT_LE(c.residual, direct.tolerance);
  EXPECT_TRUE(names(c.message, "fold: rfe")) << c.message;

  const StaticsResult r = solveStatics(*model, staticsProblem(s));
  if (r.converged)
    EXPECT_LT(r.kin.back().end().y(), s.top.position.z()) << r.message;
  else
    EXPECT_TRUE(names(r.message, "stability") || names(r.message, "current")) << r.message;
}

TEST(StaticsStability, UpturnedLineInStrongCurrentIsRefused3D) {
  const Scene s = loadSceneFile(kDpRiser, {kCurrent10});
  ASSERT_EQ(s.space, SpaceKind::kSpatial);
  // The 3D check on the upturned state of the planar statics (the current along +x: the plane x-z).
  const Scene ps = loadSceneFile(kDpRiser, {"space=planar", kCurrent10});
  StaticsProblem direct = staticsProblem(ps);
  direct.continuation = false;
  const StaticsResult up = solveStatics(*buildModel(ps), direct);
  spatial::InitialState3 init;
  init.kin = spatial::fromPlanar(up.kin);
  ASSERT_GT(init.kin.back().end().z(), 10.0);
  try {
    spatial::checkStable(s, init, false);
    ADD_FAILURE() << "the upturned state passed the 3D stability check";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(names(e.what(), "stability: the equilibrium is unstable")) << e.what();
  }
  // The 3D start itself: refused naming why, or hanging below the hang-off.
  try {
    const spatial::InitialState3 r = spatial::solveInitialState3(s, s.top.position);
    EXPECT_LT(r.kin.back().end().z(), s.top.position.z());
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(names(e.what(), "stability") || names(e.what(), "current")) << e.what();
    EXPECT_FALSE(names(e.what(), "not an equilibrium of the 3D model")) << e.what();
  }
}

// linearStability on two dofs: a follower load (Ziegler's column, K non-symmetric with a positive definite
// symmetric part) flutters without damping and is held by enough of it; a negative stiffness diverges.
TEST(StaticsStability, FollowerLoadFluttersUnlessDamped) {
  const MatX M = MatX::Identity(2, 2);
  MatX K(2, 2);
  K << 2.0, -3.0, 3.0, 2.0;  // eigenvalues 2 ± 3i: λ² = -(2 ± 3i), one root with Re λ > 0
  const LinearStability u = linearStability(K, MatX(), M, MatX(), 1e-9);
  EXPECT_FALSE(u.stable);
  EXPECT_TRUE(u.first_order);
  EXPECT_GT(u.frequency, 0.0);
  // Damping c I: λ² + c λ + (2 ± 3i) = 0 is stable for c² > 9/2 (Re λ < 0 on both roots).
  const LinearStability d = linearStability(K, 3.0 * MatX::Identity(2, 2), M, MatX(), 1e-9);
  EXPECT_TRUE(d.stable) << d.describe();
  MatX Kd(2, 2);
  Kd << 1.0, 0.0, 0.0, -0.5;
  const LinearStability v = linearStability(Kd, MatX(), M, MatX(), 1e-9);
  EXPECT_FALSE(v.stable);
  EXPECT_TRUE(names(v.describe(), "divergence"));
}

}  // namespace
}  // namespace riser_sim
