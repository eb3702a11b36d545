// The node's 3D outputs without a master, through the run the node steps (NodeRun): ~state's curvature and
// bending moment (against the planar node's on the same scene, and against the analytic catenary), the
// markers of the sea and the seabed, the twist in the rfe frames.
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/water.h"
#include "riser_sim/spatial/rfe_frames.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim_ros/node_run.h"
#include "riser_sim_ros/modes_service.h"

namespace riser_sim_ros {
namespace {

using Vec3 = Eigen::Vector3d;

riser_sim::Scene scene(const char* yaml) { return riser_sim::parseScene(YAML::Load(yaml)); }

std::unique_ptr<NodeRun> startAt(const riser_sim::Scene& scene, const Vec3& hangoff) {
  VesselSample s;
  s.hangoff = hangoff;
  NodeParams params;
  auto run = std::make_unique<NodeRun>(scene, s, 0.0, params);
  EXPECT_TRUE(run->evaluate());
  return run;
}

// A slack 20 m line between a hang-off 8 m off the anchor's vertical and an anchor 15 m down (a bent,
// planar static state), planar and, with `space: spatial`, in the vertical plane at azimuth psi.
const char* kTether = R"(
name: tether
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 0.0, axial_flexibility: false,
       bending: true, bending_damping: 20.0}
top: {position: [8.0, 0.0], motion: {type: external}}
bottom: {type: pinned, position: [0.0, -15.0]}
environment: {gravity: 9.81}
initial: {type: between_points}
solver: {dt: 0.001}
)";

// The same static state: the 3D joint curvature and moment are the planar ones (the planar moment signed
// about -y, the 3D one a vector: rotated by the plane's azimuth). The 3D statics are the planar ones
// rotated (run_builder.h), so equal to round-off: 1e-9 relative.
TEST(SpatialState, CurvatureAndMomentAreThePlanarNodesInAnyVerticalPlane) {
  const riser_sim::Scene planar = scene(kTether);
  const riser_sim::LineState p = startAt(planar, Vec3(8.0, 0.0, 0.0))->state(ros::Time(1));
  const int joints = planar.elements;
  ASSERT_EQ(p.curvatures.size(), size_t(joints));
  ASSERT_EQ(p.bending_moment_vectors.size(), size_t(joints));
  double biggest = 0.0;
  for (int j = 0; j < joints; ++j) biggest = std::max(biggest, std::abs(p.bending_moments[j]));
  ASSERT_GT(biggest, 1.0);  // bent: a real comparison [N m]
  for (double psi : {0.0, 0.6, -2.0}) {
    riser_sim::Scene s = planar;
    s.space = riser_sim::SpaceKind::kSpatial;
    const Vec3 top(8.0 * std::cos(psi), 8.0 * std::sin(psi), 0.0);
    s.top.position = top;
    s.bottom_point = Vec3(0.0, 0.0, -15.0);
    std::unique_ptr<NodeRun> run = startAt(s, top);
    const riser_sim::LineState q = run->state(ros::Time(1));
    ASSERT_EQ(q.curvatures.size(), size_t(joints));
    ASSERT_EQ(q.bending_moments.size(), size_t(joints));
    ASSERT_EQ(q.bending_moment_vectors.size(), size_t(joints));
    ASSERT_EQ(q.elongations.size(), size_t(joints + 1));
    const Eigen::AngleAxisd yaw(psi, Vec3::UnitZ());
    for (int j = 0; j < joints; ++j) {
      const double tol = 1e-9 * biggest;
      EXPECT_NEAR(q.curvatures[j], p.curvatures[j], tol / 100.0) << j;                 // EI = 100 N m²
      EXPECT_NEAR(q.curvatures[j] * 100.0, std::abs(p.bending_moments[j]), tol) << j;  // EI κ, at rest
      EXPECT_NEAR(q.bending_moments[j], std::abs(p.bending_moments[j]), tol) << j;
      const auto& v = q.bending_moment_vectors[j];
      const Vec3 expect = yaw * Vec3(0.0, -p.bending_moments[j], 0.0);
      EXPECT_LT((Vec3(v.x, v.y, v.z) - expect).norm(), tol) << "joint " << j + 1 << " psi " << psi;
    }
  }
}

// A heavy chain hanging between two points in a yawed plane, EI small: the catenary. Its curvature at arc
// length s is a / (a² + (s - s_v)²), a = H / w, s_v = V_top / w the vertex's arc length (H, V_top the top
// force's horizontal and vertical parts from the node's own top wrench, w the weight per length). Each
// rfe lies along the tangent at its middle (moment balance of a uniform link), so the joint angle over d is
// the mean curvature over [s - d/2, s + d/2]: within |κ''| d²/24 <= κ d²/(12 a²) of κ(s) (|κ''/κ| <= 2/a²).
// The joints next to the half-length end rfes (1 and n) span 3d/4 and are left out. EI = 1 N m²: its
// boundary layer sqrt(EI/T) is ~5 mm here, a share ~1e-4 of the moment.
TEST(SpatialState, HangingCatenaryCurvatureIsTheAnalyticOne) {
  const double psi = 0.5, w = 10.0 * 9.81, L = 100.0;
  const int n = 50;
  const double d = L / n;
  const Vec3 top(60.0 * std::cos(psi), 60.0 * std::sin(psi), 0.0);
  riser_sim::Scene s = scene(R"(
name: catenary
space: spatial
line: {length: 100.0, elements: 50, mass_per_length: 10.0, EI: 1.0, axial_flexibility: false}
top: {position: [0.0, 0.0, 0.0], motion: {type: external}}
bottom: {type: pinned, position: [0.0, 0.0, -50.0]}
environment: {gravity: 9.81}
initial: {type: between_points}
solver: {dt: 0.001}
)");
  s.top.position = top;
  std::unique_ptr<NodeRun> run = startAt(s, top);
  const geometry_msgs::Wrench& f = run->topWrench(ros::Time(1)).wrench;  // the line's pull on the hang-off
  const double H = std::hypot(f.force.x, f.force.y), V = -f.force.z, a = H / w, sv = V / w;
  ASSERT_GT(sv, 0.0);
  ASSERT_LT(sv, L);  // the vertex lies on the line: the curvature peaks inside
  const riser_sim::LineState st = run->state(ros::Time(1));
  ASSERT_EQ(st.curvatures.size(), size_t(n));
  double worst = 0.0;
  for (int j = 2; j < n; ++j) {  // joint j at s = (j - 1/2) d
    const double sj = (j - 0.5) * d, kappa = a / (a * a + (sj - sv) * (sj - sv));
    worst = std::max(worst, std::abs(st.curvatures[j - 1] / kappa - 1.0));
    EXPECT_NEAR(st.curvatures[j - 1], kappa, kappa * (d * d / (12.0 * a * a) + 1e-3)) << "joint " << j;
    EXPECT_NEAR(st.bending_moments[j - 1], 1.0 * st.curvatures[j - 1], 1e-12);  // EI κ, at rest
  }
  // The moment vectors are horizontal, across the plane (normal (-sin psi, cos psi, 0)).
  for (const auto& v : st.bending_moment_vectors) EXPECT_NEAR(v.x * std::cos(psi) + v.y * std::sin(psi), 0.0, 1e-12);
  std::printf("catenary a = %.3f m, vertex at s = %.3f m, worst relative curvature error %.2e (bound %.2e)\n", a, sv,
              worst, d * d / (12.0 * a * a));
}

// The sea's markers: the current's arrows along its heading with the profile's speeds, the wave surface on
// the water model's elevation at the run's time, the sloped seabed's slab on its plane with its normal
// (docs/scene_keys.md: n = (-sin θ cos ψ, -sin θ sin ψ, cos θ), z_b = level + tan θ (x cos ψ + y sin ψ)).
TEST(SeaMarkers, CurrentWavesAndSlopedSeabed) {
  const double cur = 30.0 * M_PI / 180.0, slope = 10.0 * M_PI / 180.0, psi = 45.0 * M_PI / 180.0;
  const riser_sim::Scene s = scene(R"(
name: sea
space: spatial
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false,
       outer_diameter: 0.05}
top: {position: [0.0, 0.0, 2.0], motion: {type: external}}
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {profile: [[0.0, 0.8660254037844386, 0.5], [10.0, 0.4330127018922193, 0.25]]}
  waves: {height: 2.0, period: 3.0, heading: 120.0, depth: 200.0}
seabed: {level: -100.0, stiffness_normal: 1.0e5, slope: 10.0, slope_heading: 45.0}
solver: {dt: 0.001}
)");
  std::unique_ptr<NodeRun> run = startAt(s, Vec3(0.0, 0.0, 2.0));
  for (int k = 0; k < 50; ++k) ASSERT_TRUE(run->step());  // t = 0.05 s: the waves have moved
  ASSERT_TRUE(run->evaluate());
  const visualization_msgs::MarkerArray& msg = run->markers(ros::Time(1));
  const double t = run->time();
  riser_sim::WaterSpec w = s.water;  // the water model's elevation along the heading (Water3's waves)
  w.current = riser_sim::CurrentSpec();
  w.waves.heading = 0.0;
  const riser_sim::WaterKinematics waves(w, 9.81);
  const Vec3 heading(std::cos(s.water.waves.heading), std::sin(s.water.waves.heading), 0.0);
  int arrows = 0, surfaces = 0, seabeds = 0;
  double eta_lo = 1e9, eta_hi = -1e9;
  for (const auto& m : msg.markers) {
    for (const auto& p : m.points) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    if (m.ns == "current") {
      ++arrows;
      ASSERT_EQ(m.points.size(), 2u);
      const Vec3 a(m.points[1].x - m.points[0].x, m.points[1].y - m.points[0].y, m.points[1].z - m.points[0].z);
      const double depth = -m.points[0].z;
      EXPECT_NEAR(a.normalized().dot(Vec3(std::cos(cur), std::sin(cur), 0.0)), 1.0, 1e-12) << depth;
      // Speed 1 m/s at the surface, 0.5 below 10 m: the arrows' lengths keep that ratio.
      const double speed = depth >= 10.0 ? 0.5 : 1.0 - 0.05 * depth;
      EXPECT_NEAR(a.norm(), speed * 0.15 * 20.0, 1e-9) << depth;  // the fastest is 0.15 L long
    } else if (m.ns == "water_surface") {
      ++surfaces;
      EXPECT_EQ(m.type, visualization_msgs::Marker::TRIANGLE_LIST);
      ASSERT_GE(m.points.size(), 6u);
      EXPECT_EQ(m.points.size() % 3, 0u);
      for (const auto& p : m.points) {
        const double eta = waves.elevation(heading.dot(Vec3(p.x, p.y, 0.0)), t);
        EXPECT_NEAR(p.z, eta, 1e-9);
        eta_lo = std::min(eta_lo, p.z), eta_hi = std::max(eta_hi, p.z);
      }
    } else if (m.ns == "seabed") {
      ++seabeds;
      EXPECT_EQ(m.type, visualization_msgs::Marker::CUBE);
      const auto& q = m.pose.orientation;
      const Vec3 n = Eigen::Quaterniond(q.w, q.x, q.y, q.z) * Vec3::UnitZ();
      const Vec3 expect(-std::sin(slope) * std::cos(psi), -std::sin(slope) * std::sin(psi), std::cos(slope));
      EXPECT_LT((n - expect).norm(), 1e-12);
      const auto& c = m.pose.position;
      EXPECT_NEAR(c.z, -100.0 + std::tan(slope) * (c.x * std::cos(psi) + c.y * std::sin(psi)), 1e-9);
    }
  }
  EXPECT_EQ(arrows, 5);
  EXPECT_EQ(surfaces, 1);  // the waves' surface replaces the flat slab
  EXPECT_EQ(seabeds, 1);   // the sloped slab replaces the level one
  // A real wave on the grid: H = 2 m, wave length g T²/2π = 14 m < the strip's 20 m span.
  EXPECT_GT(eta_hi - eta_lo, 1.5);
}

// Torsion on: rfe i's frame is its material frame. Spin angles θ_i = 0.1 i on a hanging straight line turn
// frame i by θ_i about its axis from the untwisted one; after 0.2 s of motion the turn from frame k to
// frame k + 1 about e_{k+1} (after the parallel transport across the joint) is the core's twist m_k.
TEST(TwistFrames, FramesTurnByTheTwistAboutTheAxis) {
  riser_sim::Scene s = scene(R"(
name: twist
space: spatial
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false,
       torsion: {stiffness: 200.0, polar_inertia: 0.5}}
top: {position: [0.0, 0.0, 0.0]}
solver: {dt: 0.001}
)");
  namespace sp = riser_sim::spatial;
  sp::Run3 run(s);
  sp::Simulator3& sim = run.simulator();
  const int nb = run.model().bodies();
  riser_sim::VecX theta(nb), omega = riser_sim::VecX::Zero(nb), zero = riser_sim::VecX::Zero(nb);
  for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i;
  sim.setTwist(theta, omega);
  sp::Kinematics3 kin(nb);
  sim.kinematics(kin);
  // The frames the run publishes (line_run.cpp: materialFrame with the spins, rfe 0 held untwisted).
  const auto frames = [&](const double* theta, std::vector<Eigen::Quaterniond>& q) {
    const sp::TwistFrames& f = sim.lastEvaluation().twist.frames;
    q.resize(nb);
    for (int i = 0; i < nb; ++i) q[i] = sp::materialFrame(kin[i].e, f.centre[i], f.ref[i], i == 0 ? 0.0 : theta[i]);
  };
  run.outputs();  // evaluates the state: the twist charts of lastEvaluation()
  std::vector<Eigen::Quaterniond> twisted, flat;
  frames(sim.state().data() + run.model().dofs(), twisted);
  frames(zero.data(), flat);
  for (int i = 0; i < nb; ++i) {
    const Eigen::Quaterniond a = flat[i], b = twisted[i];
    const Vec3 e = kin[i].e.normalized();
    EXPECT_LT((b * Vec3::UnitX() - e).norm(), 1e-12);
    const Vec3 ya = a * Vec3::UnitY(), yb = b * Vec3::UnitY();
    EXPECT_NEAR(std::atan2(ya.cross(yb).dot(e), ya.dot(yb)), i == 0 ? 0.0 : 0.1 * i, 1e-12) << "rfe " << i;
  }
  for (int k = 0; k < 200; ++k) ASSERT_TRUE(run.step());
  sim.kinematics(kin);
  const sp::NaturalData& d = sim.evaluate();
  frames(sim.state().data() + run.model().dofs(), twisted);
  double largest = 0.0, worst = 0.0;
  for (int k = 0; k + 1 < nb; ++k) {
    const Vec3 e0 = kin[k].e.normalized(), e1 = kin[k + 1].e.normalized();
    const Vec3 y0 = sp::minimalRotation(e0, e1, twisted[k] * Vec3::UnitY());
    const Vec3 y1 = twisted[k + 1] * Vec3::UnitY();
    const double turn = std::atan2(y0.cross(y1).dot(e1), y0.dot(y1));
    const double miss = std::abs(std::remainder(turn - d.twist.m[k], 2.0 * M_PI));
    EXPECT_LT(miss, 1e-9) << "joint " << k;
    largest = std::max(largest, std::abs(d.twist.m[k])), worst = std::max(worst, miss);
  }
  std::printf("twist: largest m_k %.4f rad, frames' turn minus m_k at most %.1e rad\n", largest, worst);
  EXPECT_GT(largest, 0.01);  // still twisted: a real comparison
}

// The node's path (NodeRun) with torsion on: the vessel swings the hang-off sideways; every frame is
// finite, unit, its x axis along its element, its y across it.
TEST(TwistFrames, TheNodesRunPublishesMaterialFrames) {
  riser_sim::Scene s = scene(R"(
name: twist_run
space: spatial
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false,
       torsion: {stiffness: 200.0, polar_inertia: 0.5}}
top: {position: [0.0, 0.0, 0.0], motion: {type: external}}
solver: {dt: 0.001}
)");
  std::unique_ptr<NodeRun> run = startAt(s, Vec3::Zero());
  VesselSample v;
  for (int k = 1; k <= 300; ++k) {
    v.hangoff = Vec3(0.5 * std::sin(0.01 * k), 0.5 * (1.0 - std::cos(0.01 * k)), 0.0);
    ASSERT_TRUE(run->addSample(0.001 * k, v)) << k;
    ASSERT_TRUE(run->step());
  }
  ASSERT_TRUE(run->evaluate());
  const riser_sim::LineState st = run->state(ros::Time(1));
  const auto& tf = run->transforms(ros::Time(1));
  ASSERT_EQ(tf.size(), st.points.size());
  for (size_t i = 0; i + 1 < tf.size(); ++i) {
    const auto& q = tf[i].transform.rotation;
    const Eigen::Quaterniond r(q.w, q.x, q.y, q.z);
    ASSERT_TRUE(r.coeffs().allFinite()) << i;
    EXPECT_NEAR(r.norm(), 1.0, 1e-12);
    const Vec3 e = Vec3(st.points[i + 1].x - st.points[i].x, st.points[i + 1].y - st.points[i].y,
                        st.points[i + 1].z - st.points[i].z)
                       .normalized();
    EXPECT_LT((r * Vec3::UnitX() - e).norm(), 1e-6) << i;  // the joints' gaps: ~1e-9 m of 2 m elements
  }
}

// The node's path with a top flex joint (undamped: its moment is the spring's at every instant): the vessel
// rolls 0.15 rad over 1 s and holds; the joint's axis turns with it, so the torque of ~top_wrench is
// k angle(R d_0, e_0) about (e_0 × R d_0) with R the commanded roll and e_0 the top element from ~state's points
// (a joint fixed in the world would give k angle(d_0, e_0)).
TEST(FlexJoint, TurnsWithTheVessel) {
  riser_sim::Scene s = scene(R"(
name: flex_roll
space: spatial
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false,
       bending_damping: 20.0}
top: {position: [0.0, 0.0, 0.0], motion: {type: external}, flex_joint: {stiffness: 2.0e4}}
solver: {dt: 0.001}
)");
  std::unique_ptr<NodeRun> run = startAt(s, Vec3::Zero());
  VesselSample v;
  double worst = 0.0, biggest = 0.0, fixed_gap = 1e300;
  for (int k = 1; k <= 3000; ++k) {  // 3 s: the roll over the first second, then held
    const double roll = 0.15 * std::min(1.0, 0.001 * k);
    v.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(roll, Vec3::UnitX()));
    ASSERT_TRUE(run->addSample(0.001 * k, v)) << k;
    ASSERT_TRUE(run->step()) << run->divergenceReason();
    if (k < 2000 || k % 100 != 0) continue;  // the smoothed attitude has reached the held roll
    ASSERT_TRUE(run->evaluate());
    const riser_sim::LineState st = run->state(ros::Time(3));
    const auto& tq = run->topWrench(ros::Time(3)).wrench.torque;
    const Vec3 e0 =
        Vec3(st.points[1].x - st.points[0].x, st.points[1].y - st.points[0].y, st.points[1].z - st.points[0].z)
            .normalized();
    const Vec3 d = Eigen::AngleAxisd(0.15, Vec3::UnitX()) * Vec3(0, 0, -1);
    const Vec3 expected = -2.0e4 * std::acos(std::clamp(e0.dot(d), -1.0, 1.0)) * e0.cross(d).normalized();
    const Vec3 d0(0, 0, -1), fixed = -2.0e4 * std::acos(std::clamp(e0.dot(d0), -1.0, 1.0)) * e0.cross(d0).normalized();
    worst = std::max(worst, (Vec3(tq.x, tq.y, tq.z) - expected).norm());
    fixed_gap = std::min(fixed_gap, (Vec3(tq.x, tq.y, tq.z) - fixed).norm());
    biggest = std::max(biggest, expected.norm());
  }
  std::printf(
      "[ INFO ] rolled flex joint: torque minus k angle(R d0, e0) <= %.2e N m of %.1f N m; a joint fixed in "
      "the world would be off by >= %.1f N m\n",
      worst, biggest, fixed_gap);
  EXPECT_GT(biggest, 100.0);  // the roll loads the joint (the line swings after it: 218 N m at most, measured)
  EXPECT_GT(fixed_gap, 1e3);  // ~k x 0.15 rad: what a joint that did not turn would miss
  // The joint's gaps at the top (~1e-9 m over 2 m elements) bound e_0 from the points: 1e-8 rad of k = 2e4.
  EXPECT_LT(worst, 1e-3);
}

// 3D ~modes refuses bad counts, naming the field; a
// hanging line's lowest transverse modes come in degenerate pairs turned into and across the statics' plane.
TEST(SpatialModes, RefusalsNameTheFieldAndPairsSplitByPlane) {
  riser_sim::Scene s = scene(R"(
name: hang
space: spatial
line: {length: 20.0, elements: 6, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false}
top: {position: [0.0, 0.0, 0.0]}
solver: {dt: 0.001}
)");
  riser_sim::Modes::Response r;
  computeModesResponse(s, 0, r);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.message, "count: must be >= 1, got 0");
  r = riser_sim::Modes::Response();
  computeModesResponse(s, 1000, r);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.message.rfind("count: must be <= ", 0), 0u) << r.message;
  r = riser_sim::Modes::Response();
  computeModesResponse(s, 4, r);
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_EQ(r.characters.size(), 4u);
  EXPECT_NEAR(r.periods[0], r.periods[1], 1e-6 * r.periods[0]);        // a pair across the vertical
  EXPECT_NE(r.characters[0], r.characters[1]);                         // one in the plane, one across it
  for (size_t k = 0; k < 4; ++k) EXPECT_NE(r.characters[k], "axial");  // inextensible
}

// With line.torsion the same line gains torsional modes (spins, as the CLI's --modes names them); its
// bending modes are those without torsion (the spins do not couple at a straight, untwisted equilibrium: the
// core's modal test measures 6e-14 in ω²).
TEST(SpatialModes, TorsionAddsTorsionalModesAndKeepsTheBendingOnes) {
  const char* yaml = R"(
name: hang
space: spatial
line: {length: 20.0, elements: 6, mass_per_length: 5.0, EI: 100.0, end_mass: 50.0, axial_flexibility: false%s}
top: {position: [0.0, 0.0, 0.0]}
solver: {dt: 0.001}
)";
  char with[600], without[600];
  std::snprintf(with, sizeof(with), yaml, ",\n       torsion: {stiffness: 200.0, polar_inertia: 0.5}");
  std::snprintf(without, sizeof(without), yaml, "");
  const riser_sim::Scene st = scene(with), s0 = scene(without);
  riser_sim::Modes::Response mt, m0;
  computeModesResponse(s0, 4, m0);
  ASSERT_TRUE(m0.success) << m0.message;
  computeModesResponse(st, m0.dofs + 6, mt);  // every mode: the spins of rfes 1..6 on top
  ASSERT_TRUE(mt.success) << mt.message;
  EXPECT_GE(mt.dofs, m0.dofs + 6);  // the top rfe's spin is held (top.torsion: fixed)
  std::vector<double> bending;
  int torsional = 0;
  for (size_t k = 0; k < mt.characters.size(); ++k) {
    if (mt.characters[k] == "torsional")
      ++torsional;
    else if (bending.size() < 4)
      bending.push_back(mt.periods[k]);
  }
  EXPECT_GE(torsional, 6);
  ASSERT_EQ(bending.size(), 4u);
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(bending[k], m0.periods[k], 1e-9 * m0.periods[k]) << k;
}

}  // namespace
}  // namespace riser_sim_ros

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::Time::init();
  return RUN_ALL_TESTS();
}
