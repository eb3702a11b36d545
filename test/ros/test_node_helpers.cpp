// The node's ROS-side helpers, without a master: parameter tree -> YAML -> scene, pose checks, the
// paper -> world mapping of the messages, marker colours, timing percentiles, the sample buffer.
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/planar/force_term.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages.h"
#include "riser_sim_ros/tf_listener.h"
#include "riser_sim_ros/timing_stats.h"
#include "riser_sim_ros/vessel_input.h"
#include "riser_sim_ros/xmlrpc_yaml.h"

namespace riser_sim_ros {
namespace {

XmlRpc::XmlRpcValue sceneTree() {
  XmlRpc::XmlRpcValue t;
  t["name"] = std::string("tree");
  t["line"]["length"] = 20.0;
  t["line"]["elements"] = 4;
  t["line"]["mass_per_length"] = 5.0;
  t["line"]["EA"] = std::string("1.0e6");  // PyYAML loads 1.0e6 (no exponent sign) as a string
  t["line"]["EI"] = 0;                     // an int where a float is meant
  t["line"]["bending"] = false;
  t["top"]["position"][0] = 1.5;
  t["top"]["position"][1] = -2;
  t["solver"]["dt"] = 1e-4;
  return t;
}

TEST(XmlRpcYaml, ParameterTreeParsesLikeTheSceneFile) {
  XmlRpc::XmlRpcValue t = sceneTree();
  const riser_sim::Scene s = riser_sim::parseScene(toYaml(t));
  EXPECT_EQ(s.name, "tree");
  EXPECT_EQ(s.elements, 4);
  EXPECT_EQ(s.length, 20.0);
  EXPECT_EQ(s.line.EA, 1.0e6);
  EXPECT_FALSE(s.options.bending);
  EXPECT_EQ(s.top.position.x(), 1.5);
  EXPECT_EQ(s.top.position.y(), 0.0);  // [x, z]: (x, 0, z)
  EXPECT_EQ(s.top.position.z(), -2.0);
  EXPECT_EQ(s.solver.dt, 1e-4);  // doubles round-trip exactly (%.17g)
}

TEST(XmlRpcYaml, ErrorsNameTheParameterPath) {
  XmlRpc::XmlRpcValue t = sceneTree();
  t["line"]["elements"] = 0;
  try {
    riser_sim::parseScene(toYaml(t));
    FAIL();
  } catch (const riser_sim::SceneError& e) {
    EXPECT_EQ(paramPath("~scene", e.key()), "~scene/line/elements");
  }
  EXPECT_EQ(paramPath("~scene", "top.motion.knots[1][0]"), "~scene/top/motion/knots[1][0]");
  EXPECT_EQ(paramPath("~scene", ""), "~scene");
  XmlRpc::XmlRpcValue bad;
  bad["line"]["length"] = XmlRpc::XmlRpcValue(reinterpret_cast<void*>(const_cast<char*>("ab")), 2);  // base64
  try {
    toYaml(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("line.length:", 0), 0u) << e.what();
  }
}

std_msgs::Header header(const char* frame, double stamp = 10.0) {
  std_msgs::Header h;
  h.frame_id = frame;
  h.stamp = ros::Time(stamp);
  return h;
}

geometry_msgs::Pose unitPose() {
  geometry_msgs::Pose p;
  p.orientation.w = 1.0;
  return p;
}

TEST(CheckPose, AcceptsValidAndNamesEachProblem) {
  Eigen::Isometry3d pose;
  geometry_msgs::Pose p = unitPose();
  p.position.x = 1.0;
  p.orientation.w = 1.005;  // within 1 %: normalised
  EXPECT_EQ(checkPose(header("world"), p, "world", pose), "");
  EXPECT_NEAR(Eigen::Quaterniond(pose.rotation()).norm(), 1.0, 1e-12);
  EXPECT_EQ(checkPose(header("/world"), p, "world", pose), "");  // leading slash ignored
  EXPECT_NE(checkPose(header("map"), p, "world", pose).find("frame_id"), std::string::npos);
  EXPECT_NE(checkPose(header("world", 0.0), p, "world", pose).find("stamp is zero"), std::string::npos);
  geometry_msgs::Pose q = unitPose();
  q.position.y = std::nan("");
  EXPECT_NE(checkPose(header("world"), q, "world", pose).find("position"), std::string::npos);
  q = unitPose();
  q.orientation.w = 0.0;
  EXPECT_NE(checkPose(header("world"), q, "world", pose).find("zero quaternion"), std::string::npos);
  q.orientation.w = 1.5;
  EXPECT_NE(checkPose(header("world"), q, "world", pose).find("unit quaternion"), std::string::npos);
  q.orientation.w = INFINITY;
  EXPECT_NE(checkPose(header("world"), q, "world", pose).find("orientation is not finite"), std::string::npos);
  q = unitPose();
  q.position.z = 1e30;  // finite, absurd: would drive the top at 1e30 m
  EXPECT_NE(checkPose(header("world"), q, "world", pose, 1e7).find("beyond ~max_position"), std::string::npos);
  q.position.z = -9.9e6;  // a UTM northing is fine
  EXPECT_EQ(checkPose(header("world"), q, "world", pose, 1e7), "");
}

// What tf2's BufferCore::setTransform refuses (and logs per message) must be refused before it.
TEST(CheckTransform, RefusesWhatTf2WouldRefuse) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "/world";
  t.child_frame_id = "vessel";
  t.transform.rotation.w = 1.0;
  EXPECT_EQ(checkTransform(t), "");
  t.transform.rotation.w = 1.0 + 4e-6;  // |q|^2 - 1 = 8e-6: under tf2's 1e-5
  EXPECT_EQ(checkTransform(t), "");
  t.transform.rotation.w = 1.0 + 6e-6;  // 1.2e-5: tf2 refuses it
  EXPECT_NE(checkTransform(t).find("not a unit quaternion"), std::string::npos);
  t.transform.rotation.w = 0.0;
  EXPECT_NE(checkTransform(t).find("zero quaternion"), std::string::npos);
  t.transform.rotation.w = 1.0;
  t.transform.translation.y = NAN;
  EXPECT_NE(checkTransform(t).find("translation is not finite"), std::string::npos);
  t.transform.translation.y = 0.0;
  t.transform.rotation.z = INFINITY;
  EXPECT_NE(checkTransform(t).find("rotation is not finite"), std::string::npos);
  t.transform.rotation.z = 0.0;
  t.child_frame_id = "world";
  EXPECT_NE(checkTransform(t).find("both 'world'"), std::string::npos);
  t.child_frame_id = "";
  EXPECT_NE(checkTransform(t).find("child_frame_id is empty"), std::string::npos);
}

TEST(CheckStamp, AgeLeadAndOrder) {
  const ros::Time now(1000.0), none;
  EXPECT_EQ(checkStamp(ros::Time(999.5), now, none, 1.0, 0.5), "");
  EXPECT_EQ(checkStamp(ros::Time(1000.4), now, none, 1.0, 0.5), "");
  EXPECT_NE(checkStamp(ros::Time(998.0), now, none, 1.0, 0.5).find("2 s older than ROS time (~max_pose_age 1 s"),
            std::string::npos);
  EXPECT_NE(checkStamp(ros::Time(2000.0), now, none, 1.0, 0.5).find("1000 s ahead of ROS time (~max_pose_lead"),
            std::string::npos);
  EXPECT_NE(checkStamp(ros::Time(999.8), now, ros::Time(999.9), 1.0, 0.5).find("out of order"), std::string::npos);
  EXPECT_NE(checkStamp(ros::Time(999.9), now, ros::Time(999.9), 1.0, 0.5).find("repeats"), std::string::npos);
  EXPECT_EQ(checkStamp(ros::Time(999.95), now, ros::Time(999.9), 1.0, 0.5), "");
}

TEST(WarnThrottle, OnePerPeriodAndCountsTheRest) {
  WarnThrottle t(2.0);
  const auto t0 = std::chrono::steady_clock::now();
  auto at = [&](double s) {
    return t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
  };
  long suppressed = -1;
  ASSERT_TRUE(t.allow(at(0.0), suppressed));
  EXPECT_EQ(suppressed, 0);
  for (int i = 1; i <= 100; ++i) EXPECT_FALSE(t.allow(at(1.99 * i / 100), suppressed));
  ASSERT_TRUE(t.allow(at(2.0), suppressed));
  EXPECT_EQ(suppressed, 100);
  EXPECT_FALSE(t.allow(at(3.9), suppressed));
  ASSERT_TRUE(t.allow(at(10.0), suppressed));
  EXPECT_EQ(suppressed, 1);
}

TEST(CheckPose, HangOffIsPoseTimesOffsetProjectedOntoXZ) {
  // Vessel at (10, 3, -1) pitched by 90 degrees about world y: vessel x -> world -z.
  geometry_msgs::Pose p;
  p.position.x = 10.0;
  p.position.y = 3.0;
  p.position.z = -1.0;
  p.orientation.y = std::sin(M_PI / 4);
  p.orientation.w = std::cos(M_PI / 4);
  Eigen::Isometry3d pose;
  ASSERT_EQ(checkPose(header("world"), p, "world", pose), "");
  const Eigen::Vector3d hang = pose * Eigen::Vector3d(2.0, 0.0, 0.0);
  EXPECT_NEAR(hang.x(), 10.0, 1e-12);
  EXPECT_NEAR(hang.z(), -3.0, 1e-12);
  const Eigen::Vector2d paper = toPaper(hang);
  EXPECT_NEAR(paper.x(), 10.0, 1e-12);
  EXPECT_NEAR(paper.y(), -3.0, 1e-12);  // world y (3 m) dropped
}

// The filler maps RunOutputs onto the messages as they are: a planar state (angles, y = 0, moments about -y), its
// frame ids, and a body-frame wrench turned by the inverse vessel attitude.
TEST(LineMessages, FilledFromTheRunsOutputs) {
  using riser_sim::Vec3;
  riser_sim::RunOutputs out;
  out.points = {Vec3(0, 0, 0), Vec3(1, 0, -1), Vec3(2, 0, -2), Vec3(3, 0, -3)};
  out.angles = {-M_PI / 4, -M_PI / 4, -M_PI / 4};
  out.frames.assign(3, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY())));
  out.elongations = {0, 0, 0};
  out.axial_force = {30, 20, 10};
  out.arc_length = {0.5, 2, 3.5};
  out.bending_moment = {2.0, -1.0};
  out.bending_moment_vector = {Vec3(0, -2.0, 0), Vec3(0, 1.0, 0)};
  out.curvature = {0.0, 0.0};
  out.top_force = Vec3(-5, 0, -30);
  out.top_tension = out.top_force.norm();
  ASSERT_TRUE(riser_sim::allFinite(out));
  LineMessages m(3, "world", "ns/riser");
  m.fillState(out, ros::Time(1));
  EXPECT_EQ(m.state.points[2].x, 2.0);
  EXPECT_EQ(m.state.points[2].y, 0.0);
  EXPECT_EQ(m.state.points[2].z, -2.0);
  ASSERT_EQ(m.state.angles.size(), 3u);
  EXPECT_EQ(m.state.bending_moments[1], -1.0);
  EXPECT_EQ(m.state.bending_moment_vectors[1].y, 1.0);
  m.fillTension(out, ros::Time(1));
  EXPECT_EQ(m.tension.arc_length[2], 3.5);
  m.fillTopWrench(out, Eigen::Quaterniond::Identity(), ros::Time(1));
  EXPECT_EQ(m.top_wrench.wrench.force.x, -5.0);
  EXPECT_EQ(m.top_wrench.wrench.force.z, -30.0);
  EXPECT_EQ(m.top_wrench.header.frame_id, "world");
  m.fillTransforms(out, ros::Time(1));
  ASSERT_EQ(m.transforms.size(), 4u);
  EXPECT_EQ(m.transforms[0].child_frame_id, "ns/riser/rfe_0");
  EXPECT_EQ(m.transforms[3].child_frame_id, "ns/riser/end");
  // The frame's x axis points along the rfe: (cos φ, 0, sin φ) in the world.
  const auto& q = m.transforms[1].transform.rotation;
  const Eigen::Vector3d x_axis = Eigen::Quaterniond(q.w, q.x, q.y, q.z) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(x_axis.x(), std::cos(-M_PI / 4), 1e-12);
  EXPECT_NEAR(x_axis.y(), 0.0, 1e-12);
  EXPECT_NEAR(x_axis.z(), std::sin(-M_PI / 4), 1e-12);
  // In the vessel's frame: a vessel yawed 90 deg sees the world's -x pull along its +y.
  LineMessages body(3, "world", "", true, "vessel");
  body.fillTopWrench(out, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())), ros::Time(1));
  EXPECT_EQ(body.top_wrench.header.frame_id, "vessel");
  EXPECT_NEAR(body.top_wrench.wrench.force.x, 0.0, 1e-12);
  EXPECT_NEAR(body.top_wrench.wrench.force.y, 5.0, 1e-12);
  out.axial_force[1] = std::nan("");
  EXPECT_FALSE(riser_sim::allFinite(out));
}

TEST(LineMarkers, ColoursAndLegendFollowTheTensionRange) {
  const auto lo = tensionColour(0, 0, 10), hi = tensionColour(10, 0, 10), mid = tensionColour(5, 0, 10);
  EXPECT_GT(lo.b, 0.9);
  EXPECT_GT(hi.r, 0.9);
  EXPECT_LT(hi.b, 0.2);
  EXPECT_GT(mid.g, 0.8);
  const auto flat = tensionColour(3, 3, 3);  // degenerate range: mid colour, finite
  EXPECT_TRUE(std::isfinite(flat.r) && std::isfinite(flat.g) && std::isfinite(flat.b));
}

TEST(LineMarkers, SurfacesOnlyWhenTheSceneHasThem) {
  riser_sim::RunOutputs out;
  out.points = {riser_sim::Vec3(0, 0, 0), riser_sim::Vec3(0, 0, -1), riser_sim::Vec3(0, 0, -3),
                riser_sim::Vec3(0, 0, -4)};
  out.axial_force = {30, 20, 10};
  auto names = [&](const Surfaces& s) {
    LineMarkers m(4.0, 3, false, "world", MarkerParams(), s);
    m.fill(out, ros::Time(1));
    std::string all;
    for (const auto& mk : m.msg.markers) all += mk.ns + " ";
    return std::make_pair(all, m.msg);
  };
  EXPECT_EQ(names(Surfaces()).first.find("water"), std::string::npos);
  EXPECT_EQ(names(Surfaces()).first.find("seabed"), std::string::npos);
  riser_sim::Scene scene;
  scene.water.enabled = true;
  scene.water.surface = 2.0;
  scene.seabed.enabled = true;
  scene.seabed.level = -50.0;
  const auto [all, msg] = names(surfacesOf(scene));
  EXPECT_NE(all.find("water_surface"), std::string::npos);
  EXPECT_NE(all.find("seabed"), std::string::npos);
  for (const auto& mk : msg.markers) {
    if (mk.ns == "water_surface") EXPECT_EQ(mk.pose.position.z, 2.0);
    if (mk.ns == "seabed") EXPECT_EQ(mk.pose.position.z, -50.0);
    if (mk.ns == "line") {
      EXPECT_GT(mk.colors.front().r, 0.9);  // top: highest tension, red
      EXPECT_GT(mk.colors.back().b, 0.9);   // bottom: lowest, blue
    }
  }
}

TEST(TimingStats, PercentilesOverTheRing) {
  TimingStats s(100);
  for (int i = 1; i <= 100; ++i) s.add(i);
  EXPECT_EQ(s.percentile(0.99), 99.0);
  EXPECT_EQ(s.percentile(1.0), 100.0);
  EXPECT_EQ(s.max(), 100.0);
  EXPECT_DOUBLE_EQ(s.mean(), 50.5);
  for (int i = 0; i < 100; ++i) s.add(1.0);  // ring wraps: old values gone
  EXPECT_EQ(s.max(), 1.0);
}

TEST(SampleBuffer, KeepsOrderAndDropsTheOldestWhenFull) {
  SampleBuffer b;
  std::array<VesselSample, SampleBuffer::kCapacity> out;
  for (int i = 0; i < SampleBuffer::kCapacity + 5; ++i) {
    VesselSample s;
    s.stamp = ros::Time(1 + i);
    b.push(s);
  }
  EXPECT_EQ(b.overflows(), 5);
  const int n = b.drain(out);
  ASSERT_EQ(n, SampleBuffer::kCapacity);
  EXPECT_EQ(out[0].stamp, ros::Time(6));
  EXPECT_EQ(out[n - 1].stamp, ros::Time(SampleBuffer::kCapacity + 5));
  EXPECT_EQ(b.drain(out), 0);
  VesselSample last;
  ASSERT_TRUE(b.latest(last));
  EXPECT_EQ(last.stamp, ros::Time(SampleBuffer::kCapacity + 5));
}

}  // namespace
}  // namespace riser_sim_ros

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::Time::init();
  return RUN_ALL_TESTS();
}
