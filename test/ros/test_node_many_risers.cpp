// node_many_risers.test: riser_1..3 as nodelets (with the vessel nodelet, surge 10 m / 27 s at 20 Hz)
// and riser_4..6 as nodes, from launch/many_risers.launch; riser i hangs at x = (i - 1) * 10 m from
// the vessel.
#include <ros/master.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr int kRisers = 6;
constexpr double kSpacing = 10.0;  // many_risers.launch default
// Half the vessel's motion in one pose period, as test_node_following.cpp: 10 m / 27 s surge at 20 Hz.
const double kTrackTol = 0.5 * 10.0 * 2 * M_PI / 27.0 / 20.0;
// [s] after a riser's first state: the catch-up with the moving vessel (motion/start_blend, 2 s in
// node_defaults.yaml, which many_risers.launch loads) and the motion's fit window.
constexpr double kWarmup = 2.5;

// The node (process) that publishes `topic`, from the master's system state ("" when none).
std::string publisherOf(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, false)) return "";
  XmlRpc::XmlRpcValue& pubs = payload[0];
  for (int i = 0; i < pubs.size(); ++i)
    if (static_cast<std::string>(pubs[i][0]) == topic && pubs[i][1].size() > 0) return pubs[i][1][0];
  return "";
}

TEST(ManyRisers, EachRiserHasItsNamespacePrefixOffsetAndProcess) {
  ros::NodeHandle nh;
  std::vector<std::unique_ptr<Recorder<riser_sim::LineState>>> states;
  for (int i = 1; i <= kRisers; ++i)
    states.push_back(
        std::make_unique<Recorder<riser_sim::LineState>>(nh, "/riser_" + std::to_string(i) + "/riser_sim/state"));
  Recorder<geometry_msgs::PoseStamped> vessel(nh, "/vessel/pose");
  for (int i = 0; i < kRisers; ++i) ASSERT_TRUE(states[i]->waitCount(1, 40.0)) << "riser_" << i + 1 << " runs";
  ASSERT_TRUE(waitRosTime(kWarmup + 3.0, 30.0));

  const std::vector<geometry_msgs::PoseStamped> poses = vessel.all();
  ASSERT_GT(poses.size(), 40u);
  auto vesselAt = [&](const ros::Time& t, geometry_msgs::Point& p) {  // linear in the recorded poses
    for (size_t k = 1; k < poses.size(); ++k)
      if (poses[k - 1].header.stamp <= t && t <= poses[k].header.stamp) {
        const double w =
            (t - poses[k - 1].header.stamp).toSec() / (poses[k].header.stamp - poses[k - 1].header.stamp).toSec();
        p.x = poses[k - 1].pose.position.x + w * (poses[k].pose.position.x - poses[k - 1].pose.position.x);
        p.z = poses[k - 1].pose.position.z + w * (poses[k].pose.position.z - poses[k - 1].pose.position.z);
        return true;
      }
    return false;
  };
  for (int i = 0; i < kRisers; ++i) {
    const auto all = states[i]->all();
    double worst = 0.0;
    int n = 0;
    for (const auto& s : all) {
      geometry_msgs::Point v;
      if (s.header.stamp < all.front().header.stamp + ros::Duration(kWarmup) || !vesselAt(s.header.stamp, v)) continue;
      worst = std::max(worst, std::hypot(s.points[0].x - (v.x + i * kSpacing), s.points[0].z - v.z));
      ++n;
    }
    std::printf("[ INFO ] riser_%d: max tracking error %.4f m over %d states (tolerance %.4f m)\n", i + 1, worst, n,
                kTrackTol);
    RecordProperty("max_tracking_error_riser_" + std::to_string(i + 1), std::to_string(worst));
    EXPECT_GE(n, 20) << "riser_" << i + 1 << ": ~state at 10 Hz over 3 s";
    EXPECT_LT(worst, kTrackTol) << "riser_" << i + 1;
  }

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  for (int i = 1; i <= kRisers; ++i)
    EXPECT_TRUE(waitFor(
        [&] { return buffer.canTransform("world", "riser_" + std::to_string(i) + "/riser_sim/rfe_0", ros::Time(0)); },
        10.0))
        << "frames of riser_" << i;

  // nodelets:=true put riser_1..3 in the manager; nodelets:=false gave riser_4..6 their own processes.
  for (int i = 1; i <= kRisers; ++i) {
    const std::string ns = "/riser_" + std::to_string(i);
    EXPECT_EQ(publisherOf(ns + "/riser_sim/tension"), i <= 3 ? std::string("/riser_manager") : ns + "/riser_sim");
  }
  EXPECT_EQ(publisherOf("/vessel/pose"), "/riser_manager");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_many_risers");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
