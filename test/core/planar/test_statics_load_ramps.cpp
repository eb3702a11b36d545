// The statics' continuations compose: a line whose still-water shape needs its attachments' loads ramped up from
// none (an ROV tether with a clump and floats) starts in a current too, the current then ramped up from that
// still-water shape. Each accepted start is checked against the dynamics (every joint at rest under the scene's
// forces: the builder's acceleration bound) and for stability, both independent of the statics' residual.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "riser_sim/planar/statics.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

using spatial::Vec3;

const std::string kTether = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/rov_tether_floats.yaml";

TEST(StaticsLoadRamps, TetherWithFloatsStartsInACurrentAlongAndAcross) {
  // 0.5 and 1 m/s along the tether's plane (towards the ROV) and across it: drag up to ~7x the tether's wet
  // weight per metre (0.5 rho Cd D U^2 = 18 N/m at 1 m/s against 0.8 N/m), so the shape is far from the
  // still-water one and Newton from the catenary guess alone does not reach it.
  for (const char* current : {"[0.5, 0.0, 0.0]", "[1.0, 0.0, 0.0]", "[0.7, 0.7, 0.0]", "[0.0, 1.0, 0.0]"}) {
    SCOPED_TRACE(current);
    const Scene s = loadSceneFile(kTether, {std::string("environment.current.velocity=") + current});
    spatial::InitialState3 init;
    ASSERT_NO_THROW(init = spatial::solveInitialState3(s, s.top.position));
    EXPECT_TRUE(init.equilibrium);
    EXPECT_LE(init.max_acceleration, init.acceleration_bound);
    EXPECT_NO_THROW(spatial::checkStable(s, init, false));
    // The current carries the tether downstream of the chord between its ends: the middle rfe's horizontal
    // offset from the chord points along the current (the drag's direction).
    const Vec3 top = init.kin.front().A, end = init.kin.back().end();
    const Vec3 mid = init.kin[init.kin.size() / 2].A;
    const Vec3 chord = (end - top).normalized();
    Vec3 off = (mid - top) - (mid - top).dot(chord) * chord;
    off.z() = 0.0;
    const Vec3 u = s.water.current.velocity;
    const Vec3 u_across = u - u.dot(chord) * chord;
    if (u_across.norm() > 0.1) EXPECT_GT(off.dot(u_across), 0.0);
  }
}

// The lazy wave hung off 2 m deeper than its scene's working point (a fixed top at -10 m): the catenary guess, the
// seabed's ramps and the buoyancy's ramp all stop short (the buoyancy's at 0.96 of the lift, contacts at the
// touch-down switching on the stiff seabed); the loads ramped on a seabed 10x softer, then its stiffness raised,
// reach it. Checked by checkEquilibrium (residual and stability, independent of the path) and by its shape: the
// hog bend inside the buoyancy section (560-800 m) above the sag bend before it. ~25 s: long.
TEST(StaticsLoadRamps, LazyWaveStartsWithItsHangOffMoved) {
  const char* check = std::getenv("RISER_SIM_CHECK");
  const char* run_long = std::getenv("RISER_SIM_LONG");
  if (check && std::string(check) == "1" && !(run_long && std::string(run_long) == "1"))
    GTEST_SKIP() << "long: RISER_SIM_LONG=1 runs it under make check";
  const Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/lazy_wave_riser.yaml",
                                {"top.motion=null", "top.position=[0.0, -10.0]"});
  const auto model = buildModel(s);
  InitialState init;
  ASSERT_NO_THROW(init = solveInitialState(s, *model, staticsProblem(s).top));
  const EquilibriumCheck c = checkEquilibrium(*model, staticsProblem(s), init.kin, init.end_force);
  EXPECT_TRUE(c.ok) << c.message;
  // Elevation against arc length: the lowest point before the buoyancy section, the highest inside it.
  double sag = INFINITY, hog = -INFINITY;
  for (size_t i = 0; i < init.kin.size(); ++i) {
    const double s_end = 5.0 + 10.0 * i;  // rfe i's end: half an end element, then 10 m segments (the scene's)
    const double z = init.kin[i].end().y();
    if (s_end < 560.0) sag = std::min(sag, z);
    if (s_end > 560.0 && s_end < 800.0) hog = std::max(hog, z);
  }
  EXPECT_GT(hog, sag + 5.0);  // a wave: the scene's working point has its hog ~30 m above the sag
}

}  // namespace
}  // namespace riser_sim
