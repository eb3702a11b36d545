// Vessel at rest at (3, 0.5, -2) with hang-off offset (1, 0, -0.5): the riser hangs straight down from
// (4, -2.5) in the world x-z plane.
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

// Scene small_riser.yaml: (20 m * 5 kg/m + 50 kg) * 9.81 m/s^2.
constexpr double kWeight = (20.0 * 5.0 + 50.0) * 9.81;
// The statics converge to 1e-9 of the weight and the line starts at rest in that equilibrium; the
// integration keeps it there to round-off. 1e-6 relative leaves room for both.
constexpr double kStaticTol = 1e-6 * kWeight;
constexpr double kHangX = 4.0, kHangZ = -2.5;  // vessel (3, 0.5, -2) + offset (1, 0, -0.5), y dropped
constexpr int kBodies = 11;                    // n + 1 rfes, n = 10
constexpr double kRateTol = 0.25;              // rates counted over a ROS-time window: +-25 %

class NodeStatic : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    nh_ = new ros::NodeHandle;
    pose_ = new PosePublisher(*nh_, "vessel/pose", 20.0, [](double, geometry_msgs::Pose& p) {
      p.position.x = 3.0;
      p.position.y = 0.5;
      p.position.z = -2.0;
    });
    tension_ = new Recorder<riser_sim::Tension>(*nh_, "riser_sim/tension");
    state_ = new Recorder<riser_sim::LineState>(*nh_, "riser_sim/state");
    markers_ = new Recorder<visualization_msgs::MarkerArray>(*nh_, "riser_sim/markers");
    wrench_ = new Recorder<geometry_msgs::WrenchStamped>(*nh_, "riser_sim/top_wrench");
    tf_ = new Recorder<tf2_msgs::TFMessage>(*nh_, "/tf");
    diag_ = new Recorder<diagnostic_msgs::DiagnosticArray>(*nh_, "/diagnostics");
    ASSERT_TRUE(waitFor([] { return pose_->subscribers() > 0; }, 20.0)) << "node never subscribed to vessel/pose";
    pose_->start();
    ASSERT_TRUE(tension_->waitCount(1, 20.0)) << "no ~tension within 20 s of the first pose";
  }
  static ros::NodeHandle* nh_;
  static PosePublisher* pose_;
  static Recorder<riser_sim::Tension>* tension_;
  static Recorder<riser_sim::LineState>* state_;
  static Recorder<visualization_msgs::MarkerArray>* markers_;
  static Recorder<geometry_msgs::WrenchStamped>* wrench_;
  static Recorder<tf2_msgs::TFMessage>* tf_;
  static Recorder<diagnostic_msgs::DiagnosticArray>* diag_;
};
ros::NodeHandle* NodeStatic::nh_;
PosePublisher* NodeStatic::pose_;
Recorder<riser_sim::Tension>* NodeStatic::tension_;
Recorder<riser_sim::LineState>* NodeStatic::state_;
Recorder<visualization_msgs::MarkerArray>* NodeStatic::markers_;
Recorder<geometry_msgs::WrenchStamped>* NodeStatic::wrench_;
Recorder<tf2_msgs::TFMessage>* NodeStatic::tf_;
Recorder<diagnostic_msgs::DiagnosticArray>* NodeStatic::diag_;

TEST_F(NodeStatic, TopTensionIsTheWeightInAir) {
  ASSERT_TRUE(tension_->waitCount(5, 10.0));
  for (const auto& m : tension_->all()) {
    ASSERT_EQ(m.axial_force.size(), static_cast<size_t>(kBodies));
    ASSERT_EQ(m.arc_length.size(), static_cast<size_t>(kBodies));
    EXPECT_NEAR(m.top, kWeight, kStaticTol);
    EXPECT_NEAR(m.max, kWeight, 0.1 * kWeight);  // the largest force is near the top (rfe 0's mid)
    EXPECT_GT(m.bottom, 50.0 * 9.81 * 0.99);     // at least the end mass hangs below the last rfe
    EXPECT_EQ(m.header.frame_id, "world");
  }
}

TEST_F(NodeStatic, TopWrenchIsTheWeightPullingDown) {
  ASSERT_TRUE(wrench_->waitCount(3, 10.0));
  const auto w = wrench_->last();
  EXPECT_EQ(w.header.frame_id, "world");
  EXPECT_NEAR(w.wrench.force.x, 0.0, kStaticTol);
  EXPECT_EQ(w.wrench.force.y, 0.0);
  EXPECT_NEAR(w.wrench.force.z, -kWeight, kStaticTol);
  // Moment about the hang-off point (as in 3D): the planar top is pinned, the force acts at that point.
  EXPECT_EQ(w.wrench.torque.x, 0.0);
  EXPECT_EQ(w.wrench.torque.y, 0.0);
  EXPECT_EQ(w.wrench.torque.z, 0.0);
}

TEST_F(NodeStatic, StateHangsStraightDownFromTheHangOff) {
  ASSERT_TRUE(state_->waitCount(2, 10.0));
  const auto s = state_->last();
  ASSERT_EQ(s.points.size(), static_cast<size_t>(kBodies + 1));
  ASSERT_EQ(s.angles.size(), static_cast<size_t>(kBodies));
  ASSERT_EQ(s.elongations.size(), static_cast<size_t>(kBodies));
  ASSERT_EQ(s.bending_moments.size(), static_cast<size_t>(kBodies - 1));
  EXPECT_NEAR(s.points.front().x, kHangX, 1e-9);
  EXPECT_EQ(s.points.front().y, 0.0);
  EXPECT_NEAR(s.points.front().z, kHangZ, 1e-9);
  // Inextensible 20 m line hanging straight: the end point is 20 m below, every angle -90 degrees.
  EXPECT_NEAR(s.points.back().x, kHangX, 1e-6);
  EXPECT_NEAR(s.points.back().z, kHangZ - 20.0, 1e-6);
  for (double a : s.angles) EXPECT_NEAR(a, -M_PI / 2, 1e-6);
}

TEST_F(NodeStatic, PublishesAtTheConfiguredRates) {
  ASSERT_TRUE(markers_->waitCount(1, 10.0));
  const ros::Time from = ros::Time::now();
  ASSERT_TRUE(waitRosTime(3.0, 20.0));
  const ros::Time to = ros::Time::now();
  const double span = (to - from).toSec();
  auto expectRate = [&](const char* what, size_t count, double hz) {
    EXPECT_NEAR(count / span, hz, kRateTol * hz) << what << ": " << count << " messages in " << span << " s";
  };
  expectRate("tension", tension_->countBetween(from, to), 20.0);
  expectRate("state", state_->countBetween(from, to), 10.0);
  expectRate("markers", markers_->countBetween(from, to), 10.0);
  expectRate("top_wrench", wrench_->countBetween(from, to), 20.0);  // rates/wrench defaults to rates/tension
  // /tf may carry other publishers' frames: count the node's messages (by stamp) only.
  size_t tf_count = 0;
  {
    const auto all = tf_->all();
    for (const auto& m : all)
      if (!m.transforms.empty() && m.transforms[0].child_frame_id == "riser_sim/rfe_0" &&
          m.transforms[0].header.stamp >= from - ros::Duration(0.01) && m.transforms[0].header.stamp < to)
        ++tf_count;
  }
  expectRate("tf", tf_count, 20.0);
}

TEST_F(NodeStatic, TfFramesMatchTheState) {
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(waitFor([&] { return buffer.canTransform("world", "riser_sim/end", ros::Time(0)); }, 10.0));
  const auto s = state_->last();
  for (int i = 0; i < kBodies; ++i) {
    const std::string frame = "riser_sim/rfe_" + std::to_string(i);
    ASSERT_TRUE(buffer.canTransform("world", frame, ros::Time(0))) << frame;
    const auto t = buffer.lookupTransform("world", frame, ros::Time(0));
    EXPECT_NEAR(t.transform.translation.x, s.points[i].x, 1e-9) << frame;
    EXPECT_NEAR(t.transform.translation.y, 0.0, 1e-12) << frame;
    EXPECT_NEAR(t.transform.translation.z, s.points[i].z, 1e-9) << frame;
    // x axis along the rfe: hanging down, the frame's x axis is world -z (rotation +90 deg about y).
    const auto& q = t.transform.rotation;
    const double xz = 2.0 * (q.x * q.z - q.w * q.y);  // world z of the frame's x axis
    EXPECT_NEAR(xz, -1.0, 1e-6) << frame;
  }
  EXPECT_FALSE(buffer.canTransform("world", "riser_sim/rfe_" + std::to_string(kBodies), ros::Time(0)));
}

TEST_F(NodeStatic, MarkersShowTheLineAndTheTopTension) {
  ASSERT_TRUE(markers_->waitCount(2, 10.0));
  const auto m = markers_->last();
  ASSERT_TRUE(finite(m));
  const visualization_msgs::Marker* line = nullptr;
  const visualization_msgs::Marker* text = nullptr;
  for (const auto& mk : m.markers) {
    if (mk.ns == "line") line = &mk;
    if (mk.ns == "top_tension") text = &mk;
  }
  ASSERT_NE(line, nullptr);
  ASSERT_NE(text, nullptr);
  EXPECT_EQ(line->type, visualization_msgs::Marker::LINE_STRIP);
  ASSERT_EQ(line->points.size(), static_cast<size_t>(kBodies + 1));
  EXPECT_EQ(line->colors.size(), line->points.size());
  EXPECT_NEAR(line->points[0].x, kHangX, 1e-9);
  EXPECT_NEAR(line->points[0].z, kHangZ, 1e-9);
  EXPECT_NE(text->text.find("1.47 kN"), std::string::npos) << text->text;
}

TEST_F(NodeStatic, DiagnosticsReportRealTime) {
  ASSERT_TRUE(waitFor(
      [] {
        if (diag_->count() == 0) return false;
        return diagValue(diag_->last(), "riser_sim", "mode") == "running";
      },
      10.0));
  ASSERT_TRUE(diag_->waitCount(diag_->count() + 1, 5.0));  // a full window after the start
  const auto d = diag_->last();
  ASSERT_FALSE(d.status.empty());
  EXPECT_EQ(d.status[0].level, diagnostic_msgs::DiagnosticStatus::OK) << d.status[0].message;
  const double rtf = std::stod(diagValue(d, "riser_sim", "real-time factor"));
  EXPECT_NEAR(rtf, 1.0, 0.05);  // keeps up with the clock (n = 10 is ~100x faster than real time)
  EXPECT_LT(std::stod(diagValue(d, "riser_sim", "constraint error [m]")), 1e-9);
  for (const auto& s : d.status)
    for (const auto& kv : s.values) EXPECT_EQ(kv.value.find("nan"), std::string::npos) << kv.key;
}

TEST_F(NodeStatic, ResetRecomputesTheStatics) {
  ros::ServiceClient client = nh_->serviceClient<std_srvs::Trigger>("riser_sim/reset");
  ASSERT_TRUE(client.waitForExistence(ros::Duration(10.0)));
  std_srvs::Trigger srv;
  ASSERT_TRUE(client.call(srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_NE(srv.response.message.find("static equilibrium"), std::string::npos) << srv.response.message;
  const size_t n = tension_->count();
  ASSERT_TRUE(tension_->waitCount(n + 3, 10.0));
  EXPECT_NEAR(tension_->last().top, kWeight, kStaticTol);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_static");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
