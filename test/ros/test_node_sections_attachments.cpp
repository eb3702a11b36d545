// Sections, attachments and the live range graph in the node (node_sections_attachments.test). The expected
// values come from the scene files themselves (element counts, attachment arc lengths, masses and volumes) and
// from the node's other topics over the same window, not from the node's own code.
#include <algorithm>
#include <atomic>
#include <map>

#include <Eigen/Core>
#include <std_srvs/Trigger.h>
#include <yaml-cpp/yaml.h>

#include "node_test_util.h"
#include "riser_sim/RangeEnvelope.h"

using namespace riser_sim_test;

namespace {

std::string g_lazy, g_scenes;  // the sectioned planar scene file and config/scenes (the launch file's arguments)

constexpr double kG = 9.81;  // environment.gravity default (scene_keys.md)

Eigen::Vector3d vec(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }
Eigen::Vector3d vec(const geometry_msgs::Vector3& p) { return Eigen::Vector3d(p.x, p.y, p.z); }

std::vector<visualization_msgs::Marker> inNs(const visualization_msgs::MarkerArray& a, const std::string& ns) {
  std::vector<visualization_msgs::Marker> out;
  for (const auto& m : a.markers)
    if (m.ns == ns) out.push_back(m);
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  return out;
}

bool finite(const riser_sim::RangeEnvelope& m) {
  return riser_sim_test::finite(m.arc_length) && riser_sim_test::finite(m.tension_min) &&
         riser_sim_test::finite(m.tension_max) && riser_sim_test::finite(m.moment_min) &&
         riser_sim_test::finite(m.moment_max) && riser_sim_test::finite(m.curvature_min) &&
         riser_sim_test::finite(m.curvature_max) && riser_sim_test::finite(m.clearance_min) &&
         riser_sim_test::finite(m.clearance_max) && std::isfinite(m.top_tension_min) &&
         std::isfinite(m.top_tension_max) && std::isfinite(m.touchdown_min) && std::isfinite(m.touchdown_max);
}

// Segments per line.sections entry of a scene file (elements, or length / segment_length).
std::vector<int> sectionElements(const YAML::Node& scene) {
  std::vector<int> out;
  for (const auto& s : scene["line"]["sections"]) {
    if (s["elements"]) {
      out.push_back(s["elements"].as<int>());
      continue;
    }
    const double ratio = s["length"].as<double>() / s["segment_length"].as<double>();
    EXPECT_NEAR(ratio, std::round(ratio), 1e-9) << "the test expects whole segments";
    out.push_back(static_cast<int>(std::lround(ratio)));
  }
  return out;
}

// The point at unstretched arc length s along ~state's polyline A_0..A_n, end, whose rfes have the unstretched
// lengths l (rfe 0 and n a half segment, the others a whole one).
Eigen::Vector3d alongLine(const riser_sim::LineState& st, const std::vector<double>& l, double s) {
  double begin = 0.0;
  for (size_t i = 0; i < l.size(); ++i) {
    if (s <= begin + l[i] || i + 1 == l.size()) {
      const Eigen::Vector3d a = vec(st.points[i]), b = vec(st.points[i + 1]);
      return a + (s - begin) * (b - a).normalized();
    }
    begin += l[i];
  }
  return Eigen::Vector3d::Constant(NAN);
}

// Holds the pose publishers of both scenes for the whole test program: the nodes start once.
struct Inputs {
  ros::NodeHandle nh;
  // Lazy wave: the hang-off at the scene's (0, -10) m until the node runs (its statics start from there),
  // then heaving 1 m over 6 s from heave_from on (slow enough that the line stays taut: a
  // slack line snaps, and its tension spikes between two published samples) (the tension moves through the window).
  std::atomic<double> heave_from{NAN};  // [s] on the publisher's clock
  // The scene's top at t = 0: top.position, plus amplitude cos(phase) of a sinusoid (scene_keys.md).
  static double topAt0(int axis) {
    const YAML::Node top = YAML::LoadFile(g_lazy)["top"];
    double p = top["position"][axis].as<double>();
    const YAML::Node m = top["motion"];
    if (m && m["type"] && m["type"].as<std::string>() == "sinusoid")
      p += m["amplitude"][axis].as<double>() * std::cos(m["phase"] ? m["phase"].as<double>() : 0.0);
    return p;
  }
  const double top_x = topAt0(0), top_z = topAt0(1);
  PosePublisher lazy{nh, "/lazy_wave/vessel/pose", 20.0, [this](double t, geometry_msgs::Pose& p) {
                       const double t0 = heave_from.load();
                       p.position.x = top_x, p.position.z = top_z;
                       p.position.z += t >= t0 ? std::sin(2.0 * M_PI * (t - t0) / 6.0) : 0.0;
                     }};
  void startHeave() {
    if (std::isnan(heave_from.load())) heave_from = (ros::Time::now() - lazy.startTime()).toSec();
  }
  // Floats: both ends where the scene puts them, still.
  PosePublisher vessel{nh, "/floats/vessel/pose", 20.0, [](double, geometry_msgs::Pose& p) {
                         p.position.x = 3.0, p.position.y = 0.0, p.position.z = 1.0;
                       }};
  PosePublisher rov{nh, "/floats/riser_sim/bottom_pose", 20.0, [](double, geometry_msgs::Pose& p) {
                      p.position.x = 25.0, p.position.y = -0.5, p.position.z = -29.7;
                    }};
  Inputs() {
    lazy.start();
    vessel.start();
    rov.start();
  }
};
Inputs* g_inputs = nullptr;

TEST(NodeSectionsAttachments, LazyWaveSectionsInMarkersAndState) {
  ros::NodeHandle nh;
  const YAML::Node scene = YAML::LoadFile(g_lazy);
  const std::vector<int> elements = sectionElements(scene);
  ASSERT_EQ(elements.size(), 3u);
  int n = 0;
  for (int e : elements) n += e;
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/lazy_wave/riser_sim/markers");
  Recorder<riser_sim::LineState> state(nh, "/lazy_wave/riser_sim/state");
  ASSERT_TRUE(markers.waitCount(2, 180.0)) << "no markers from the lazy wave (statics?)";
  g_inputs->startHeave();
  ASSERT_TRUE(state.waitCount(2, 30.0));

  // ~state: n + 1 rfes; rfe i in the section of segment min(i, n - 1): e_k rfes per section, the last e_K + 1.
  const riser_sim::LineState st = state.last();
  ASSERT_TRUE(riser_sim_test::finite(st));
  ASSERT_EQ(st.sections.size(), static_cast<size_t>(n + 1));
  for (size_t k = 0; k < elements.size(); ++k)
    EXPECT_EQ(std::count(st.sections.begin(), st.sections.end(), static_cast<int>(k)),
              elements[k] + (k + 1 == elements.size() ? 1 : 0))
        << "section " << k;
  EXPECT_TRUE(std::is_sorted(st.sections.begin(), st.sections.end()));
  EXPECT_TRUE(st.attachment_names.empty());
  EXPECT_TRUE(st.attachment_points.empty());

  // Markers: one strip per section, each its own colour, e_k + 2 points, meeting where the sections meet, the
  // first starting at the hang-off; no attachment markers.
  const visualization_msgs::MarkerArray m = markers.last();
  ASSERT_TRUE(riser_sim_test::finite(m));
  const auto strips = inNs(m, "sections");
  ASSERT_EQ(strips.size(), elements.size());
  for (size_t k = 0; k < strips.size(); ++k) {
    EXPECT_EQ(strips[k].points.size(), static_cast<size_t>(elements[k] + 2)) << "section " << k;
    for (size_t j = 0; j < k; ++j) {
      const auto &a = strips[k].color, &b = strips[j].color;
      EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.3)
          << "sections " << j << " and " << k << " look alike";
    }
    if (k > 0) {
      EXPECT_LT((vec(strips[k].points.front()) - vec(strips[k - 1].points.back())).norm(), 1e-9);
    }
  }
  const auto line = inNs(m, "line");
  ASSERT_EQ(line.size(), 1u);
  EXPECT_LT((vec(strips.front().points.front()) - vec(line[0].points.front())).norm(), 1e-9);
  EXPECT_LT((vec(strips.back().points.back()) - vec(line[0].points.back())).norm(), 1e-9);
  EXPECT_TRUE(inNs(m, "attachments").empty());
}

// ~range_graph's envelopes over its window against ~tension's values stamped inside that window. Every
// published ~tension is a state the range graph sampled (it samples every solver step; ~tension goes out
// after the steps of a cycle), so max_window >= max_published exactly (1e-9 relative: the same doubles).
// ~tension goes out at the scene's step rate (the launch's tension_rate), so the steps it misses are those of the
// loop's cycles that ran more than one; the envelope exceeds the published maximum only at such a step, by at most the
// largest change between consecutive published values (which holds the step-to-step force noise of the inextensible
// line too); likewise the minima.
TEST(NodeSectionsAttachments, RangeGraphMatchesThePublishedTensionOverItsWindow) {
  ros::NodeHandle nh;
  Recorder<riser_sim::Tension> tension(nh, "/lazy_wave/riser_sim/tension");  // queue 100: ~0.2 s
  Recorder<riser_sim::RangeEnvelope> range(nh, "/lazy_wave/riser_sim/range_graph");
  ASSERT_TRUE(tension.waitCount(1, 180.0));
  g_inputs->startHeave();
  // After the first recorded ~tension and 1 s after the heave began (its sudden start, 1 m/s at once, jerks
  // the line: a tension spike between two 20 Hz samples that the bound below does not cover).
  const ros::Time first = std::max(tension.all().front().header.stamp,
                                   g_inputs->lazy.startTime() + ros::Duration(g_inputs->heave_from.load() + 1.0));
  // A window that starts after `first` and spans at least 3 s (window 4 s, 10 blocks).
  riser_sim::RangeEnvelope g;
  ASSERT_TRUE(waitFor(
      [&] {
        for (const auto& r : range.all())
          if (r.window_start > first && (r.header.stamp - r.window_start).toSec() > 3.0) return g = r, true;
        return false;
      },
      60.0));
  ASSERT_TRUE(tension.waitCount(1, 5.0));
  ASSERT_TRUE(waitFor([&] { return tension.last().header.stamp >= g.header.stamp; }, 10.0));
  ASSERT_TRUE(finite(g));
  // The window: the current block and the 9 before it, blocks of 0.4 s: its first sample at most one step
  // (<= 0.05 s) after the oldest block's start, so it spans at least 3.6 s - 0.05 s (more if the node dropped
  // backlog: its stamps then jump ahead of the run time).
  EXPECT_GT((g.header.stamp - g.window_start).toSec(), 0.9 * 4.0 - 0.05 - 1e-6);
  EXPECT_GE(g.samples, 30u);  // 3.55 s: 71 steps at dt 0.05 s (the lazy wave's), more at smaller dt

  const ros::Duration eps(1e-6);
  double top_max = -INFINITY, top_min = INFINITY, f0_max = -INFINITY, f0_min = INFINITY, d_top = 0.0, d_f0 = 0.0;
  const riser_sim::Tension* prev = nullptr;
  int inside = 0;
  const auto all = tension.all();
  for (const auto& t : all) {
    ASSERT_TRUE(riser_sim_test::finite(t));
    if (t.header.stamp < g.window_start - eps || t.header.stamp > g.header.stamp + eps) continue;
    ++inside;
    top_max = std::max(top_max, t.top), top_min = std::min(top_min, t.top);
    f0_max = std::max(f0_max, t.axial_force[0]), f0_min = std::min(f0_min, t.axial_force[0]);
    if (prev) {
      d_top = std::max(d_top, std::abs(t.top - prev->top));
      d_f0 = std::max(d_f0, std::abs(t.axial_force[0] - prev->axial_force[0]));
    }
    prev = &t;
    ASSERT_EQ(t.arc_length, g.arc_length);
  }
  // >= 3.55 s at the step rate: hundreds; a loaded machine makes the node drop backlog (stamps jump ahead).
  ASSERT_GE(inside, 10);
  // The heave's acceleration 1 m (2π/6 s)² = 1.1 m/s² moves the top tension by ~10 % of the weight (~2 kN).
  EXPECT_GT(top_max - top_min, 100.0) << "the heave moves the top tension (else the test could not fail)";
  const double tol = 1e-9 * top_max;
  EXPECT_GE(g.top_tension_max, top_max - tol);
  EXPECT_LE(g.top_tension_max, top_max + d_top + tol);
  EXPECT_LE(g.top_tension_min, top_min + tol);
  EXPECT_GE(g.top_tension_min, top_min - d_top - tol);
  EXPECT_GE(g.tension_max[0], f0_max - tol);
  EXPECT_LE(g.tension_max[0], f0_max + d_f0 + tol);
  EXPECT_LE(g.tension_min[0], f0_min + tol);
  EXPECT_GE(g.tension_min[0], f0_min - d_f0 - tol);
  // The envelope holds every station's min <= max; the lazy wave lies on the seabed: touch-down sampled.
  for (size_t i = 0; i < g.tension_min.size(); ++i) EXPECT_LE(g.tension_min[i], g.tension_max[i]);
  const YAML::Node scene = YAML::LoadFile(g_lazy);
  if (scene["seabed"]) {  // the lazy wave lies on it beyond its sag bend
    ASSERT_EQ(g.clearance_min.size(), g.arc_length.size());
    EXPECT_GT(g.touchdown_samples, 0u);
    EXPECT_GT(g.touchdown_min, 0.5 * g.arc_length.back());
  } else {
    EXPECT_TRUE(g.clearance_min.empty());
  }

  // ~range_graph/reset: the next window starts after the call.
  ros::ServiceClient reset = nh.serviceClient<std_srvs::Trigger>("/lazy_wave/riser_sim/range_graph/reset");
  ASSERT_TRUE(reset.waitForExistence(ros::Duration(10.0)));
  std_srvs::Trigger srv;
  const ros::Time called = ros::Time::now();
  ASSERT_TRUE(reset.call(srv));
  EXPECT_TRUE(srv.response.success);
  riser_sim::RangeEnvelope after;
  ASSERT_TRUE(waitFor(
      [&] {
        const riser_sim::RangeEnvelope r = range.last();
        return r.header.stamp > called + ros::Duration(0.5) && (after = r, true);
      },
      30.0));
  // The clear applies at the node's next cycle; its stamps lag ROS time by at most ~max_lag (0.5 s).
  EXPECT_GT(after.window_start, called - ros::Duration(0.5));
}

TEST(NodeSectionsAttachments, FloatsAndClumpMarkersSitAtTheirArcLength) {
  ros::NodeHandle nh;
  const YAML::Node scene = YAML::LoadFile(g_scenes + "/rov_tether_floats.yaml");
  const double length = scene["line"]["length"].as<double>(),
               rho = scene["environment"]["water"]["density"].as<double>();
  const int n = scene["line"]["elements"].as<int>();
  ASSERT_FALSE(scene["line"]["axial_flexibility"].as<bool>()) << "the walk along the line needs it inextensible";
  std::vector<double> l(n + 1, length / n);  // the rfes' unstretched lengths (riser_sim/planar/model.h)
  l.front() = l.back() = 0.5 * length / n;
  const YAML::Node att = scene["attachments"];
  ASSERT_EQ(att.size(), 4u);

  Recorder<visualization_msgs::MarkerArray> markers(nh, "/floats/riser_sim/markers");
  Recorder<riser_sim::LineState> state(nh, "/floats/riser_sim/state");
  Recorder<riser_sim::RangeEnvelope> range(nh, "/floats/riser_sim/range_graph");
  ASSERT_TRUE(markers.waitCount(5, 120.0));
  ASSERT_TRUE(range.waitCount(1, 30.0));
  // A markers message and a ~state of the same stamp (both at 10 Hz, sent in the same cycle).
  std::map<ros::Time, riser_sim::LineState> states;
  visualization_msgs::MarkerArray m;
  riser_sim::LineState st;
  ASSERT_TRUE(waitFor(
      [&] {
        for (const auto& s : state.all()) states[s.header.stamp] = s;
        for (const auto& a : markers.all()) {
          if (a.markers.empty()) continue;
          const auto it = states.find(a.markers[0].header.stamp);
          if (it != states.end()) return m = a, st = it->second, true;
        }
        return false;
      },
      30.0));
  ASSERT_TRUE(riser_sim_test::finite(m));
  ASSERT_TRUE(riser_sim_test::finite(st));
  EXPECT_EQ(inNs(m, "sections").size(), 1u);  // a uniform line: one section
  ASSERT_EQ(st.sections.size(), static_cast<size_t>(n + 1));
  EXPECT_EQ(std::count(st.sections.begin(), st.sections.end(), 0), n + 1);

  const auto spheres = inNs(m, "attachments"), arrows = inNs(m, "attachment_forces");
  ASSERT_EQ(spheres.size(), att.size());
  ASSERT_EQ(arrows.size(), att.size());
  ASSERT_EQ(st.attachment_points.size(), att.size());
  for (size_t k = 0; k < att.size(); ++k) {
    SCOPED_TRACE(att[k]["name"].as<std::string>());
    EXPECT_EQ(st.attachment_names[k], att[k]["name"].as<std::string>());
    const double s = att[k]["arc_length"].as<double>(), mass = att[k]["mass"].as<double>(),
                 volume = att[k]["volume"].as<double>();
    // On rfe i at s - s_begin_i along its chord: the polyline of ~state at s (round-off on a 60 m line).
    const Eigen::Vector3d p = vec(spheres[k].pose.position);
    EXPECT_LT((p - alongLine(st, l, s)).norm(), 1e-9 * length);
    EXPECT_LT((p - vec(st.attachment_points[k])).norm(), 1e-12 * length);
    // At least a sphere of its displaced volume; yellow when buoyant (floats), red-brown (the clump).
    EXPECT_GE(spheres[k].scale.x, 2.0 * std::cbrt(3.0 * volume / (4.0 * M_PI)) - 1e-12);
    const bool buoyant = rho * volume > mass;
    EXPECT_EQ(spheres[k].color.r > 0.9 && spheres[k].color.g > 0.8, buoyant);
    // Ends held still: the line is at rest in its statics, the force on it is its net weight (ρ V - m) g up;
    // drag at the residual motion's speed (< 0.1 m/s: ½ ρ C_d A u² < 0.15 N) is within 5 %.
    const Eigen::Vector3d f = vec(st.attachment_forces[k]), weight(0.0, 0.0, (rho * volume - mass) * kG);
    EXPECT_LT((f - weight).norm(), 0.05 * weight.norm()) << f.transpose();
    // The arrow from the centre along the force.
    ASSERT_EQ(arrows[k].points.size(), 2u);
    EXPECT_LT((vec(arrows[k].points[0]) - p).norm(), 1e-12 * length);
    const Eigen::Vector3d dir = vec(arrows[k].points[1]) - p;
    EXPECT_GT(dir.normalized().dot(f.normalized()), 1.0 - 1e-9);
  }
  // Floats one colour, the clump another.
  EXPECT_NE(spheres[0].color.g, spheres[1].color.g);
  const riser_sim::RangeEnvelope g = range.last();
  EXPECT_TRUE(finite(g));
  EXPECT_EQ(g.arc_length.size(), static_cast<size_t>(n + 1));
  EXPECT_TRUE(g.clearance_min.empty());  // no seabed
  EXPECT_EQ(g.touchdown_samples, 0u);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_sections_attachments");
  if (argc < 3) {
    std::fprintf(stderr, "usage: test_node_sections_attachments <sectioned scene.yaml> <config/scenes>\n");
    return 2;
  }
  g_lazy = argv[1];
  g_scenes = argv[2];
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Inputs inputs;
  g_inputs = &inputs;
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
