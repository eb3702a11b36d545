// ~modes against the core's modal analysis of the same scene (an independent call in this process:
// its own statics and model) and against the pendulum's omega = sqrt(g / L).
#include <cmath>

#include "node_test_util.h"
#include "riser_sim/run_builder.h"
#include "riser_sim/Modes.h"
#include "riser_sim/modal.h"
#include "riser_sim/scene_yaml.h"

using namespace riser_sim_test;

namespace {

const double kX = 5.0, kZ = -1.0;  // hang-off [m]: the vessel sits here

riser_sim::Modes call(ros::ServiceClient& client, int count) {
  riser_sim::Modes srv;
  srv.request.count = count;
  EXPECT_TRUE(client.call(srv)) << "count " << count;
  return srv;
}

TEST(NodeModes, MatchesTheCoreAndThePendulum) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_file;
  ASSERT_TRUE(pnh.getParam("scene_file", scene_file));
  ros::ServiceClient modes = nh.serviceClient<riser_sim::Modes>("/riser_sim/modes");
  ASSERT_TRUE(modes.waitForExistence(ros::Duration(20.0)));

  // Before the first pose there is no static state.
  riser_sim::Modes early = call(modes, 2);
  EXPECT_FALSE(early.response.success);
  EXPECT_NE(early.response.message.find("no static state yet"), std::string::npos) << early.response.message;

  PosePublisher pose(nh, "/vessel/pose", 20.0, [](double, geometry_msgs::Pose& p) {
    p.position.x = kX;
    p.position.z = kZ;
  });
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0));

  // Bad counts: a clear error naming the field.
  for (int bad : {0, -3}) {
    const riser_sim::Modes r = call(modes, bad);
    EXPECT_FALSE(r.response.success);
    EXPECT_NE(r.response.message.find("count: must be >= 1, got " + std::to_string(bad)), std::string::npos)
        << r.response.message;
    EXPECT_TRUE(r.response.periods.empty());
  }
  const riser_sim::Modes big = call(modes, 1000);
  EXPECT_FALSE(big.response.success);
  // n = 4, inextensible: 5 rfes, one angle each.
  EXPECT_NE(big.response.message.find("count: must be <= 5"), std::string::npos) << big.response.message;

  // The reference: the same scene with the top fixed at the hang-off, statics and modes in this process.
  riser_sim::Scene scene = riser_sim::loadSceneFile(scene_file);
  scene.top.type = riser_sim::MotionKind::kFixed;
  scene.top.position = riser_sim::Vec2(kX, kZ);
  riser_sim::ModalOptions o;
  o.modes = 5;
  const riser_sim::ModalResult ref = riser_sim::sceneModes(scene, o);

  const riser_sim::Modes got = call(modes, 5);
  ASSERT_TRUE(got.response.success) << got.response.message;
  const auto& r = got.response;
  EXPECT_EQ(r.dofs, 5);
  EXPECT_EQ(r.header.frame_id, "world");
  EXPECT_LT(r.equilibrium_residual, 1e-8);
  ASSERT_EQ(r.periods.size(), 5u);
  ASSERT_EQ(r.frequencies.size(), 5u);
  ASSERT_EQ(r.characters.size(), 5u);
  ASSERT_EQ(r.axial_share.size(), 5u);
  const size_t np = scene.elements + 2;
  ASSERT_EQ(r.points.size(), np);
  ASSERT_EQ(r.arc_length.size(), np);
  ASSERT_EQ(r.shape_x.size(), 5 * np);
  ASSERT_EQ(r.shape_z.size(), 5 * np);
  // Same statics and eigen-solve on both sides: equal to round-off (1e-9 relative).
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(r.periods[k] / ref.modes[k].period, 1.0, 1e-9) << "mode " << k + 1;
    EXPECT_NEAR(r.frequencies[k] * r.periods[k], 1.0, 1e-12);
    EXPECT_EQ(r.characters[k], ref.modes[k].character);
    EXPECT_NEAR(r.axial_share[k], ref.modes[k].axial_fraction, 1e-9);
    for (size_t p = 0; p < np; ++p) {
      EXPECT_NEAR(r.shape_x[k * np + p], ref.modes[k].displacement[p].x(), 1e-6);
      EXPECT_NEAR(r.shape_z[k * np + p], ref.modes[k].displacement[p].y(), 1e-6);
    }
  }
  for (size_t p = 0; p < np; ++p) {
    EXPECT_NEAR(r.points[p].x, ref.points[p].x(), 1e-9);
    EXPECT_EQ(r.points[p].y, 0.0);
    EXPECT_NEAR(r.points[p].z, ref.points[p].y(), 1e-9);
    EXPECT_NEAR(r.arc_length[p], ref.arc_length[p], 1e-12);
  }
  EXPECT_NEAR(r.points.front().x, kX, 1e-9);
  EXPECT_NEAR(r.points.front().z, kZ, 1e-9);
  EXPECT_NEAR(r.points.back().z, kZ - 10.0, 1e-6);  // hangs straight down

  // Physics: a pendulum, omega_1 = sqrt(g / L) within the line-mass fraction eps = mu L / m = 1e-3
  // (the line's own mass moves the compound pendulum's length by O(eps); docs/modal.md).
  const double eps = 0.01 * 10.0 / 100.0;
  EXPECT_NEAR(r.periods[0] / (2.0 * M_PI * std::sqrt(10.0 / 9.81)), 1.0, eps);
  EXPECT_EQ(r.characters[0], "transverse");
  EXPECT_NEAR(r.shape_x[np - 1], 1.0, 1e-9);  // the mass swings sideways: the largest displacement

  // Fewer modes: the lowest ones, same values.
  const riser_sim::Modes two = call(modes, 2);
  ASSERT_TRUE(two.response.success) << two.response.message;
  ASSERT_EQ(two.response.periods.size(), 2u);
  EXPECT_DOUBLE_EQ(two.response.periods[1], r.periods[1]);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_modes");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
