// riser_a and riser_b hang from one vessel at x = -5 m and x = +5 m (hang-off offsets in the vessel
// frame); each node's outputs must be its own.
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kVesselX = 1.0, kVesselZ = 2.0;
constexpr double kWeight = (20.0 * 5.0 + 50.0) * 9.81;  // small_riser.yaml
constexpr double kStaticTol = 1e-6 * kWeight;           // see test_node_static.cpp

TEST(TwoNamespaces, EachNodeHasItsOwnTopicsFramesAndService) {
  ros::NodeHandle nh;
  PosePublisher pose(nh, "/vessel/pose", 20.0, [](double, geometry_msgs::Pose& p) {
    p.position.x = kVesselX;
    p.position.z = kVesselZ;
  });
  Recorder<riser_sim::LineState> state_a(nh, "/riser_a/riser_sim/state"), state_b(nh, "/riser_b/riser_sim/state");
  Recorder<riser_sim::Tension> tension_a(nh, "/riser_a/riser_sim/tension"), tension_b(nh, "/riser_b/riser_sim/tension");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() >= 2; }, 20.0)) << "both nodes subscribe to /vessel/pose";
  pose.start();
  ASSERT_TRUE(state_a.waitCount(2, 20.0));
  ASSERT_TRUE(state_b.waitCount(2, 20.0));
  ASSERT_TRUE(tension_a.waitCount(2, 10.0));
  ASSERT_TRUE(tension_b.waitCount(2, 10.0));

  // Each hangs from its own hang-off point.
  const auto a = state_a.last(), b = state_b.last();
  EXPECT_NEAR(a.points[0].x, kVesselX - 5.0, 1e-9);
  EXPECT_NEAR(b.points[0].x, kVesselX + 5.0, 1e-9);
  EXPECT_NEAR(a.points[0].z, kVesselZ, 1e-9);
  EXPECT_NEAR(b.points[0].z, kVesselZ, 1e-9);
  EXPECT_NEAR(tension_a.last().top, kWeight, kStaticTol);
  EXPECT_NEAR(tension_b.last().top, kWeight, kStaticTol);

  // Frames are prefixed by namespace and node name; both sets exist and sit at their own points.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(waitForFrames(buffer, {"riser_a/riser_sim/rfe_0", "riser_b/riser_sim/rfe_0"}, 10.0));
  for (int i = 0; i <= 10; ++i) {
    const auto ta = buffer.lookupTransform("world", "riser_a/riser_sim/rfe_" + std::to_string(i), ros::Time(0));
    const auto tb = buffer.lookupTransform("world", "riser_b/riser_sim/rfe_" + std::to_string(i), ros::Time(0));
    EXPECT_NEAR(ta.transform.translation.x, a.points[i].x, 1e-9);
    EXPECT_NEAR(tb.transform.translation.x, b.points[i].x, 1e-9);
  }
  EXPECT_FALSE(buffer.canTransform("world", "riser_sim/rfe_0", ros::Time(0))) << "no un-prefixed frames";

  // Services are per node.
  for (const char* srv_name : {"/riser_a/riser_sim/reset", "/riser_b/riser_sim/reset"}) {
    ros::ServiceClient c = nh.serviceClient<std_srvs::Trigger>(srv_name);
    ASSERT_TRUE(c.waitForExistence(ros::Duration(10.0))) << srv_name;
    std_srvs::Trigger t;
    ASSERT_TRUE(c.call(t)) << srv_name;
    EXPECT_TRUE(t.response.success) << srv_name << ": " << t.response.message;
  }

  // Diagnostics: one status per node, distinct names.
  ASSERT_TRUE(waitFor(
      [&] {
        bool seen_a = false, seen_b = false;
        for (const auto& d : diag.all())
          for (const auto& s : d.status) {
            seen_a |= s.name.rfind("riser_a/riser_sim", 0) == 0;
            seen_b |= s.name.rfind("riser_b/riser_sim", 0) == 0;
          }
        return seen_a && seen_b;
      },
      10.0));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_two_namespaces");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
