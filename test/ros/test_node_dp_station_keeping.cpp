// Closed loop (node_dp_station_keeping.test: launch/dp_station_keeping.launch): the DP vessel integrates
// its motion under ~top_wrench and feeds its pose back; it holds station within a PD's static offset
// (F / kp ~0.38 m for the ~7.6 kN pull) and is pushed downstream, never beyond.
#include <Eigen/Core>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kRun = 20.0;      // [s] of ROS time
constexpr double kHold = 0.6;      // [m] horizontal distance from the setpoint (0, 0)
constexpr double kYawHold = 0.02;  // [rad]

std::string lastDiag(const Recorder<diagnostic_msgs::DiagnosticArray>& diag, const char* key) {
  const auto all = diag.all();
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    const std::string v = diagValue(*it, "riser_sim", key);
    if (!v.empty()) return v;
  }
  return "";
}

TEST(NodeDpStationKeeping, HoldsStationWhileTheRiserPulls) {
  ros::NodeHandle nh;
  Recorder<geometry_msgs::PoseStamped> vessel(nh, "/vessel/pose");
  Recorder<geometry_msgs::WrenchStamped> wrench(nh, "/riser_sim/top_wrench");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(wrench.waitCount(1, 60.0));
  ASSERT_TRUE(waitRosTime(kRun, 120.0));

  double worst = 0.0, worst_yaw = 0.0, fx = 0.0;
  for (const auto& m : wrench.all()) {
    ASSERT_TRUE(finite(m));
    fx = m.wrench.force.x;
  }
  const ros::Time from = wrench.all().front().header.stamp;
  int n = 0;
  for (const auto& m : vessel.all()) {
    if (m.header.stamp < from) continue;
    const auto& p = m.pose.position;
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    worst = std::max(worst, std::hypot(p.x, p.y));
    worst_yaw = std::max(worst_yaw, std::abs(2.0 * std::atan2(m.pose.orientation.z, m.pose.orientation.w)));
    ++n;
  }
  const auto last = vessel.last().pose.position;
  std::printf(
      "[ INFO ] DP over %.0f s (%d poses): largest offset %.3f m (bound %.2f m), yaw %.4f rad; final "
      "(%.3f, %.3f) m; riser pull fx %.0f N (static PD offset fx / kp = %.3f m)\n",
      kRun, n, worst, kHold, worst_yaw, last.x, last.y, fx, fx / 2.0e4);
  EXPECT_GT(n, 200);
  EXPECT_GT(fx, 1000.0);   // the current makes the riser pull downstream
  EXPECT_GT(last.x, 0.1);  // and the vessel gives way to it
  EXPECT_LT(worst, kHold);
  EXPECT_LT(worst_yaw, kYawHold);
  EXPECT_EQ(lastDiag(diag, "mode"), "running");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_dp_station_keeping");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
