// Bad vessel poses for a 3D scene (node_spatial_bad_input.test) never reach the integrator: the
// node keeps running at the last good, yawed pose and publishes nothing non-finite.
#include <Eigen/Core>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kWeight = (20.0 * 5.0 + 50.0) * 9.81;  // small_riser_3d.yaml
constexpr double kYaw = M_PI / 6.0;
constexpr double kBadY = 100.0;  // every bad pose sits here: had one reached the integrator, the top would move

geometry_msgs::PoseStamped pose(const ros::Time& stamp, double y) {
  geometry_msgs::PoseStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = "world";
  m.pose.position.y = y;
  m.pose.orientation.w = std::cos(0.5 * kYaw);
  m.pose.orientation.z = std::sin(0.5 * kYaw);
  return m;
}

long diagCount(const Recorder<diagnostic_msgs::DiagnosticArray>& diag, const char* key) {
  const auto all = diag.all();
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    const std::string v = diagValue(*it, "riser_sim", key);
    if (!v.empty()) return std::stol(v);
  }
  return -1;
}

TEST(NodeSpatialBadInput, BadPosesNeverReachTheIntegrator) {
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("/vessel/pose", 50);
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state");
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  Recorder<geometry_msgs::WrenchStamped> wrench(nh, "/riser_sim/top_wrench");
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/riser_sim/markers");
  Recorder<tf2_msgs::TFMessage> tf(nh, "/tf");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 20.0));

  const ros::Time good = ros::Time::now();
  pub.publish(pose(good, 0.0));
  ASSERT_TRUE(state.waitCount(2, 20.0));

  const double nan = std::nan(""), inf = INFINITY;
  std::vector<geometry_msgs::PoseStamped> bad;
  const auto next = [] { return ros::Time::now(); };
  bad.push_back(pose(next(), kBadY));
  bad.back().pose.orientation.w *= 1.5, bad.back().pose.orientation.z *= 1.5;  // norm 1.5
  bad.push_back(pose(next(), kBadY));
  bad.back().pose.orientation.w = bad.back().pose.orientation.z = 0.0;  // zero quaternion
  bad.push_back(pose(next(), kBadY));
  bad.back().pose.orientation.z = nan;  // NaN orientation
  bad.push_back(pose(next(), nan));     // NaN position (y)
  bad.push_back(pose(next(), kBadY));
  bad.back().pose.position.z = inf;                       // Inf position
  bad.push_back(pose(good, kBadY));                       // duplicate stamp
  bad.push_back(pose(good - ros::Duration(0.3), kBadY));  // out of order
  for (const auto& m : bad) pub.publish(m);
  pub.publish(pose(ros::Time::now(), 0.0));
  ASSERT_TRUE(waitFor([&] { return diagCount(diag, "poses rejected") >= long(bad.size()); }, 10.0))
      << "rejected: " << diagCount(diag, "poses rejected");
  EXPECT_EQ(diagCount(diag, "poses accepted"), 2);
  const size_t n = state.count();
  ASSERT_TRUE(state.waitCount(n + 10, 10.0)) << "the node stopped publishing";  // still running

  const Eigen::Vector3d hangoff(5.0 * std::cos(kYaw), 5.0 * std::sin(kYaw), -1.0);
  for (const auto& m : state.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_NEAR(m.points.front().x, hangoff.x(), 1e-9);
    EXPECT_NEAR(m.points.front().y, hangoff.y(), 1e-9);
    EXPECT_NEAR(m.points.front().z, hangoff.z(), 1e-9);
  }
  for (const auto& m : tension.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_NEAR(m.top, kWeight, 1e-6 * kWeight);
  }
  // Body frame: the weight straight down in the yawed vessel's frame too.
  for (const auto& m : wrench.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_NEAR(m.wrench.force.z, -kWeight, 1e-6 * kWeight);
    EXPECT_NEAR(std::hypot(m.wrench.force.x, m.wrench.force.y), 0.0, 1e-6 * kWeight);
  }
  for (const auto& m : markers.all()) EXPECT_TRUE(finite(m));
  for (const auto& m : tf.all()) EXPECT_TRUE(finite(m));
  EXPECT_GT(tension.count(), 0u);
  EXPECT_GT(wrench.count(), 0u);
  EXPECT_GT(tf.count(), 0u);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_spatial_bad_input");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
