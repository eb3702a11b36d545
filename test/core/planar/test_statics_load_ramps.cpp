// The statics' continuations compose: a line whose still-water shape needs its attachments' loads ramped up from
// none (an ROV tether with a clump and floats) starts in a current too, the current then ramped up from that
// still-water shape. Each accepted start is checked against the dynamics (every joint at rest under the scene's
// forces: the builder's acceleration bound) and for stability, both independent of the statics' residual.
#include <gtest/gtest.h>

#include <string>
#include <vector>

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
    ASSERT_NO_THROW(init = spatial::solveInitialState3(s, s.top.position3));
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
    const Vec3 u = s.water.current.velocity3;
    const Vec3 u_across = u - u.dot(chord) * chord;
    if (u_across.norm() > 0.1) EXPECT_GT(off.dot(u_across), 0.0);
  }
}

}  // namespace
}  // namespace riser_sim
