// The node and riser_sim_cli give the same first second on every shipped scene. Each node (namespace =
// scene file name) gets a constant vessel pose whose hang-off lands at the scene's top.position + kShift
// (paper x, y = world x, z); the CLI runs the same scene with the top fixed there. The test owns
// /clock and advances it in lock-step: a 0.05 s tick, then it waits for every node's /diagnostics of
// that tick, so each node integrates exactly the ticks' ROS time (no backlog dropped, no wall timing).
#include <rosgraph_msgs/Clock.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <Eigen/Geometry>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

constexpr double kTick = 0.05;    // /clock step = publish period of tension, state, diagnostics [s]
constexpr int kTicks = 20;        // the first second
const ros::Time kT0(1000.0);      // first /clock value (zero would mean "no clock yet")
// Hang-off = top.position + kShift (paper x, y): off the origin, so a sign error in the world -> paper
// mapping (x, z) moves the top by metres.
const Eigen::Vector2d kShift(4.0, -3.0);
// Vessel pose: turned 90 deg about world z; the hang-off offset (node_matches_cli.yaml) then points
// along world (2, 10, 5). World y of the hang-off (dropped by the node) is kOutOfPlane.
const Eigen::Quaterniond kTurn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
const Eigen::Vector3d kOffset(10.0, -2.0, 5.0);
constexpr double kOutOfPlane = 0.5;

// Both sides build the run with riser_sim::buildRun from the same scene; they differ only by rounding:
// the hang-off pose * offset (~1e-15 m), the external motion's fit of identical samples (v, a ~1e-15)
// and the CLI's CSV (9 significant digits: 5e-10 relative, 5e-7 m on coordinates of a few hundred
// metres). Measured: |dT|/T <= 4e-9, |d end| <= 3e-7 m. The tolerances sit well above that and far
// below any physical difference: dropping the J-lay's held end load changes its top tension by ~1e5 N
// within the first second, and a hang-off off by 1 mm moves the end by ~1 mm.
constexpr double kRelTension = 1e-6;
constexpr double kPositionTol = 1e-5;  // [m]

struct Sample {
  double tension = NAN;
  Eigen::Vector2d top{NAN, NAN}, end{NAN, NAN};  // paper (x, y)
  bool has_tension = false, has_state = false;
};

struct Riser {
  std::string ns, scene_file;
  Eigen::Vector2d hangoff;  // paper (x, y)
  ros::Publisher pose_pub;
  ros::Subscriber tension_sub, state_sub;
  // Filled by callbacks (mutex_).
  ros::Time last_diag, origin;  // origin: ROS time the node started (its first "running" diagnostics)
  std::map<int64_t, Sample> by_stamp;
};

std::mutex mutex_;

Riser* find(std::vector<std::unique_ptr<Riser>>& risers, const std::string& status_name) {
  for (auto& r : risers)
    if (status_name == r->ns + "/riser_sim: riser simulation") return r.get();
  return nullptr;
}

// riser_sim_cli's CSV rows keyed by tick number: t, x/y/z_top, x/y/z_end, ..., tension_top (column 19); a
// planar scene is the CLI's x-z plane (the node's x-y).
std::map<int, Sample> runCli(const Riser& r) {
  const std::string csv = "/tmp/node_matches_cli_" + r.ns + "_" + std::to_string(getpid()) + ".csv";
  char top[96];
  std::snprintf(top, sizeof(top), "[%.17g,%.17g]", r.hangoff.x(), r.hangoff.y());
  const std::string cmd = std::string(RISER_SIM_CLI_BIN) + " --scene " + r.scene_file +
                          " --set top.motion.type=fixed --set top.position=" + top + " --duration " +
                          std::to_string(kTicks * kTick) + " --output-dt " + std::to_string(kTick) +
                          " --quiet --csv " + csv;
  std::map<int, Sample> rows;
  if (std::system(cmd.c_str()) != 0) {
    ADD_FAILURE() << "failed: " << cmd;
    return rows;
  }
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    double v[20];
    char comma;
    ss >> v[0];
    for (int i = 1; i < 20; ++i) ss >> comma >> v[i];
    Sample s;
    s.top = {v[1], v[3]};
    s.end = {v[4], v[6]};
    s.tension = v[19];
    rows[static_cast<int>(std::lround(v[0] / kTick))] = s;
  }
  std::remove(csv.c_str());
  return rows;
}

// Whether a scene file says space: spatial (a top-level line of its own).
bool isSpatial(const std::string& file) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("space:", 0) == 0 && line.find("spatial") != std::string::npos) return true;
  return false;
}

TEST(NodeMatchesCli, FirstSecondOfEveryShippedScene) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_dir;
  ASSERT_TRUE(pnh.getParam("scene_dir", scene_dir));
  std::vector<std::unique_ptr<Riser>> risers;
  for (const auto& f : std::filesystem::directory_iterator(scene_dir)) {
    if (f.path().extension() != ".yaml") continue;
    if (isSpatial(f.path().string())) continue;  // the node is planar: it refuses space: spatial
    auto r = std::make_unique<Riser>();
    r->ns = f.path().stem().string();
    r->scene_file = f.path().string();
    std::vector<double> top;
    ASSERT_TRUE(nh.getParam("/" + r->ns + "/riser_sim/scene/top/position", top) && top.size() == 2)
        << "scene " << r->scene_file << " has no node in node_matches_cli.test (namespace " << r->ns << ")";
    r->hangoff = Eigen::Vector2d(top[0], top[1]) + kShift;
    risers.push_back(std::move(r));
  }
  ASSERT_EQ(risers.size(), 5u) << "the shipped planar scenes changed: update node_matches_cli.test";

  ros::Subscriber diag_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 100, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& st : m->status)
          if (Riser* r = find(risers, st.name)) {
            r->last_diag = std::max(r->last_diag, m->header.stamp);
            for (const auto& kv : st.values)
              if (kv.key == "mode" && kv.value == "running" && r->origin.isZero()) r->origin = m->header.stamp;
          }
      });
  for (auto& rp : risers) {
    Riser* r = rp.get();
    const std::string ns = "/" + r->ns + "/";
    r->pose_pub = nh.advertise<geometry_msgs::PoseStamped>(ns + "vessel/pose", 10);
    r->tension_sub = nh.subscribe<riser_sim::Tension>(ns + "riser_sim/tension", 100, [r](const riser_sim::Tension::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      Sample& s = r->by_stamp[m->header.stamp.toNSec()];
      s.tension = m->top;
      s.has_tension = true;
    });
    r->state_sub = nh.subscribe<riser_sim::LineState>(ns + "riser_sim/state", 100, [r](const riser_sim::LineState::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      Sample& s = r->by_stamp[m->header.stamp.toNSec()];
      s.top = {m->points.front().x, m->points.front().z};
      s.end = {m->points.back().x, m->points.back().z};
      s.has_state = true;
    });
  }
  ros::Publisher clock_pub = nh.advertise<rosgraph_msgs::Clock>("/clock", 10, /*latch=*/true);
  ASSERT_TRUE(waitFor([&] {
    if (diag_sub.getNumPublishers() < risers.size()) return false;
    for (auto& r : risers)
      if (r->pose_pub.getNumSubscribers() == 0 || r->tension_sub.getNumPublishers() == 0 ||
          r->state_sub.getNumPublishers() == 0)
        return false;
    return true;
  }, 30.0)) << "nodes not connected";

  // Lock-step: publish the tick and a pose stamped with it, wait until every node has handled the tick.
  auto all = [&](const std::function<bool(const Riser&)>& f) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& r : risers)
      if (!f(*r)) return false;
    return true;
  };
  ros::Time now = kT0;
  for (int tick = 0;; ++tick) {
    rosgraph_msgs::Clock c;
    c.clock = now;
    clock_pub.publish(c);
    for (auto& r : risers) {
      geometry_msgs::PoseStamped p;
      p.header.stamp = now;
      p.header.frame_id = "world";
      const Eigen::Vector3d hangoff(r->hangoff.x(), kOutOfPlane, r->hangoff.y());
      const Eigen::Vector3d position = hangoff - kTurn * kOffset;
      p.pose.position.x = position.x();
      p.pose.position.y = position.y();
      p.pose.position.z = position.z();
      p.pose.orientation.w = kTurn.w();
      p.pose.orientation.x = kTurn.x();
      p.pose.orientation.y = kTurn.y();
      p.pose.orientation.z = kTurn.z();
      r->pose_pub.publish(p);
    }
    ASSERT_TRUE(waitFor([&] { return all([&](const Riser& r) { return r.last_diag >= now; }); }, 30.0))
        << "a node did not handle /clock " << now;
    if (all([&](const Riser& r) { return !r.origin.isZero() && now >= r.origin + ros::Duration(kTicks * kTick); }))
      break;
    ASSERT_LT(tick, 100) << "a node never started";
    now += ros::Duration(kTick);
  }

  for (auto& rp : risers) {
    const Riser& r = *rp;
    SCOPED_TRACE(r.ns);
    const std::map<int, Sample> cli = runCli(r);
    ASSERT_TRUE(waitFor([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      for (int k = 1; k <= kTicks; ++k) {
        auto it = r.by_stamp.find((r.origin + ros::Duration(k * kTick)).toNSec());
        if (it == r.by_stamp.end() || !it->second.has_tension || !it->second.has_state) return false;
      }
      return true;
    }, 10.0)) << "tension/state of the first second (0.05 s apart from " << r.origin << ") incomplete";
    std::lock_guard<std::mutex> lock(mutex_);
    double worst_tension = 0.0, worst_end = 0.0;
    for (int k = 1; k <= kTicks; ++k) {
      const Sample& node = r.by_stamp.at((r.origin + ros::Duration(k * kTick)).toNSec());
      ASSERT_TRUE(cli.count(k)) << "CLI has no row at t = " << k * kTick << " s";
      const Sample& ref = cli.at(k);
      const double d_tension = std::abs(node.tension - ref.tension) / std::abs(ref.tension);
      const double d_end = (node.end - ref.end).lpNorm<Eigen::Infinity>();
      const double d_top = (node.top - ref.top).lpNorm<Eigen::Infinity>();
      worst_tension = std::max(worst_tension, d_tension);
      worst_end = std::max(worst_end, d_end);
      if (d_tension > kRelTension || d_end > kPositionTol || d_top > kPositionTol) {
        ADD_FAILURE() << r.ns << " at t = " << k * kTick << " s: node top tension " << node.tension << " N, end ("
                      << node.end.x() << ", " << node.end.y() << ") m, top (" << node.top.x() << ", " << node.top.y()
                      << ") m; CLI " << ref.tension << " N, (" << ref.end.x() << ", " << ref.end.y() << ") m, ("
                      << ref.top.x() << ", " << ref.top.y() << ") m";
        break;  // the first differing instant says enough
      }
    }
    std::printf("%-18s top tension at 1 s %.6e N (CLI %.6e N); first second: max |dT|/T %.2e, max |d end| %.2e m\n",
                r.ns.c_str(), r.by_stamp.at((r.origin + ros::Duration(1.0)).toNSec()).tension, cli.at(kTicks).tension,
                worst_tension, worst_end);
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_matches_cli");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
