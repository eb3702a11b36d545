// 3D scenes in the node (node_spatial.test): the hang-off follows the rotated offset of a vessel that
// moves and yaws, the line leaves the x-z plane, its frames are unit rotations with x along the line;
// a yawed vessel at rest gives the rotated static result of the unyawed one.
#include <Eigen/Geometry>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

// Moving vessel [m, rad] at t [s]: surge 1.5 m / 6 s, sway 2 m / 8 s, heave 0.3 m / 3 s, yaw 0.4 rad / 8 s.
constexpr double kRate = 20.0;  // poses per second
const Eigen::Vector3d kOffset(5.0, 0.0, -1.0);
double w(double period) { return 2.0 * M_PI / period; }
Eigen::Vector3d vesselAt(double t) {
  return Eigen::Vector3d(1.5 * std::sin(w(6) * t), 2.0 * std::sin(w(8) * t), 0.3 * std::sin(w(3) * t));
}
double yawAt(double t) { return 0.4 * std::sin(w(8) * t); }
Eigen::Vector3d hangoffAt(double t) {
  return vesselAt(t) + Eigen::AngleAxisd(yawAt(t), Eigen::Vector3d::UnitZ()) * kOffset;
}
// Peak hang-off speed ~3.1 m/s (sway 1.57 + yaw 0.31 rad/s x 5 m); half a pose period of that motion.
constexpr double kTrackTol = 0.08;  // [m]
constexpr double kWarmup = 1.0;     // [s]

void setYaw(geometry_msgs::Pose& p, double yaw) {
  p.orientation.w = std::cos(0.5 * yaw);
  p.orientation.x = p.orientation.y = 0.0;
  p.orientation.z = std::sin(0.5 * yaw);
}

Eigen::Vector3d vec(const geometry_msgs::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }
Eigen::Vector3d vec(const geometry_msgs::Point& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

TEST(NodeSpatial, HangoffFollowsTheRotatedOffsetAndTheLineLeavesThePlane) {
  ros::NodeHandle nh;
  PosePublisher vessel(nh, "/moving/vessel/pose", kRate, [](double t, geometry_msgs::Pose& p) {
    const Eigen::Vector3d v = vesselAt(t);
    p.position.x = v.x(), p.position.y = v.y(), p.position.z = v.z();
    setYaw(p, yawAt(t));
  });
  Recorder<riser_sim::LineState> state(nh, "/moving/riser_sim/state");
  Recorder<tf2_msgs::TFMessage> tf(nh, "/tf");
  Recorder<geometry_msgs::WrenchStamped> wrench(nh, "/moving/riser_sim/top_wrench");
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/moving/riser_sim/markers");
  ASSERT_TRUE(waitFor([&] { return vessel.subscribers() > 0; }, 20.0));
  vessel.start();
  ASSERT_TRUE(state.waitCount(1, 20.0));
  ASSERT_TRUE(waitRosTime(kWarmup + 8.0, 40.0));  // a full sway and yaw period after the warm-up

  double worst = 0.0, end_y = 0.0;
  int n = 0;
  for (const auto& m : state.all()) {
    ASSERT_TRUE(finite(m));
    ASSERT_EQ(m.points.size(), 12u);  // A_0..A_10 and the end
    const double t = PosePublisher::timeOf(vessel.startTime(), m.header.stamp);
    if (t < kWarmup) continue;
    worst = std::max(worst, (vec(m.points.front()) - hangoffAt(t)).norm());
    end_y = std::max(end_y, std::abs(m.points.back().y));
    ++n;
  }
  std::printf(
      "[ INFO ] 3D hang-off: largest distance from the rotated offset %.4f m (tolerance %.2f m) over %d "
      "states; end of the line up to %.2f m out of the x-z plane\n",
      worst, kTrackTol, n, end_y);
  EXPECT_GT(n, 100);
  EXPECT_LT(worst, kTrackTol);
  EXPECT_GT(end_y, 1.0);

  // rfe_0's frame: at the hang-off, a unit rotation, x along the line (hanging: mostly down).
  int frames = 0;
  double tf_worst = 0.0;
  for (const auto& m : tf.all()) {
    ASSERT_TRUE(finite(m));
    for (const auto& tr : m.transforms) {
      if (tr.child_frame_id != "moving/riser_sim/rfe_0") continue;
      const double t = PosePublisher::timeOf(vessel.startTime(), tr.header.stamp);
      if (t < kWarmup) continue;
      const auto& r = tr.transform.rotation;
      const Eigen::Quaterniond q(r.w, r.x, r.y, r.z);
      EXPECT_NEAR(q.norm(), 1.0, 1e-9);
      EXPECT_LT((q * Eigen::Vector3d::UnitX()).z(), -0.5);
      tf_worst = std::max(tf_worst, (vec(tr.transform.translation) - hangoffAt(t)).norm());
      ++frames;
    }
  }
  EXPECT_GT(frames, 100);
  EXPECT_LT(tf_worst, kTrackTol);
  for (const auto& m : wrench.all()) EXPECT_TRUE(finite(m));
  for (const auto& m : markers.all()) EXPECT_TRUE(finite(m));
}

// Tether from the hang-off (offset [8, 0, 0] on a vessel at the origin) to an anchor 15 m below the
// origin: a yaw of 60 deg rotates the whole static problem about world z.
TEST(NodeSpatial, YawedVesselAtRestGivesTheRotatedStatics) {
  ros::NodeHandle nh;
  const double yaw = M_PI / 3.0;
  const auto still = [](double angle) { return [angle](double, geometry_msgs::Pose& p) { setYaw(p, angle); }; };
  PosePublisher flat(nh, "/flat/vessel/pose", 10.0, still(0.0)), yawed(nh, "/yawed/vessel/pose", 10.0, still(yaw)),
      body(nh, "/yawed_body/vessel/pose", 10.0, still(yaw));
  Recorder<geometry_msgs::WrenchStamped> top_flat(nh, "/flat/riser_sim/top_wrench"),
      top_yawed(nh, "/yawed/riser_sim/top_wrench"), top_body(nh, "/yawed_body/riser_sim/top_wrench"),
      bottom_flat(nh, "/flat/riser_sim/bottom_wrench"), bottom_yawed(nh, "/yawed/riser_sim/bottom_wrench");
  Recorder<riser_sim::LineState> state_flat(nh, "/flat/riser_sim/state"), state_yawed(nh, "/yawed/riser_sim/state");
  ASSERT_TRUE(waitFor([&] { return flat.subscribers() && yawed.subscribers() && body.subscribers(); }, 20.0));
  flat.start(), yawed.start(), body.start();
  for (auto* r : {&top_flat, &top_yawed, &top_body, &bottom_flat, &bottom_yawed}) ASSERT_TRUE(r->waitCount(1, 20.0));
  ASSERT_TRUE(state_flat.waitCount(1, 10.0) && state_yawed.waitCount(1, 10.0));
  ASSERT_TRUE(waitRosTime(2.0, 20.0));  // at rest: nothing should move

  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d f0 = vec(top_flat.last().wrench.force), f1 = vec(top_yawed.last().wrench.force);
  const Eigen::Vector3d fb = vec(top_body.last().wrench.force);
  const Eigen::Vector3d b0 = vec(bottom_flat.last().wrench.force), b1 = vec(bottom_yawed.last().wrench.force);
  const double tol = 1e-3;  // [N], of a 875 N top force (measured ~1e-10 N)
  std::printf(
      "[ INFO ] top force flat (%.3f, %.3f, %.3f) N; yawed minus rotated %.2e N; body frame minus flat "
      "%.2e N; bottom: yawed minus rotated %.2e N\n",
      f0.x(), f0.y(), f0.z(), (f1 - R * f0).norm(), (fb - f0).norm(), (b1 - R * b0).norm());
  EXPECT_GT(f0.norm(), 100.0);
  EXPECT_GT(std::abs(f0.x()), 10.0);  // the tether pulls the hang-off towards the axis: not just the weight
  EXPECT_LT((f1 - R * f0).norm(), tol);
  EXPECT_LT((fb - f0).norm(), tol);
  EXPECT_LT((b1 - R * b0).norm(), tol);
  EXPECT_EQ(top_body.last().header.frame_id, "vessel");
  EXPECT_EQ(top_yawed.last().header.frame_id, "world");
  const auto s0 = state_flat.last(), s1 = state_yawed.last();
  ASSERT_EQ(s0.points.size(), s1.points.size());
  double shape = 0.0;
  for (size_t i = 0; i < s0.points.size(); ++i)
    shape = std::max(shape, (vec(s1.points[i]) - R * vec(s0.points[i])).norm());
  std::printf("[ INFO ] shape: yawed minus rotated flat %.2e m\n", shape);
  EXPECT_LT(shape, 1e-6);  // [m] (measured ~1e-13 m)
  EXPECT_NEAR(s0.points.front().x, 8.0, 1e-6);
  EXPECT_NEAR(s1.points.front().y, 8.0 * std::sin(yaw), 1e-6);
  // ~state's bending in 3D: per joint (n = 10), the moment vector turns with the problem; at rest the
  // moment is EI κ (EI = 100 N m²; the damper's share is its rate, ~0 at rest: 1e-3 N m of ~10 N m).
  ASSERT_EQ(s0.curvatures.size(), 10u);
  ASSERT_EQ(s1.bending_moment_vectors.size(), 10u);
  ASSERT_EQ(s1.bending_moments.size(), 10u);
  double turned = 0.0, biggest = 0.0;
  for (size_t j = 0; j < 10; ++j) {
    turned = std::max(turned, (vec(s1.bending_moment_vectors[j]) - R * vec(s0.bending_moment_vectors[j])).norm());
    biggest = std::max(biggest, s1.bending_moments[j]);
    EXPECT_NEAR(s1.bending_moments[j], 100.0 * s1.curvatures[j], 1e-3) << "joint " << j + 1;
    EXPECT_NEAR(s1.bending_moments[j], vec(s1.bending_moment_vectors[j]).norm(), 1e-12);
  }
  std::printf("[ INFO ] bending: largest %.3f N m; yawed minus rotated flat moment vectors %.2e N m\n", biggest,
              turned);
  EXPECT_GT(biggest, 1.0);
  EXPECT_LT(turned, 1e-3);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_spatial");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
