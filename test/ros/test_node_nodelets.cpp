// node_nodelets.test: riser_a and riser_b (RiserSimNodelet, hang-off offsets -5 m and +5 m) and the
// vessel (VesselMotionNodelet) in one manager, /riser_manager.
#include <algorithm>
#include <map>

#include <nodelet/NodeletUnload.h>
#include <ros/master.h>
#include <ros/network.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

// The vessel nodelet's motion in node_nodelets.test (surge 2 m / 4 s, 20 Hz) is test_node_following's:
// the same tolerance, half the vessel's motion in one pose period (0.0785 m), from the same reasoning.
const double kTrackTol = 0.5 * 2.0 * 2 * M_PI / 4.0 / 20.0;
// [s] after a riser's first state: the catch-up with the moving vessel (motion/start_blend, 2 s in
// node_defaults.yaml, which riser_nodelet.launch loads) and the motion's fit window.
constexpr double kWarmup = 2.5;

// Vessel positions by stamp, as published (the test receives the nodelet's poses over TCP).
class VesselTrack {
 public:
  explicit VesselTrack(ros::NodeHandle& nh) {
    sub_ = nh.subscribe<geometry_msgs::PoseStamped>("/vessel/pose", 100,
                                                    [this](const geometry_msgs::PoseStamped::ConstPtr& m) {
                                                      std::lock_guard<std::mutex> lock(mutex_);
                                                      path_[m->header.stamp.toSec()] = m->pose.position;
                                                    });
  }
  // Linear interpolation at stamp t; false outside the recorded range.
  bool at(double t, geometry_msgs::Point& p) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto hi = path_.lower_bound(t);
    if (hi == path_.end() || hi == path_.begin()) return false;
    auto lo = std::prev(hi);
    const double w = (t - lo->first) / (hi->first - lo->first);
    p.x = lo->second.x + w * (hi->second.x - lo->second.x);
    p.z = lo->second.z + w * (hi->second.z - lo->second.z);
    return true;
  }
  size_t count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return path_.size();
  }

 private:
  ros::Subscriber sub_;
  mutable std::mutex mutex_;
  std::map<double, geometry_msgs::Point> path_;
};

// Max |top - (vessel + offset)| over the states from kWarmup after the first; `n` = states compared.
double trackingError(const std::vector<riser_sim::LineState>& states, const VesselTrack& vessel, double offset,
                     int& n) {
  double worst = 0.0;
  n = 0;
  if (states.empty()) return worst;
  const double t_first = states.front().header.stamp.toSec();
  for (const auto& s : states) {
    const double t = s.header.stamp.toSec();
    geometry_msgs::Point v;
    if (t < t_first + kWarmup || !vessel.at(t, v)) continue;
    worst = std::max(worst, std::hypot(s.points[0].x - (v.x + offset), s.points[0].z - v.z));
    ++n;
  }
  return worst;
}

// Transports of this process's subscriptions to `topic` in the node `node` (its slave API getBusInfo).
std::vector<std::string> inboundTransports(const std::string& node, const std::string& topic) {
  std::vector<std::string> out;
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = std::string("/test_node_nodelets");
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, payload, false)) return out;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return out;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue bus_args, bus;
  bus_args[0] = std::string("/test_node_nodelets");
  if (!client.execute("getBusInfo", bus_args, bus) || bus.size() != 3) return out;
  // [connectionId, destinationId, direction (i/o), transport, topic, connected, ...]
  XmlRpc::XmlRpcValue& links = bus[2];
  for (int i = 0; i < links.size(); ++i)
    if (static_cast<std::string>(links[i][4]) == topic && static_cast<std::string>(links[i][2]) == "i")
      out.push_back(static_cast<std::string>(links[i][3]));
  return out;
}

bool advertised(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return true;
  return std::any_of(topics.begin(), topics.end(), [&](const ros::master::TopicInfo& t) { return t.name == topic; });
}

TEST(Nodelets, TwoRisersAndTheVesselShareOneManager) {
  ros::NodeHandle nh;
  VesselTrack vessel(nh);
  Recorder<riser_sim::LineState> state_a(nh, "/riser_a/riser_sim/state"), state_b(nh, "/riser_b/riser_sim/state");
  Recorder<riser_sim::Tension> tension_a(nh, "/riser_a/riser_sim/tension"), tension_b(nh, "/riser_b/riser_sim/tension");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(state_a.waitCount(1, 30.0)) << "riser_a runs";
  ASSERT_TRUE(state_b.waitCount(1, 30.0)) << "riser_b runs";
  ASSERT_TRUE(waitRosTime(kWarmup + 4.0, 30.0));  // a full surge period after the warm-up

  // Both follow the vessel from their own hang-off points.
  int na = 0, nb = 0;
  const double ea = trackingError(state_a.all(), vessel, -5.0, na), eb = trackingError(state_b.all(), vessel, 5.0, nb);
  std::printf("[ INFO ] max tracking error riser_a %.4f m over %d states, riser_b %.4f m over %d (tolerance %.4f m)\n",
              ea, na, eb, nb, kTrackTol);
  RecordProperty("max_tracking_error_a", std::to_string(ea));
  RecordProperty("max_tracking_error_b", std::to_string(eb));
  EXPECT_GE(na, 30);  // ~state at 10 Hz (node_defaults.yaml) over the 4 s after the warm-up: 40
  EXPECT_GE(nb, 30);
  EXPECT_LT(ea, kTrackTol);
  EXPECT_LT(eb, kTrackTol);

  // Frames carry each nodelet's own prefix (its name, not the manager's).
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(waitForFrames(buffer, {"riser_a/riser_sim/rfe_0", "riser_b/riser_sim/rfe_0"}, 10.0));
  EXPECT_FALSE(buffer.canTransform("world", "riser_manager/rfe_0", ros::Time(0)));
  const double gap = buffer.lookupTransform("world", "riser_b/riser_sim/rfe_0", ros::Time(0)).transform.translation.x -
                     buffer.lookupTransform("world", "riser_a/riser_sim/rfe_0", ros::Time(0)).transform.translation.x;
  EXPECT_NEAR(gap, 10.0, 2.0 * kTrackTol) << "the two tops 10 m apart (their tf stamps may differ by a publish period)";

  // Diagnostics named after each nodelet.
  ASSERT_TRUE(waitFor(
      [&] {
        bool a = false, b = false;
        for (const auto& d : diag.all())
          for (const auto& s : d.status) {
            a |= s.name == "riser_a/riser_sim: riser simulation";
            b |= s.name == "riser_b/riser_sim: riser simulation";
          }
        return a && b;
      },
      10.0));

  // The vessel's poses reach the risers inside the manager: roscpp joins a process's subscriptions to
  // one topic, so the manager has one inbound link on /vessel/pose serving both risers, intra-process
  // (the vessel publishes shared pointers: no serialisation, no copy).
  const auto links = inboundTransports("/riser_manager", "/vessel/pose");
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0], "INTRAPROCESS");

  // Unloading riser_a stops it and leaves riser_b running.
  ros::ServiceClient unload = nh.serviceClient<nodelet::NodeletUnload>("/riser_manager/unload_nodelet");
  ASSERT_TRUE(unload.waitForExistence(ros::Duration(10.0)));
  nodelet::NodeletUnload srv;
  srv.request.name = "/riser_a/riser_sim";
  ASSERT_TRUE(unload.call(srv));
  ASSERT_TRUE(srv.response.success);
  ASSERT_TRUE(waitFor([&] { return !advertised("/riser_a/riser_sim/tension"); }, 10.0))
      << "riser_a's publishers are gone";
  EXPECT_FALSE(ros::service::exists("/riser_a/riser_sim/reset", false));
  const size_t a_after = tension_a.count(), b_after = tension_b.count();
  ASSERT_TRUE(waitRosTime(1.0, 10.0));
  EXPECT_EQ(tension_a.count(), a_after) << "no tension from riser_a after unloading";
  EXPECT_GE(tension_b.count(), b_after + 15) << "riser_b still at 20 Hz (>= 15 in 1 s)";
  ros::ServiceClient reset_b = nh.serviceClient<std_srvs::Trigger>("/riser_b/riser_sim/reset");
  std_srvs::Trigger t;
  ASSERT_TRUE(reset_b.call(t));
  EXPECT_TRUE(t.response.success) << t.response.message;
  const size_t b_reset = state_b.count();
  ASSERT_TRUE(state_b.waitCount(b_reset + 5, 10.0)) << "riser_b publishes after its reset";
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_nodelets");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
