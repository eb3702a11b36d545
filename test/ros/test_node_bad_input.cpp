#include <std_srvs/Trigger.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kWeight = (20.0 * 5.0 + 50.0) * 9.81;  // small_riser.yaml
constexpr double kBadX = 100.0;  // every bad pose sits here: had one reached the integrator, the top would move

geometry_msgs::PoseStamped pose(const ros::Time& stamp, double x, const char* frame = "world") {
  geometry_msgs::PoseStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.pose.position.x = x;
  m.pose.orientation.w = 1.0;
  return m;
}

long diagCount(const Recorder<diagnostic_msgs::DiagnosticArray>& diag, const std::string& node, const char* key) {
  const auto all = diag.all();
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    const std::string v = diagValue(*it, node, key);
    if (!v.empty()) return std::stol(v);
  }
  return -1;
}

TEST(NodeBadInput, BadPosesNeverReachTheIntegrator) {
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("/vessel/pose", 50);
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state");
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  Recorder<geometry_msgs::WrenchStamped> wrench(nh, "/riser_sim/top_wrench");
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/riser_sim/markers");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 20.0));

  // A valid pose at the origin starts the simulation.
  ros::Time good = ros::Time::now();
  pub.publish(pose(good, 0.0));
  ASSERT_TRUE(state.waitCount(2, 20.0));

  std::vector<geometry_msgs::PoseStamped> bad;
  auto next = [&] { return ros::Time::now(); };
  const double nan = std::nan(""), inf = INFINITY;
  bad.push_back(pose(next(), nan));                    // NaN position
  bad.push_back(pose(next(), kBadX));
  bad.back().pose.position.z = inf;                    // Inf position
  bad.push_back(pose(next(), kBadX));
  bad.back().pose.orientation.w = 0.0;                 // zero quaternion
  bad.push_back(pose(next(), kBadX));
  bad.back().pose.orientation.w = 2.0;                 // not a unit quaternion
  bad.push_back(pose(next(), kBadX));
  bad.back().pose.orientation.x = nan;                 // NaN orientation
  bad.push_back(pose(next(), kBadX, "map"));           // wrong frame_id
  bad.push_back(pose(ros::Time(), kBadX));             // zero stamp
  bad.push_back(pose(good, kBadX));                    // duplicate stamp
  bad.push_back(pose(good - ros::Duration(0.5), kBadX));  // out of order
  for (const auto& m : bad) pub.publish(m);
  // Another valid pose at the origin after them, then wait until the node has seen them all.
  pub.publish(pose(ros::Time::now(), 0.0));
  ASSERT_TRUE(waitFor([&] { return diagCount(diag, "riser_sim", "poses rejected") >= long(bad.size()); }, 10.0))
      << "rejected: " << diagCount(diag, "riser_sim", "poses rejected");
  EXPECT_EQ(diagCount(diag, "riser_sim", "poses accepted"), 2);
  // A few more states after the last rejection.
  const size_t n = state.count();
  ASSERT_TRUE(state.waitCount(n + 4, 10.0));

  for (const auto& m : state.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_NEAR(m.points.front().x, 0.0, 1e-9);
    EXPECT_NEAR(m.points.front().z, 0.0, 1e-9);
  }
  for (const auto& m : tension.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_NEAR(m.top, kWeight, 1e-6 * kWeight);
  }
  for (const auto& m : wrench.all()) EXPECT_TRUE(finite(m));
  for (const auto& m : markers.all()) EXPECT_TRUE(finite(m));
  EXPECT_GT(tension.count(), 0u);
}

TEST(NodeBadInput, DivergenceStopsDataReportsErrorAndResetRestarts) {
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("/unstable/vessel/pose", 10);
  Recorder<riser_sim::Tension> tension(nh, "/unstable/riser_sim/tension");
  Recorder<riser_sim::LineState> state(nh, "/unstable/riser_sim/state");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 20.0));
  pub.publish(pose(ros::Time::now(), 0.0));

  auto errorCount = [&] {
    int n = 0;
    for (const auto& d : diag.all())
      for (const auto& s : d.status)
        if (s.name.rfind("unstable/riser_sim", 0) == 0 && s.level == diagnostic_msgs::DiagnosticStatus::ERROR) {
          EXPECT_NE(s.message.find("diverged"), std::string::npos) << s.message;
          EXPECT_NE(s.message.find("reset"), std::string::npos) << s.message;
          ++n;
        }
    return n;
  };
  ASSERT_TRUE(waitFor([&] { return errorCount() >= 1; }, 15.0)) << "no ERROR diagnostics from the diverging node";
  // Publishing has stopped: no data message between two ERROR reports.
  const size_t t0 = tension.count(), s0 = state.count();
  const int e0 = errorCount();
  ASSERT_TRUE(waitFor([&] { return errorCount() >= e0 + 2; }, 10.0));
  EXPECT_EQ(tension.count(), t0);
  EXPECT_EQ(state.count(), s0);

  ros::ServiceClient reset = nh.serviceClient<std_srvs::Trigger>("/unstable/riser_sim/reset");
  ASSERT_TRUE(reset.waitForExistence(ros::Duration(10.0)));
  std_srvs::Trigger srv;
  ASSERT_TRUE(reset.call(srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_NE(srv.response.message.find("static equilibrium"), std::string::npos) << srv.response.message;
  // It diverges again (same scene), and reports it again.
  const int e1 = errorCount();
  ASSERT_TRUE(waitFor([&] { return errorCount() >= e1 + 1; }, 10.0));
  for (const auto& m : tension.all()) EXPECT_TRUE(finite(m));
  for (const auto& m : state.all()) EXPECT_TRUE(finite(m));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_bad_input");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
