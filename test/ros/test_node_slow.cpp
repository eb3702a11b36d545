#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

TEST(NodeSlow, ReportsFallingBehindAndKeepsPublishing) {
  ros::NodeHandle nh;
  PosePublisher pose(nh, "vessel/pose", 20.0, [](double, geometry_msgs::Pose&) {});
  Recorder<riser_sim::Tension> tension(nh, "riser_sim/tension");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0));

  diagnostic_msgs::DiagnosticStatus warn;
  ASSERT_TRUE(waitFor(
      [&] {
        for (const auto& d : diag.all())
          for (const auto& s : d.status)
            if (s.name.rfind("riser_sim", 0) == 0 && s.level == diagnostic_msgs::DiagnosticStatus::WARN &&
                s.message.find("falling behind") != std::string::npos) {
              diagnostic_msgs::DiagnosticArray one;
              one.status.push_back(s);
              const std::string dropped = diagValue(one, "riser_sim", "time dropped total [s]");
              if (dropped.empty() || std::stod(dropped) <= 0.0) continue;  // not yet past max_lag
              warn = s;
              return true;
            }
        return false;
      },
      15.0))
      << "no 'falling behind' WARN with dropped time on /diagnostics";
  diagnostic_msgs::DiagnosticArray a;
  a.status.push_back(warn);
  EXPECT_LT(std::stod(diagValue(a, "riser_sim", "real-time factor")), 0.9);
  EXPECT_GT(std::stod(diagValue(a, "riser_sim", "time dropped total [s]")), 0.0);

  // Publishing is scheduled in ROS time, independent of how far the integration got: +-25 %.
  const ros::Time from = ros::Time::now();
  ASSERT_TRUE(waitRosTime(2.0, 20.0));
  const ros::Time to = ros::Time::now();
  EXPECT_NEAR(tension.countBetween(from, to) / (to - from).toSec(), 20.0, 0.25 * 20.0);
  // The lag behind the clock stays bounded by ~max_lag (0.2 s) plus one capped cycle.
  const auto last = tension.last();
  EXPECT_LT((ros::Time::now() - last.header.stamp).toSec(), 0.5);
  for (const auto& m : tension.all()) EXPECT_TRUE(finite(m));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_slow");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
