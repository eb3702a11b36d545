// An ROV on its tether (node_rov_tether.test: launch/rov_tether.launch, wrench_frame body): both ends
// follow their pose topics, both wrenches are published and finite, the tether's end force points from
// the ROV into the line, the energy balance holds; bad ROV poses are refused and counted.
#include <map>

#include <Eigen/Geometry>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

const Eigen::Vector3d kHangoff(3.0, 0.0, 1.0), kAttach(-0.5, 0.0, 0.3);  // launch defaults
// ROV ~0.9 m/s, vessel 0.2 m/s: the smoothing's error (prediction on 20 Hz poses) stays well below this.
constexpr double kTrackTol = 0.02;  // [m]
constexpr double kWarmup = 1.0;     // [s] after the first state
constexpr double kRun = 10.0;       // [s] of ROS (= sim) time

Eigen::Vector3d vec(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }
Eigen::Vector3d vec(const geometry_msgs::Vector3& p) { return Eigen::Vector3d(p.x, p.y, p.z); }
Eigen::Isometry3d iso(const geometry_msgs::Pose& p) {
  const auto& q = p.orientation;
  return Eigen::Translation3d(vec(p.position)) * Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized();
}

// The body pose at `stamp`, linear between the recorded poses around it (false outside them).
bool poseAt(const std::vector<geometry_msgs::PoseStamped>& poses, const ros::Time& stamp, Eigen::Isometry3d& out) {
  for (size_t i = 1; i < poses.size(); ++i) {
    const ros::Time &t0 = poses[i - 1].header.stamp, &t1 = poses[i].header.stamp;
    if (t0 > stamp || t1 < stamp || t1 <= t0) continue;
    const double u = (stamp - t0).toSec() / (t1 - t0).toSec();
    const Eigen::Isometry3d a = iso(poses[i - 1].pose), b = iso(poses[i].pose);
    const Eigen::Quaterniond q = Eigen::Quaterniond(a.rotation()).slerp(u, Eigen::Quaterniond(b.rotation()));
    out = Eigen::Translation3d((1 - u) * a.translation() + u * b.translation()) * q;
    return true;
  }
  return false;
}

std::string lastDiag(const Recorder<diagnostic_msgs::DiagnosticArray>& diag, const char* key) {
  const auto all = diag.all();
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    const std::string v = diagValue(*it, "riser_sim", key);
    if (!v.empty()) return v;
  }
  return "";
}

TEST(NodeRovTether, BothEndsFollowAndTheEndForcePointsIntoTheLine) {
  ros::NodeHandle nh;
  Recorder<geometry_msgs::PoseStamped> rov(nh, "/rov/pose"), vessel(nh, "/vessel/pose");
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state");
  Recorder<geometry_msgs::WrenchStamped> top(nh, "/riser_sim/top_wrench"), bottom(nh, "/riser_sim/bottom_wrench");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  ASSERT_TRUE(state.waitCount(1, 60.0));
  ASSERT_TRUE(waitRosTime(kRun, 120.0));
  const ros::Time t0 = state.all().front().header.stamp + ros::Duration(kWarmup);

  const auto rovs = rov.all(), vessels = vessel.all();
  std::map<ros::Time, geometry_msgs::WrenchStamped> bottoms;
  for (const auto& m : bottom.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_EQ(m.header.frame_id, "rov");
    bottoms[m.header.stamp] = m;
  }
  for (const auto& m : top.all()) {
    ASSERT_TRUE(finite(m));
    EXPECT_EQ(m.header.frame_id, "vessel");
  }
  double worst_bottom = 0.0, worst_top = 0.0, min_cos = 1.0, rov_path = 0.0, force = 0.0;
  int n = 0, paired = 0;
  Eigen::Vector3d first_end = Eigen::Vector3d::Zero();
  for (const auto& s : state.all()) {
    ASSERT_TRUE(finite(s));
    if (s.header.stamp < t0) continue;
    Eigen::Isometry3d r, v;
    if (!poseAt(rovs, s.header.stamp, r) || !poseAt(vessels, s.header.stamp, v)) continue;
    const Eigen::Vector3d end = vec(s.points.back()), before = vec(s.points[s.points.size() - 2]);
    if (n == 0) first_end = end;
    rov_path = std::max(rov_path, (end - first_end).norm());
    worst_bottom = std::max(worst_bottom, (end - r * kAttach).norm());
    worst_top = std::max(worst_top, (vec(s.points.front()) - v * kHangoff).norm());
    ++n;
    const auto w = bottoms.find(s.header.stamp);
    if (w == bottoms.end()) continue;
    // The line pulls the ROV along its last element: body frame back to world with the ROV's orientation.
    const Eigen::Vector3d f = r.rotation() * vec(w->second.wrench.force);
    min_cos = std::min(min_cos, f.normalized().dot((before - end).normalized()));
    force = f.norm();
    ++paired;
  }
  std::printf(
      "[ INFO ] ROV tether over %d states (%.1f s): bottom end from the ROV attachment up to %.4f m, "
      "hang-off from the vessel's up to %.4f m (tolerance %.2f m); the end moved %.2f m; end force %.2f N, "
      "its direction vs the last element: cos >= %.4f over %d\n",
      n, kRun, worst_bottom, worst_top, kTrackTol, rov_path, force, min_cos, paired);
  EXPECT_GT(n, 50);
  EXPECT_GT(paired, 50);
  EXPECT_GT(rov_path, 3.0);  // the ROV did move
  EXPECT_LT(worst_bottom, kTrackTol);
  EXPECT_LT(worst_top, kTrackTol);
  // Within 45 deg of the last element: the rest is that element's drag (moving ~0.9 m/s across it).
  EXPECT_GT(min_cos, std::cos(M_PI / 4));
  EXPECT_GT(force, 1.0);

  ASSERT_TRUE(waitFor([&] { return !lastDiag(diag, "energy balance error (relative)").empty(); }, 10.0));
  EXPECT_EQ(lastDiag(diag, "mode"), "running");
  const double drift = std::stod(lastDiag(diag, "energy balance error (relative)"));
  std::printf("[ INFO ] energy balance error %.3e (relative), time dropped %s s\n", drift,
              lastDiag(diag, "time dropped total [s]").c_str());
  EXPECT_LT(std::abs(drift), 1e-2);
  EXPECT_EQ(lastDiag(diag, "bottom poses rejected"), "0");
}

// Bad ROV poses (the vessel pose's checks) never reach the integrator and are counted.
TEST(NodeRovTether, BadRovPosesAreRefusedAndCounted) {
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("/rov/pose", 20);
  Recorder<geometry_msgs::PoseStamped> rov(nh, "/rov/pose");
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state");
  Recorder<geometry_msgs::WrenchStamped> bottom(nh, "/riser_sim/bottom_wrench");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  // Two subscribers on this publisher: the node and the recorder above (one alone may be the recorder, and
  // poses sent before the node connects are lost).
  ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() >= 2 && rov.count() > 0; }, 20.0));
  const double nan = std::nan("");
  std::vector<geometry_msgs::PoseStamped> bad(6, rov.last());
  for (auto& m : bad) m.header.stamp = ros::Time::now();
  bad[0].pose.orientation.w *= 1.5, bad[0].pose.orientation.z *= 1.5;  // norm 1.5
  bad[1].pose.orientation.w = bad[1].pose.orientation.z = 0.0;         // zero quaternion
  bad[2].pose.position.y = nan;                                        // NaN position
  bad[3].pose.position.z = INFINITY;                                   // Inf position
  bad[4].header.stamp = rov.last().header.stamp;                       // duplicate (or out of order)
  bad[5].header.stamp = rov.last().header.stamp - ros::Duration(0.3);  // out of order
  for (const auto& m : bad) pub.publish(m);
  ASSERT_TRUE(waitFor(
      [&] {
        const std::string v = lastDiag(diag, "bottom poses rejected");
        return !v.empty() && std::stol(v) >= 6;
      },
      20.0));
  std::printf("[ INFO ] bottom poses rejected %s, last: %s\n", lastDiag(diag, "bottom poses rejected").c_str(),
              lastDiag(diag, "last bottom rejection").c_str());
  EXPECT_EQ(lastDiag(diag, "mode"), "running");
  const size_t before = state.count();
  ASSERT_TRUE(state.waitCount(before + 10, 20.0));
  for (const auto& m : state.all()) EXPECT_TRUE(finite(m));
  for (const auto& m : bottom.all()) EXPECT_TRUE(finite(m));
}

// Nodes that wait: /diagnostics names every input without a valid pose yet, the bottom's alone when the vessel's
// arrive (no_rov), both when none do (no_poses).
TEST(NodeRovTether, WaitingNamesTheMissingInputs) {
  ros::NodeHandle nh;
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  std::string rov, none, mode;
  const auto waiting = [&](const char* node, std::string& message) {
    return waitFor(
        [&] {
          for (const auto& a : diag.all())
            for (const auto& st : a.status)
              if (st.name.rfind(node, 0) == 0 && diagValue(a, node, "mode").rfind("waiting", 0) == 0 &&
                  (std::string(node) != "no_rov/riser_sim" || diagValue(a, node, "poses accepted") != "0")) {
                message = st.message;
                mode = diagValue(a, node, "mode");
                return true;
              }
          return false;
        },
        20.0);
  };
  ASSERT_TRUE(waiting("no_rov/riser_sim", rov)) << "no waiting diagnostics with vessel poses accepted";
  EXPECT_NE(rov.find("waiting for the first valid bottom pose (/no_rov/riser_sim/bottom_pose)"), std::string::npos)
      << rov;
  EXPECT_EQ(rov.find("vessel pose"), std::string::npos) << rov;
  EXPECT_EQ(mode, "waiting for bottom pose");
  ASSERT_TRUE(waiting("no_poses/riser_sim", none));
  EXPECT_NE(none.find("waiting for the first valid vessel pose (/no_poses/vessel/pose) and bottom pose "
                      "(/no_poses/riser_sim/bottom_pose)"),
            std::string::npos)
      << none;
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_rov_tether");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
