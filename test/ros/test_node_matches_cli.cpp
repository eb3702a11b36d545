// The node and riser_sim_cli give the same first second on every shipped scene, planar and 3D. Each node
// (namespace = scene file name) gets a constant vessel pose whose hang-off lands at the scene's top.position +
// kShift (planar: paper x, y = world x, z, the pose kOutOfPlane off the plane; 3D: world x, y, z); the CLI runs
// the same scene with the top fixed there. A driven bottom (bottom.motion.type external) gets a constant pose
// at the scene's bottom.position, where the CLI holds it. The test owns /clock and advances it in lock-step: a
// 0.05 s tick, then it waits for every node's /diagnostics of that tick, so each node integrates exactly the
// ticks' ROS time (no backlog dropped, no wall timing). Node and CLI rows are compared at the same sim times.
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

constexpr double kTick = 0.05;  // /clock step = publish period of tension, state, diagnostics [s]
constexpr int kTicks = 20;      // the first second
const ros::Time kT0(1000.0);    // first /clock value (zero would mean "no clock yet")
// Hang-off = top.position + kShift (planar: paper x, y; 3D: x, y, z): off the origin, so a sign error in the
// world -> paper mapping (x, z) or in the 3D pose moves the top by metres.
const Eigen::Vector2d kShift(4.0, -3.0);
const Eigen::Vector3d kShift3(4.0, 1.5, -3.0);
// Vessel pose: turned 90 deg about world z; the hang-off offset (node_matches_cli.yaml) then points
// along world (2, 10, 5). World y of the hang-off (dropped by the node) is kOutOfPlane.
const Eigen::Quaterniond kTurn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
const Eigen::Vector3d kOffset(10.0, -2.0, 5.0);
constexpr double kOutOfPlane = 0.5;

// Both sides build the run with riser_sim::buildLineRun from the same scene; they differ only by rounding:
// the hang-off pose * offset (~1e-15 m), the external motion's fit of identical samples (v, a ~1e-15)
// and the CLI's CSV (9 significant digits: 5e-10 relative, 5e-7 m on coordinates of a few hundred
// metres). Measured: |dT|/T <= 4e-9, |d end| <= 3e-7 m. The tolerances sit well above that and far
// below any physical difference: dropping the J-lay's held end load changes its top tension by ~1e5 N
// within the first second, and a hang-off off by 1 mm moves the end by ~1 mm.
constexpr double kRelTension = 1e-6;
constexpr double kPositionTol = 1e-5;  // [m]

struct Sample {
  double tension = NAN;
  Eigen::Vector3d top{NAN, NAN, NAN}, end{NAN, NAN, NAN};  // world (CLI: 3D; planar y = 0)
  bool has_tension = false, has_state = false;
};

// Sim time [us]: the key node and CLI rows are matched by.
int64_t key(double t) { return std::llround(t * 1e6); }

struct Riser {
  std::string ns, scene_file;
  bool spatial = false;
  Eigen::Vector3d hangoff;  // world: the node's hang-off
  std::string cli_top;      // top.position for the CLI ("[x,z]" planar, "[x,y,z]" 3D)
  bool driven_bottom = false;
  bool attitude = false;  // top.motion.attitude: removed for the CLI's fixed top (it needs a sinusoid)
  Eigen::Vector3d bottom = Eigen::Vector3d::Zero();  // a driven bottom's pose [m]
  ros::Publisher pose_pub, bottom_pub;
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

// riser_sim_cli's CSV rows keyed by sim time (key()): t, x/y/z_top, x/y/z_end, ..., tension_top (column 19); a
// planar scene is the x-z plane, as the node's.
std::map<int64_t, Sample> runCli(const Riser& r) {
  const std::string csv = "/tmp/node_matches_cli_" + r.ns + "_" + std::to_string(getpid()) + ".csv";
  const std::string cmd = std::string(RISER_SIM_CLI_BIN) + " --scene " + r.scene_file + " --set top.motion.type=fixed" +
                          (r.attitude ? " --set top.motion.attitude=null" : "") + " --set top.position=" + r.cli_top +
                          " --duration " + std::to_string(kTicks * kTick) + " --output-dt " + std::to_string(kTick) +
                          " --quiet --csv " + csv;
  std::map<int64_t, Sample> rows;
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
    s.top = {v[1], v[2], v[3]};
    s.end = {v[4], v[5], v[6]};
    s.tension = v[19];
    rows[key(v[0])] = s;
  }
  std::remove(csv.c_str());
  return rows;
}

std::string vector(const std::vector<double>& v) {
  std::string s = "[";
  char buf[40];
  for (size_t i = 0; i < v.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%s%.17g", i ? "," : "", v[i]);
    s += buf;
  }
  return s + "]";
}

TEST(NodeMatchesCli, FirstSecondOfEveryShippedScene) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_dir;
  ASSERT_TRUE(pnh.getParam("scene_dir", scene_dir));
  std::vector<std::unique_ptr<Riser>> risers;
  for (const auto& f : std::filesystem::directory_iterator(scene_dir)) {
    if (f.path().extension() != ".yaml") continue;
    auto r = std::make_unique<Riser>();
    r->ns = f.path().stem().string();
    r->scene_file = f.path().string();
    const std::string scene = "/" + r->ns + "/riser_sim/scene/";
    std::vector<double> top;
    ASSERT_TRUE(nh.getParam(scene + "top/position", top))
        << "scene " << r->scene_file << " has no node in node_matches_cli.test (namespace " << r->ns << ")";
    std::string space, bottom_motion;
    r->spatial = nh.getParam(scene + "space", space) && space == "spatial";
    ASSERT_EQ(top.size(), r->spatial ? 3u : 2u) << r->ns;
    if (r->spatial) {
      r->hangoff = Eigen::Vector3d(top[0], top[1], top[2]) + kShift3;
      r->cli_top = vector({r->hangoff.x(), r->hangoff.y(), r->hangoff.z()});
    } else {
      const Eigen::Vector2d paper = Eigen::Vector2d(top[0], top[1]) + kShift;
      r->hangoff = Eigen::Vector3d(paper.x(), kOutOfPlane, paper.y());  // world y: dropped by the node
      r->cli_top = vector({paper.x(), paper.y()});
    }
    r->driven_bottom = nh.getParam(scene + "bottom/motion/type", bottom_motion) && bottom_motion == "external";
    r->attitude = nh.hasParam(scene + "top/motion/attitude");
    if (r->driven_bottom) {
      std::vector<double> b;
      ASSERT_TRUE(nh.getParam(scene + "bottom/position", b) && b.size() == 3u) << r->ns;
      r->bottom = Eigen::Vector3d(b[0], b[1], b[2]);
    }
    risers.push_back(std::move(r));
  }
  ASSERT_EQ(risers.size(), 19u) << "the shipped scenes changed: update node_matches_cli.test";

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
    if (r->driven_bottom) r->bottom_pub = nh.advertise<geometry_msgs::PoseStamped>(ns + "riser_sim/bottom_pose", 10);
    r->tension_sub =
        nh.subscribe<riser_sim::Tension>(ns + "riser_sim/tension", 100, [r](const riser_sim::Tension::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          Sample& s = r->by_stamp[m->header.stamp.toNSec()];
          s.tension = m->top;
          s.has_tension = true;
        });
    r->state_sub =
        nh.subscribe<riser_sim::LineState>(ns + "riser_sim/state", 100, [r](const riser_sim::LineState::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          Sample& s = r->by_stamp[m->header.stamp.toNSec()];
          s.top = {m->points.front().x, m->points.front().y, m->points.front().z};
          s.end = {m->points.back().x, m->points.back().y, m->points.back().z};
          s.has_state = true;
        });
  }
  ros::Publisher clock_pub = nh.advertise<rosgraph_msgs::Clock>("/clock", 10, /*latch=*/true);
  ASSERT_TRUE(waitFor(
      [&] {
        if (diag_sub.getNumPublishers() < risers.size()) return false;
        for (auto& r : risers)
          if (r->pose_pub.getNumSubscribers() == 0 || r->tension_sub.getNumPublishers() == 0 ||
              r->state_sub.getNumPublishers() == 0 || (r->driven_bottom && r->bottom_pub.getNumSubscribers() == 0))
            return false;
        return true;
      },
      30.0))
      << "nodes not connected";

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
      const Eigen::Vector3d position = r->hangoff - kTurn * kOffset;
      p.pose.position.x = position.x();
      p.pose.position.y = position.y();
      p.pose.position.z = position.z();
      p.pose.orientation.w = kTurn.w();
      p.pose.orientation.x = kTurn.x();
      p.pose.orientation.y = kTurn.y();
      p.pose.orientation.z = kTurn.z();
      r->pose_pub.publish(p);
      if (r->driven_bottom) {
        p.pose.position.x = r->bottom.x();
        p.pose.position.y = r->bottom.y();
        p.pose.position.z = r->bottom.z();
        p.pose.orientation = geometry_msgs::Quaternion();
        p.pose.orientation.w = 1.0;
        r->bottom_pub.publish(p);
      }
    }
    ASSERT_TRUE(waitFor([&] { return all([&](const Riser& r) { return r.last_diag >= now; }); }, 30.0))
        << "a node did not handle /clock " << now;
    if (all([&](const Riser& r) { return !r.origin.isZero() && now >= r.origin + ros::Duration(kTicks * kTick); }))
      break;
    ASSERT_LT(tick, 200) << "a node never started";
    now += ros::Duration(kTick);
  }

  for (auto& rp : risers) {
    const Riser& r = *rp;
    SCOPED_TRACE(r.ns);
    const std::map<int64_t, Sample> cli = runCli(r);
    // The node's messages of the first second (0.05 s apart, or the step's multiples below it), by sim time.
    const auto first_second = [&] {
      std::map<int64_t, Sample> node;
      for (const auto& [stamp, sample] : r.by_stamp) {
        const double t = (ros::Time().fromNSec(stamp) - r.origin).toSec();
        if (t > 0.0 && t <= kTicks * kTick + 1e-9 && sample.has_tension && sample.has_state) node[key(t)] = sample;
      }
      return node;
    };
    ASSERT_TRUE(waitFor(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          return first_second().size() >= 10;
        },
        10.0))
        << "tension/state of the first second (from " << r.origin << ") incomplete";
    std::lock_guard<std::mutex> lock(mutex_);
    double worst_tension = 0.0, worst_end = 0.0, last_tension = NAN, last_cli = NAN;
    int compared = 0;
    for (const auto& [k, node] : first_second()) {
      const auto it = cli.find(k);
      if (it == cli.end()) continue;  // a time the CLI's output step does not hit
      const Sample& ref = it->second;
      ++compared;
      const double d_tension = std::abs(node.tension - ref.tension) / std::abs(ref.tension);
      const double d_end = (node.end - ref.end).lpNorm<Eigen::Infinity>();
      const double d_top = (node.top - ref.top).lpNorm<Eigen::Infinity>();
      worst_tension = std::max(worst_tension, d_tension);
      worst_end = std::max(worst_end, d_end);
      last_tension = node.tension, last_cli = ref.tension;
      if (d_tension > kRelTension || d_end > kPositionTol || d_top > kPositionTol) {
        ADD_FAILURE() << r.ns << " at t = " << k * 1e-6 << " s: node top tension " << node.tension << " N, end ("
                      << node.end.transpose() << ") m, top (" << node.top.transpose() << ") m; CLI " << ref.tension
                      << " N, (" << ref.end.transpose() << ") m, (" << ref.top.transpose() << ") m";
        break;  // the first differing instant says enough
      }
    }
    EXPECT_GE(compared, 5) << "node and CLI share too few instants";
    std::printf(
        "%-26s %s top tension %.6e N (CLI %.6e N) at the last of %d instants; max |dT|/T %.2e, max |d end| "
        "%.2e m\n",
        r.ns.c_str(), r.spatial ? "3D" : "planar", last_tension, last_cli, compared, worst_tension, worst_end);
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
