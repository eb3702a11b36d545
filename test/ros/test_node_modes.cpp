// ~modes against the core's modal analysis of the same scene (an independent call in this process:
// its own statics and model) and against the pendulum's omega = sqrt(g / L).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <Eigen/Core>

#include "node_test_util.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/Modes.h"
#include "riser_sim/planar/modal.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

using namespace riser_sim_test;

namespace {

const double kX = 5.0, kZ = -1.0;  // hang-off [m]: the vessel sits here

riser_sim::Modes call(ros::ServiceClient& client, int count) {
  riser_sim::Modes srv;
  srv.request.count = count;
  EXPECT_TRUE(client.call(srv)) << "count " << count;
  return srv;
}

TEST(NodeModes, MatchesTheCoreAndThePendulum) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_file;
  ASSERT_TRUE(pnh.getParam("scene_file", scene_file));
  ros::ServiceClient modes = nh.serviceClient<riser_sim::Modes>("/riser_sim/modes");
  ASSERT_TRUE(modes.waitForExistence(ros::Duration(20.0)));

  // Before the first pose there is no static state.
  riser_sim::Modes early = call(modes, 2);
  EXPECT_FALSE(early.response.success);
  EXPECT_NE(early.response.message.find("no static state yet"), std::string::npos) << early.response.message;

  PosePublisher pose(nh, "/vessel/pose", 20.0, [](double, geometry_msgs::Pose& p) {
    p.position.x = kX;
    p.position.z = kZ;
  });
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0));

  // Bad counts: a clear error naming the field.
  for (int bad : {0, -3}) {
    const riser_sim::Modes r = call(modes, bad);
    EXPECT_FALSE(r.response.success);
    EXPECT_NE(r.response.message.find("count: must be >= 1, got " + std::to_string(bad)), std::string::npos)
        << r.response.message;
    EXPECT_TRUE(r.response.periods.empty());
  }
  const riser_sim::Modes big = call(modes, 1000);
  EXPECT_FALSE(big.response.success);
  // n = 4, inextensible: 5 rfes, one angle each.
  EXPECT_NE(big.response.message.find("count: must be <= 5"), std::string::npos) << big.response.message;

  // The reference: the same scene with the top fixed at the hang-off, statics and modes in this process.
  riser_sim::Scene scene = riser_sim::loadSceneFile(scene_file);
  scene.top.type = riser_sim::MotionKind::kFixed;
  scene.top.position = Eigen::Vector3d(kX, 0.0, kZ);
  riser_sim::ModalOptions o;
  o.modes = 5;
  const riser_sim::ModalResult ref = riser_sim::sceneModes(scene, o);

  const riser_sim::Modes got = call(modes, 5);
  ASSERT_TRUE(got.response.success) << got.response.message;
  const auto& r = got.response;
  EXPECT_EQ(r.dofs, 5);
  EXPECT_EQ(r.header.frame_id, "world");
  EXPECT_LT(r.equilibrium_residual, 1e-8);
  ASSERT_EQ(r.periods.size(), 5u);
  ASSERT_EQ(r.frequencies.size(), 5u);
  ASSERT_EQ(r.characters.size(), 5u);
  ASSERT_EQ(r.axial_share.size(), 5u);
  const size_t np = scene.elements + 2;
  ASSERT_EQ(r.points.size(), np);
  ASSERT_EQ(r.arc_length.size(), np);
  ASSERT_EQ(r.shape_x.size(), 5 * np);
  ASSERT_EQ(r.shape_z.size(), 5 * np);
  // Same statics and eigen-solve on both sides: equal to round-off (1e-9 relative).
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(r.periods[k] / ref.modes[k].period, 1.0, 1e-9) << "mode " << k + 1;
    EXPECT_NEAR(r.frequencies[k] * r.periods[k], 1.0, 1e-12);
    EXPECT_EQ(r.characters[k], ref.modes[k].character);
    EXPECT_NEAR(r.axial_share[k], ref.modes[k].axial_fraction, 1e-9);
    for (size_t p = 0; p < np; ++p) {
      EXPECT_NEAR(r.shape_x[k * np + p], ref.modes[k].displacement[p].x(), 1e-6);
      EXPECT_NEAR(r.shape_z[k * np + p], ref.modes[k].displacement[p].y(), 1e-6);
    }
  }
  for (size_t p = 0; p < np; ++p) {
    EXPECT_NEAR(r.points[p].x, ref.points[p].x(), 1e-9);
    EXPECT_EQ(r.points[p].y, 0.0);
    EXPECT_NEAR(r.points[p].z, ref.points[p].y(), 1e-9);
    EXPECT_NEAR(r.arc_length[p], ref.arc_length[p], 1e-12);
  }
  EXPECT_NEAR(r.points.front().x, kX, 1e-9);
  EXPECT_NEAR(r.points.front().z, kZ, 1e-9);
  EXPECT_NEAR(r.points.back().z, kZ - 10.0, 1e-6);  // hangs straight down

  // Physics: a pendulum, omega_1 = sqrt(g / L) within the line-mass fraction eps = mu L / m = 1e-3
  // (the line's own mass moves the compound pendulum's length by O(eps); docs/modal.md).
  const double eps = 0.01 * 10.0 / 100.0;
  EXPECT_NEAR(r.periods[0] / (2.0 * M_PI * std::sqrt(10.0 / 9.81)), 1.0, eps);
  EXPECT_EQ(r.characters[0], "transverse");
  EXPECT_NEAR(r.shape_x[np - 1], 1.0, 1e-9);  // the mass swings sideways: the largest displacement

  // Fewer modes: the lowest ones, same values.
  const riser_sim::Modes two = call(modes, 2);
  ASSERT_TRUE(two.response.success) << two.response.message;
  ASSERT_EQ(two.response.periods.size(), 2u);
  EXPECT_DOUBLE_EQ(two.response.periods[1], r.periods[1]);
}

// One row of riser_sim_cli --modes-csv: mode k's period, character and point p's position and shape.
struct CliRow {
  int mode, point;
  double period;
  std::string character;
  double s, x[3], d[3];
};

// riser_sim_cli --modes count --modes-csv on scene_file, with the top fixed at `top` when given.
std::vector<CliRow> runCliModes(const std::string& scene_file, const Eigen::Vector3d* top, int count) {
  const std::string csv = "/tmp/node_modes_3d_" + std::to_string(getpid()) + ".csv";
  char pos[160] = "";
  if (top)
    std::snprintf(pos, sizeof(pos), " --set top.motion.type=fixed --set top.position=[%.17g,%.17g,%.17g]", top->x(),
                  top->y(), top->z());
  const std::string cmd = std::string(RISER_SIM_CLI_BIN) + " --scene " + scene_file + pos + " --modes " +
                          std::to_string(count) + " --modes-csv " + csv + " --quiet > /dev/null";
  std::vector<CliRow> rows;
  if (std::system(cmd.c_str()) != 0) {
    ADD_FAILURE() << "failed: " << cmd;
    return rows;
  }
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // mode,period_s,frequency_hz,character,point,s,x,y,z,dx,dy,dz
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string f[12];
    for (auto& x : f) std::getline(ss, x, ',');
    CliRow r;
    r.mode = std::stoi(f[0]), r.period = std::stod(f[1]), r.character = f[3], r.point = std::stoi(f[4]);
    r.s = std::stod(f[5]);
    for (int k = 0; k < 3; ++k) r.x[k] = std::stod(f[6 + k]), r.d[k] = std::stod(f[9 + k]);
    rows.push_back(r);
  }
  std::remove(csv.c_str());
  return rows;
}

// 3D: the tether (pinned bottom, a slack catenary) from a hang-off off the x-z plane; the node's ~modes and
// riser_sim_cli --modes make the same statics, relaxation and eigen-solve: equal to round-off.
TEST(NodeModes, SpatialMatchesTheCli) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_file;
  ASSERT_TRUE(pnh.getParam("scene_file_3d", scene_file));
  const Eigen::Vector3d top(6.0, 4.0, 0.0);  // chord to the anchor (0, 0, -15): 16.6 m < 20 m
  ros::ServiceClient modes = nh.serviceClient<riser_sim::Modes>("/spatial/riser_sim/modes");
  ASSERT_TRUE(modes.waitForExistence(ros::Duration(20.0)));
  PosePublisher pose(nh, "/spatial/vessel/pose", 20.0, [&](double, geometry_msgs::Pose& p) {
    p.position.x = top.x(), p.position.y = top.y(), p.position.z = top.z();
  });
  Recorder<riser_sim::Tension> tension(nh, "/spatial/riser_sim/tension");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0));

  const riser_sim::Modes bad = call(modes, 0);
  EXPECT_FALSE(bad.response.success);
  EXPECT_NE(bad.response.message.find("count: must be >= 1, got 0"), std::string::npos) << bad.response.message;

  const int K = 6;
  const riser_sim::Modes got = call(modes, K);
  ASSERT_TRUE(got.response.success) << got.response.message;
  const auto& r = got.response;
  const std::vector<CliRow> cli = runCliModes(scene_file, &top, K);
  const size_t np = r.points.size();
  ASSERT_EQ(np, 12u);  // n = 10: A_0..A_10 and the end
  ASSERT_EQ(cli.size(), K * np);
  ASSERT_EQ(r.periods.size(), size_t(K));
  ASSERT_EQ(r.shape_y.size(), K * np);
  EXPECT_LT(r.equilibrium_residual, 1e-8);
  int in_plane = 0, out_of_plane = 0;
  for (int k = 0; k < K; ++k) {
    const CliRow& c0 = cli[k * np];
    EXPECT_NEAR(r.periods[k] / c0.period, 1.0, 1e-9) << "mode " << k + 1;  // the CSV's 10 digits
    EXPECT_EQ(r.characters[k], c0.character) << "mode " << k + 1;
    in_plane += r.characters[k] == "in-plane", out_of_plane += r.characters[k] == "out-of-plane";
    // The eigenvector's sign is arbitrary: compare up to one sign per mode.
    double dot = 0.0;
    for (size_t p = 0; p < np; ++p)
      dot += r.shape_x[k * np + p] * cli[k * np + p].d[0] + r.shape_y[k * np + p] * cli[k * np + p].d[1] +
             r.shape_z[k * np + p] * cli[k * np + p].d[2];
    const double sign = dot < 0.0 ? -1.0 : 1.0;
    for (size_t p = 0; p < np; ++p) {
      const CliRow& c = cli[k * np + p];
      EXPECT_NEAR(r.shape_x[k * np + p], sign * c.d[0], 1e-6) << k << " " << p;
      EXPECT_NEAR(r.shape_y[k * np + p], sign * c.d[1], 1e-6) << k << " " << p;
      EXPECT_NEAR(r.shape_z[k * np + p], sign * c.d[2], 1e-6) << k << " " << p;
      if (k == 0) {  // the CSV has 10 significant digits: half of the last is 5e-10 relative
        EXPECT_NEAR(r.points[p].x, c.x[0], 1e-9 * (1.0 + std::abs(c.x[0])));
        EXPECT_NEAR(r.points[p].y, c.x[1], 1e-9 * (1.0 + std::abs(c.x[1])));
        EXPECT_NEAR(r.points[p].z, c.x[2], 1e-9 * (1.0 + std::abs(c.x[2])));
        EXPECT_NEAR(r.arc_length[p], c.s, 1e-9 * (1.0 + c.s));
      }
    }
  }
  EXPECT_GT(in_plane, 0);
  EXPECT_GT(out_of_plane, 0);  // the plane is yawed (6, 4): both kinds there, named in its frame
  std::printf("3D modes: first period node %.9g s, CLI %.9g s; %d in-plane, %d out-of-plane of %d\n", r.periods[0],
              cli[0].period, in_plane, out_of_plane, K);
}

// 3D, a line twisted by its bending axes between a hang-off and an anchor (spatial_flat_umbilical.yaml): the
// node's ~modes at the vessel's pose where the scene has its top at t = 0 are riser_sim_cli --modes on the scene
// file (the same statics, hang-off frame, material axes and eigen-solve).
TEST(NodeModes, TwistedUmbilicalMatchesTheCliOnTheSceneFile) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_file;
  ASSERT_TRUE(pnh.getParam("scene_file_umbilical", scene_file));
  const riser_sim::Scene scene = riser_sim::loadSceneFile(scene_file);
  const Eigen::Vector3d top = riser_sim::spatial::buildTopMotion3(scene.top)->at(0.0).p;  // the sway's start
  ros::ServiceClient modes = nh.serviceClient<riser_sim::Modes>("/umbilical/riser_sim/modes");
  ASSERT_TRUE(modes.waitForExistence(ros::Duration(20.0)));
  PosePublisher pose(nh, "/umbilical/vessel/pose", 20.0, [&](double, geometry_msgs::Pose& p) {
    p.position.x = top.x(), p.position.y = top.y(), p.position.z = top.z();
  });
  Recorder<riser_sim::Tension> tension(nh, "/umbilical/riser_sim/tension");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(1, 30.0));

  const int K = 4;
  const riser_sim::Modes got = call(modes, K);
  ASSERT_TRUE(got.response.success) << got.response.message;
  const auto& r = got.response;
  const std::vector<CliRow> cli = runCliModes(scene_file, nullptr, K);
  const size_t np = r.points.size();
  ASSERT_EQ(np, size_t(scene.elements) + 2);
  ASSERT_EQ(cli.size(), K * np);
  ASSERT_EQ(r.periods.size(), size_t(K));
  for (int k = 0; k < K; ++k) {
    const CliRow& c = cli[k * np];
    EXPECT_NEAR(r.periods[k] / c.period, 1.0, 1e-6) << "mode " << k + 1;
    EXPECT_EQ(r.characters[k], c.character) << "mode " << k + 1;
  }
  std::printf("umbilical modes: node %.6g, %.6g, %.6g, %.6g s; CLI %.6g, %.6g, %.6g, %.6g s\n", r.periods[0],
              r.periods[1], r.periods[2], r.periods[3], cli[0].period, cli[np].period, cli[2 * np].period,
              cli[3 * np].period);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_modes");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
