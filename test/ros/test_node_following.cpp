// The vessel surges and heaves; the riser's top (~state point 0, rfe_0 frame, the marker line's first
// vertex) follows it, for each vessel input (pose, odom, tf).
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_broadcaster.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

// Vessel path [m] at t [s] since the start: surge 2 m / 4 s, heave 0.5 m / 3 s.
constexpr double kSurge = 2.0, kSurgePeriod = 4.0, kHeave = 0.5, kHeavePeriod = 3.0;
constexpr double kRate = 20.0;  // poses per second
double surge(double t) { return kSurge * std::sin(2 * M_PI * t / kSurgePeriod); }
double heave(double t) { return kHeave * std::sin(2 * M_PI * t / kHeavePeriod); }
// One pose period of the fastest vessel motion: what the top may lag behind by at most (spec), 0.157 m.
const double kOnePeriodOfMotion = kSurge * 2 * M_PI / kSurgePeriod / kRate;
// ExternalMotion predicts to the end of its blend: the error is second order (~1 cm here); half a pose
// period of motion leaves margin for the node's loop and delivery latency.
const double kTrackTol = 0.5 * kOnePeriodOfMotion;
constexpr double kWarmup = 1.0;  // [s] the motion's fit window fills, the start-up transient passes

class Vessel {
 public:
  explicit Vessel(ros::NodeHandle& nh)
      : pose_pub_(nh.advertise<geometry_msgs::PoseStamped>("/vessel/pose", 10)),
        odom_pub_(nh.advertise<nav_msgs::Odometry>("/odom/vessel/odom", 10)) {
    timer_ = nh.createTimer(
        ros::Duration(1.0 / kRate), [this](const ros::TimerEvent&) { send(); }, false, false);
  }
  void start() {
    t0_ = ros::Time::now();
    timer_.start();
  }
  double t(const ros::Time& stamp) const { return (stamp - t0_).toSec(); }
  bool connected() const { return pose_pub_.getNumSubscribers() > 0 && odom_pub_.getNumSubscribers() > 0; }

 private:
  void send() {
    const ros::Time now = ros::Time::now();
    const double t = (now - t0_).toSec();
    geometry_msgs::PoseStamped p;
    p.header.stamp = now;
    p.header.frame_id = "world";
    p.pose.position.x = surge(t);
    p.pose.position.z = heave(t);
    p.pose.orientation.w = 1.0;
    pose_pub_.publish(p);
    nav_msgs::Odometry o;
    o.header = p.header;
    o.child_frame_id = "vessel";
    o.pose.pose = p.pose;
    odom_pub_.publish(o);
    geometry_msgs::TransformStamped tr;
    tr.header = p.header;
    tr.child_frame_id = "vessel_tf";
    tr.transform.translation.x = p.pose.position.x;
    tr.transform.translation.z = p.pose.position.z;
    tr.transform.rotation.w = 1.0;
    tf_.sendTransform(tr);
  }
  ros::Publisher pose_pub_, odom_pub_;
  tf2_ros::TransformBroadcaster tf_;
  ros::Timer timer_;
  ros::Time t0_;
};

struct Tracking {
  double max_error = 0.0;
  double x_min = 1e9, x_max = -1e9;  // range of the top's x
  double end_x_min = 1e9, end_x_max = -1e9;
  int samples = 0;
};

Tracking trackState(const std::vector<riser_sim::LineState>& msgs, const Vessel& v) {
  Tracking tr;
  for (const auto& m : msgs) {
    const double t = v.t(m.header.stamp);
    if (t < kWarmup) continue;
    const auto& top = m.points.front();
    tr.max_error = std::max(tr.max_error, std::hypot(top.x - surge(t), top.z - heave(t)));
    tr.x_min = std::min(tr.x_min, top.x), tr.x_max = std::max(tr.x_max, top.x);
    tr.end_x_min = std::min(tr.end_x_min, m.points.back().x);
    tr.end_x_max = std::max(tr.end_x_max, m.points.back().x);
    ++tr.samples;
    EXPECT_TRUE(finite(m));
  }
  return tr;
}

TEST(NodeFollowing, TopFollowsTheVesselForEveryInput) {
  ros::NodeHandle nh;
  Vessel vessel(nh);
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state"), state_odom(nh, "/odom/riser_sim/state"),
      state_tf(nh, "/tfin/riser_sim/state");
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/riser_sim/markers");
  Recorder<tf2_msgs::TFMessage> tf(nh, "/tf");
  ASSERT_TRUE(waitFor([&] { return vessel.connected(); }, 20.0));
  vessel.start();
  ASSERT_TRUE(state.waitCount(1, 20.0));
  ASSERT_TRUE(waitRosTime(kWarmup + kSurgePeriod, 30.0));  // a full surge period after the warm-up

  const char* names[] = {"pose", "odom", "tf"};
  int k = 0;
  for (auto* rec : {&state, &state_odom, &state_tf}) {
    const Tracking tr = trackState(rec->all(), vessel);
    std::printf("[ INFO ] %s input: max tracking error of the top %.4f m (tolerance %.4f m) over %d states\n", names[k],
                tr.max_error, kTrackTol, tr.samples);
    RecordProperty(std::string("max_tracking_error_") + names[k++], std::to_string(tr.max_error));
    ASSERT_GT(tr.samples, 40);
    EXPECT_LT(tr.max_error, kTrackTol);
    EXPECT_GT(tr.x_max - tr.x_min, 1.8 * kSurge);          // the top surged through nearly the full range
    EXPECT_GT(tr.end_x_max - tr.end_x_min, 0.2 * kSurge);  // and the bottom followed
  }

  // rfe_0's tf origin and the marker line's first vertex follow too.
  int tf_checked = 0;
  for (const auto& m : tf.all())
    for (const auto& t : m.transforms) {
      if (t.child_frame_id != "riser_sim/rfe_0") continue;
      const double s = vessel.t(t.header.stamp);
      if (s < kWarmup) continue;
      EXPECT_NEAR(t.transform.translation.x, surge(s), kTrackTol);
      EXPECT_NEAR(t.transform.translation.z, heave(s), kTrackTol);
      ++tf_checked;
    }
  EXPECT_GT(tf_checked, 40);
  int markers_checked = 0;
  for (const auto& m : markers.all()) {
    ASSERT_TRUE(finite(m));
    for (const auto& mk : m.markers) {
      if (mk.ns != "line") continue;
      const double s = vessel.t(mk.header.stamp);
      if (s < kWarmup) continue;
      EXPECT_NEAR(mk.points.front().x, surge(s), kTrackTol);
      EXPECT_NEAR(mk.points.front().z, heave(s), kTrackTol);
      ++markers_checked;
    }
  }
  EXPECT_GT(markers_checked, 20);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_following");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
