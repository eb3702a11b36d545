// The test owns /clock: it advances 15 ms every 5 ms of wall time (3x real time).
#include <rosgraph_msgs/Clock.h>

#include <atomic>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kSpeed = 3.0;
std::atomic<double> g_clock{1000.0};  // [s] start far from zero (zero means "no clock yet")

TEST(NodeSimTime, FollowsTheClock) {
  ros::NodeHandle nh;
  ros::Publisher clock_pub = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
  ros::WallTimer ticker = nh.createWallTimer(ros::WallDuration(0.005), [&](const ros::WallTimerEvent&) {
    rosgraph_msgs::Clock c;
    g_clock = g_clock + kSpeed * 0.005;
    c.clock = ros::Time(g_clock);
    clock_pub.publish(c);
  });
  ASSERT_TRUE(waitFor([] { return !ros::Time::now().isZero(); }, 10.0));
  PosePublisher pose(nh, "vessel/pose", 20.0, [](double, geometry_msgs::Pose&) {});
  Recorder<riser_sim::Tension> tension(nh, "riser_sim/tension");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0));

  // Rates and the real-time factor are in ROS (= clock) time: 3 s of clock in ~1 s of wall time.
  const ros::Time from = ros::Time::now();
  const ros::WallTime wall_from = ros::WallTime::now();
  ASSERT_TRUE(waitRosTime(3.0, 20.0));
  const ros::Time to = ros::Time::now();
  const double wall = (ros::WallTime::now() - wall_from).toSec();
  const double span = (to - from).toSec();
  EXPECT_LT(wall, 0.6 * span) << "the clock runs faster than the wall";
  EXPECT_NEAR(tension.countBetween(from, to) / span, 20.0, 0.25 * 20.0);
  for (const auto& m : tension.all()) {
    EXPECT_GE(m.header.stamp.toSec(), 1000.0);  // stamped with clock time
    // ros::Time(double) rounds to whole nanoseconds: allow that rounding, nothing more.
    EXPECT_LE(m.header.stamp.toSec(), g_clock.load() + 1e-6);
  }
  ASSERT_TRUE(waitFor(
      [&] {
        if (diag.count() < 2) return false;
        const std::string rtf = diagValue(diag.last(), "riser_sim", "real-time factor");
        return !rtf.empty() && std::abs(std::stod(rtf) - 1.0) < 0.1;
      },
      10.0))
      << "real-time factor (in clock time) not ~1";
  ticker.stop();
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_sim_time");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
