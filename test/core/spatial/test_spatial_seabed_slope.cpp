// The sloped seabed in 3D (spatial/forces/seabed.h, seabed.slope / seabed.slope_heading):
// - the law on the incline: its normal and penetration against the closed form, the normal force and the friction
//   along / across a line lying on it, the spring against its energy and the power (FD, spatial_force_checks.h);
// - slope 0 is the level seabed bit for bit (the force law on random states; a run);
// - sliding limits, measured by a holder at A_0 moving the stiff line along the fall line: the force it needs is
//   m a - m g sin θ + μ N_s s(v), s(v) = v / sqrt(v² + v_s²), N_s = m g cos θ - F_n (F_n: what the holder carries
//   normal to the plane). Steep (tan θ > μ): at a = g (sin θ - μ cos θ) it needs ~0: a free line slides at a.
//   Gentle (tan θ < μ): at the creep speed v_c = v_s r / sqrt(1 - r²), r = tan θ / μ, it needs ~0; held still it
//   carries m g sin θ (the smoothed friction vanishes at rest: a free line creeps at v_c, never faster);
// - turning the heading turns the run; a line hanging onto the slope starts in a checked equilibrium and stays;
// - a pinned end on the slope (downhill, uphill, across the fall line) starts at rest, its forces balanced;
// - the keys refused where they do not apply, naming them; a displaced end resting on the slope.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_force_checks.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kDeg = M_PI / 180.0;

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof(b), "%.17g", v);
  return b;
}

std::string vec(const Vec3& v) { return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]"; }

// The plane's normal from the keys' convention: steepest ascent towards heading ψ, tilted by θ.
Vec3 normalOf(double theta, double psi) {
  return Vec3(-std::sin(theta) * std::cos(psi), -std::sin(theta) * std::sin(psi), std::cos(theta));
}

SeabedSpec slopeSpec(double theta, double psi) {
  SeabedSpec s;
  s.enabled = true;
  s.level = -2.0;
  s.stiffness_normal = 1e5;
  s.damping_normal = 300.0;
  s.damping_tangential = 50.0;
  s.friction_axial = 0.4;
  s.friction_lateral = 0.9;
  s.friction_velocity = 0.05;
  s.slope = theta;
  s.slope_heading = psi;
  return s;
}

TEST(SpatialSeabedSlope, LawOnTheIncline) {
  spatial_test::LineSpec ls = spatial_test::flexibleLine();
  ls.segments = 6;
  const double theta = 20.0 * kDeg, psi = 50.0 * kDeg;
  auto m = spatial_test::spatialModel(ls, Vec3(0.0, 0.0, -9.81));
  SeabedSpec spec = slopeSpec(theta, psi);
  spec.damping_normal = spec.damping_tangential = 0.0;
  const spatial::Seabed bed(spec, m->gravity());
  const Vec3 n = normalOf(theta, psi);
  EXPECT_LE((bed.normal() - n).norm(), 1e-15);
  // Penetration: the height below the plane z_b = level + tan θ (x cos ψ + y sin ψ), times cos θ.
  const Vec3 x(3.0, -1.5, -4.0);
  const double zb = spec.level + std::tan(theta) * (x.x() * std::cos(psi) + x.y() * std::sin(psi));
  EXPECT_NEAR(bed.penetration(x), (zb - x.z()) * std::cos(theta), 1e-14);
  // A line lying in the plane along a (at 35 deg within it from the fall line), 1 mm in, sliding at v along a
  // or across it (l = n × a): every point feels C p n - μ C p v̂ v / sqrt(v² + v_s²). Round-off bound.
  const Vec3 up = Vec3::UnitZ(), h = Vec3(std::cos(psi), std::sin(psi), 0.0);
  const Vec3 fall = -std::cos(theta) * h - std::sin(theta) * up, side = n.cross(fall);
  const Vec3 a = std::cos(35.0 * kDeg) * fall + std::sin(35.0 * kDeg) * side, l = n.cross(a);
  const double p = 1e-3, v = 0.2, N = spec.stiffness_normal * p * (m->bodies() + 1);
  for (const bool across : {false, true}) {
    const Vec3 vel = v * (across ? l : a);
    const Kinematics3 kin =
        rigidChain(m->line(), Vec3(0.0, 0.0, spec.level) - p * n, std::vector<Vec3>(m->bodies(), a), vel, Vec3::Zero());
    EXPECT_EQ(bed.contacts(*m, kin), m->bodies() + 1);
    VecX Q = VecX::Zero(m->dofs());
    const double P = bed.addForcesAndPower(*m, kin, 0.0, Q);
    Vec3 F = Vec3::Zero();
    for (int i = 0; i < m->bodies(); ++i) F += Q.segment<3>(kDofPerBody3 * i + kA);
    const double mu = across ? spec.friction_lateral : spec.friction_axial;
    const Vec3 fric = -mu * N * v / std::hypot(v, spec.friction_velocity) * vel.normalized();
    EXPECT_LE((F - N * n - fric).norm(), 1e-11 * N) << (across ? "across" : "along");
    EXPECT_NEAR(P, fric.dot(vel), 1e-11 * N * v);  // the friction's power (the spring's is in dV/dt)
    EXPECT_NEAR(bed.potentialEnergy(*m, kin, 0.0), 0.5 * spec.stiffness_normal * p * p * (m->bodies() + 1), 1e-9);
  }
  // Against its energy and power on random states (tilted gravity: the heading projected normal to up).
  auto mt = spatial_test::spatialModel(ls, Vec3(1.2, -0.7, -9.5));
  const spatial::Seabed tilted(slopeSpec(theta, psi), mt->gravity());
  spatial_test::checkGradient(tilted, *mt);
  spatial_test::checkPower(tilted, *mt);
  std::mt19937 rng(7);
  const NaturalFormulation f(*mt, 50.0);
  Kinematics3 kin(mt->bodies());
  f.kinematics(spatial_test::randomState(*mt, rng, false), kin);
  const int c = tilted.contacts(*mt, kin);
  EXPECT_GE(c, 2);
  EXPECT_LE(c, mt->bodies());  // some points above: the check has teeth on both sides
}

TEST(SpatialSeabedSlope, SlopeZeroIsTheLevelSeabed) {
  spatial_test::LineSpec ls = spatial_test::flexibleLine();
  ls.segments = 5;
  auto m = spatial_test::spatialModel(ls, Vec3(1.2, -0.7, -9.5));
  SeabedSpec level = slopeSpec(0.0, 0.0);
  level.level = 4.0;
  SeabedSpec zero = level;
  zero.slope_heading = 1.3;  // no effect at slope 0
  const spatial::Seabed a(level, m->gravity()), b(zero, m->gravity());
  std::mt19937 rng(3);
  const NaturalFormulation f(*m, 50.0);
  for (int trial = 0; trial < 5; ++trial) {
    Kinematics3 kin(m->bodies());
    f.kinematics(spatial_test::randomState(*m, rng, true), kin);
    VecX Qa = VecX::Zero(m->dofs()), Qb = VecX::Zero(m->dofs());
    EXPECT_EQ(a.addForcesAndPower(*m, kin, 0.0, Qa), b.addForcesAndPower(*m, kin, 0.0, Qb));
    EXPECT_TRUE(Qa == Qb);
    EXPECT_EQ(a.potentialEnergy(*m, kin, 0.0), b.potentialEnergy(*m, kin, 0.0));
  }
}

// The stiff 2 m line (n = 4, 100 kg) lying down the fall line of an incline θ towards heading ψ, its top A_0 at the
// static sink below the plane, driven along the fall line (knots: t, speed); midpoint 1 ms. Returns the means over
// [t0, t1] of the holder's force on the line along the fall line and normal to the plane, and the end position.
struct Slide {
  double along = 0.0, normal = 0.0;
  AlignedVector<Vec3> points;
};

Slide slide(double theta, double psi, double mu, const std::vector<std::pair<double, double>>& knots, double t0,
            double t1, const std::vector<double>& sample_at = {}, std::vector<AlignedVector<Vec3>>* samples = nullptr) {
  const double m = 100.0, g = 9.81, k = 1e5;
  const Vec3 n = normalOf(theta, psi), h(std::cos(psi), std::sin(psi), 0.0);
  const Vec3 fall = -std::cos(theta) * h - std::sin(theta) * Vec3::UnitZ();
  const Vec3 top = -(m * g * std::cos(theta) / (6.0 * k)) * n;  // the static sink of 6 points, on the origin's normal
  std::string ks = "[";
  for (size_t i = 0; i < knots.size(); ++i)
    ks += (i ? ", [" : "[") + num(knots[i].first) + ", " + vec(knots[i].second * fall) + "]";
  ks += "]";
  const Scene s = loadSceneText(
      "space: spatial\nline: {length: 2.0, elements: 4, EA: 1.0e8, EI: 1.0e7, mass_per_length: 50.0, axial_damping: "
      "7.0e4, bending_damping: 1.0e4}\ntop: {position: " +
          vec(top) + ", motion: {type: velocity_profile, knots: " + ks +
          "}}\ninitial: {type: straight, angle: " + num(-theta / kDeg) + ", heading: " + num(psi / kDeg + 180.0) +
          "}\nseabed: {level: 0.0, stiffness_normal: 1.0e5, damping_normal: 2.6e3, friction_velocity: 0.01, "
          "friction_axial: " +
          num(mu) + ", friction_lateral: 0.9, slope: " + num(theta / kDeg) + ", slope_heading: " + num(psi / kDeg) +
          "}\nsolver: {integrator: midpoint, dt: 0.001}\n",
      "slide");
  Run3 run(s);
  Slide out;
  int count = 0;
  size_t next = 0;
  const long steps = std::lround(t1 / run.dt());
  for (long i = 1; i <= steps; ++i) {
    EXPECT_TRUE(run.step()) << run.divergenceReason();
    const double t = i * run.dt();
    const bool sample = samples && next < sample_at.size() && std::abs(t - sample_at[next]) < 0.5 * run.dt();
    const bool window = t >= t0 - 1e-9;
    if (!sample && !window) continue;
    const LineOutputs3& o = run.outputs();
    if (sample) samples->push_back(o.points), ++next;
    if (!window) continue;
    out.along -= o.top_force.dot(fall);  // the holder's force on the line
    out.normal -= o.top_force.dot(n);
    ++count;
  }
  out.along /= count;
  out.normal /= count;
  out.points = run.outputs().points;
  return out;
}

TEST(SpatialSeabedSlope, SlidesDownASteepIncline) {
  const double theta = 30.0 * kDeg, psi = 30.0 * kDeg, mu = 0.3, m = 100.0, g = 9.81, vs = 0.01;
  const double a = g * (std::sin(theta) - mu * std::cos(theta));  // 2.356 m/s^2
  // Ramped to 1 m/s over 0.5 s, then accelerating at a; averaged over [2, 3] s (v from 4.5 to 6.9 m/s).
  const Slide r = slide(theta, psi, mu, {{0.0, 0.0}, {0.5, 1.0}, {3.0, 1.0 + 2.5 * a}}, 2.0, 3.0);
  const double a_free = a - r.along / m;  // what the line would do without the holder
  // The law's share: μ F_n / m from the holder's normal force, μ g cos θ (1 - s(v)) <= μ g cos θ v_s² / (2 v²).
  const double v_min = 1.0 + 1.5 * a;
  const double law = mu * std::abs(r.normal) / m + mu * g * std::cos(theta) * vs * vs / (2.0 * v_min * v_min);
  EXPECT_LE(std::abs(a_free - a), law + 1e-4 * a);
  EXPECT_LE(std::abs(r.normal), 1e-3 * m * g);  // the holder hardly carries the line: it slides on the seabed
  std::printf(
      "[ measured ] theta 30 deg, mu 0.3: free acceleration %.9g vs g (sin - mu cos) = %.9g m/s^2 (%.2e; "
      "bound %.2e); holder's normal force %.3g N\n",
      a_free, a, std::abs(a_free / a - 1.0), (law + 1e-4 * a) / a, r.normal);
}

TEST(SpatialSeabedSlope, CreepsOnAGentleIncline) {
  const double theta = 10.0 * kDeg, psi = -60.0 * kDeg, mu = 0.5, m = 100.0, g = 9.81, vs = 0.01;
  const double r = std::tan(theta) / mu, vc = vs * r / std::sqrt(1.0 - r * r);  // 3.77e-3 m/s
  const double W = m * g * std::sin(theta);                                     // the downhill pull
  for (const double factor : {0.0, 1.0, 3.0}) {
    const double v = factor * vc;
    const Slide s = slide(theta, psi, mu, {{0.0, 0.0}, {0.5, v}, {100.0, v}}, 2.0, 3.0);
    const double sv = v / std::hypot(v, vs);
    const double expected = -W + mu * (m * g * std::cos(theta) - s.normal) * sv;  // m a = 0
    EXPECT_NEAR(s.along, expected, 1e-4 * W) << "holder at " << factor << " v_c";
    if (factor == 1.0) {
      EXPECT_LE(std::abs(s.along), 1e-3 * W);  // free, it creeps at v_c
    }
    std::printf(
        "[ measured ] theta 10 deg, mu 0.5, holder at %.0f v_c (v_c = %.4g m/s): its force along the fall line "
        "%.6g N vs the law %.6g N (%.2e of m g sin; m g sin = %.4g N); normal %.3g N\n",
        factor, vc, s.along, expected, std::abs(s.along - expected) / W, W, s.normal);
  }
}

// The steep slide at heading 30 and 100 deg: the second is the first turned by 70 deg about z.
TEST(SpatialSeabedSlope, TurningTheHeadingTurnsTheRun) {
  const double theta = 30.0 * kDeg, mu = 0.3;
  const std::vector<std::pair<double, double>> knots = {{0.0, 0.0}, {0.5, 1.0}, {3.0, 6.0}};
  const std::vector<double> at = {0.5, 1.0, 1.5, 2.0};
  std::vector<AlignedVector<Vec3>> p1, p2;
  slide(theta, 30.0 * kDeg, mu, knots, 2.0, 2.0, at, &p1);
  slide(theta, 100.0 * kDeg, mu, knots, 2.0, 2.0, at, &p2);
  ASSERT_EQ(p1.size(), at.size());
  ASSERT_EQ(p2.size(), at.size());
  const Mat3 R = Eigen::AngleAxisd(70.0 * kDeg, Vec3::UnitZ()).toRotationMatrix();
  double worst = 0.0;
  for (size_t k = 0; k < at.size(); ++k)
    for (size_t i = 0; i < p1[k].size(); ++i) worst = std::max(worst, (R * p1[k][i] - p2[k][i]).norm());
  EXPECT_LE(worst, 1e-9);
  std::printf("[ measured ] slide turned by 70 deg: %.2e m over 2 s (%.3g m travelled)\n", worst,
              (p1.back()[0] - p1.front()[0]).norm());
}

const char* kHanging = R"(space: spatial
line: {length: 60.0, elements: 12, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0, axial_damping: 1.0e4, bending_damping: 100.0}
top: {position: [0.0, 0.0, 0.0]}
seabed: {level: -40.0, stiffness_normal: 2.0e5, damping_normal: 2.0e3, friction_axial: 0.5, friction_lateral: 0.8}
solver: {integrator: midpoint, dt: 0.01}
)";

// 60 m hanging from z = 0 onto a seabed 40 m down at the top's vertical, rising 8 deg towards 30 deg: the line
// hangs and lies down the fall line (towards 210 deg), relaxed from the planar statics on a level seabed.
TEST(SpatialSeabedSlope, HangingOntoTheSlopeStartsAtRest) {
  const Scene s = loadSceneText(kHanging, "hanging", {"seabed.slope=8", "seabed.slope_heading=30"});
  Run3 run(s);
  const InitialState3& init = run.initial();
  EXPECT_TRUE(init.equilibrium);
  EXPECT_LE(init.max_acceleration, init.acceleration_bound);
  EXPECT_NE(init.about.find("sloped seabed"), std::string::npos) << init.about;
  const spatial::Seabed bed(s.seabed, Vec3(0.0, 0.0, -9.81));
  const AlignedVector<Vec3> p0 = run.outputs().points;
  int on = 0;
  for (const Vec3& p : p0) on += bed.penetration(p) > 0.0;
  const Vec3 downhill(-std::cos(30.0 * kDeg), -std::sin(30.0 * kDeg), 0.0);
  const Vec3 reach = p0.back() - p0.front();
  EXPECT_GE(on, 3);  // part of the line lies on the slope
  EXPECT_GT(reach.dot(downhill), 10.0);
  EXPECT_LE(std::abs(reach.dot(Vec3::UnitZ().cross(downhill))), 1e-6);  // in the fall line's vertical plane
  double moved = 0.0;
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(run.step()) << run.divergenceReason();
    const AlignedVector<Vec3>& p = run.outputs().points;
    for (size_t i = 0; i < p.size(); ++i) moved = std::max(moved, (p[i] - p0[i]).norm());
  }
  EXPECT_LE(moved, 1e-6);
  std::printf(
      "[ measured ] hanging onto an 8 deg slope: %s; acceleration at rest %.2e m/s^2 (bound %.2e); %d points "
      "on the slope, end %.3g m downhill; moved %.2e m in 1 s\n",
      init.about.c_str(), init.max_acceleration, init.acceleration_bound, on, reach.dot(downhill), moved);
  // slope 0 (any heading) is the level seabed's run, bit for bit.
  Run3 lvl(loadSceneText(kHanging, "level")),
      zero(loadSceneText(kHanging, "zero", {"seabed.slope=0", "seabed.slope_heading=40"}));
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(lvl.step() && zero.step());
  EXPECT_TRUE(lvl.outputs().points == zero.outputs().points);
}

TEST(SpatialSeabedSlope, KeysRefusedWhereTheyDoNotApplyAndADisplacedEnd) {
  const std::string base = "line: {length: 60.0, elements: 12, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0}\n";
  const auto refused = [&](const std::string& text, const std::string& key) {
    try {
      loadSceneText(base + text, "refused");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused("seabed: {level: -50.0, stiffness_normal: 1.0e5, slope: 5.0}\n", "seabed.slope");
  refused("space: spatial\nseabed: {level: -50.0, stiffness_normal: 1.0e5, slope: 45.0}\n", "seabed.slope");
  refused("space: spatial\nseabed: {level: -50.0, stiffness_normal: 1.0e5, slope: -1.0}\n", "seabed.slope");
  // A planar scene takes slope 0 (the level seabed), whatever the heading.
  EXPECT_NO_THROW(
      loadSceneText(base + "seabed: {level: -50.0, stiffness_normal: 1.0e5, slope: 0.0, slope_heading: 20.0}\n", "ok"));
  // A displaced end on the slope: Newton in 3D with the end held horizontally (a contact's kink is stepped over
  // by backtracking); the builder's rest check with the end force as a dead load, the end where asked, on the
  // slope; at rest the forces on the line less the seabed's (along n) balance in the plane to M a_max.
  const Scene displaced = loadSceneText(base + R"(space: spatial
initial: {type: displaced, end_offset: [20.0, 0.0], end_force: hold}
seabed: {level: -50.0, stiffness_normal: 1.0e5, slope: 5.0}
)",
                                        "displaced");
  Run3 run(displaced);
  const InitialState3& init = run.initial();
  EXPECT_NE(init.about.find("Newton in 3D"), std::string::npos) << init.about;
  EXPECT_LE(init.max_acceleration, init.acceleration_bound);
  const LineOutputs3& o = run.outputs();
  EXPECT_LE((o.points.back().head<2>() - Vec2(20.0, 0.0)).norm(), 1e-9);
  const spatial::Seabed bed(displaced.seabed, Vec3(0.0, 0.0, -9.81));
  EXPECT_GT(bed.penetration(o.points.back()), 0.0);  // the end rests on the slope
  const double M = 80.0 * 60.0;
  const Vec3 sum = -o.top_force + init.end_force + M * Vec3(0.0, 0.0, -9.81), n = bed.normal();
  EXPECT_LE((sum - sum.dot(n) * n).norm(), M * init.max_acceleration + 1e-9 * M * 9.81);
  const AlignedVector<Vec3> p0 = o.points;
  double moved = 0.0;
  for (int k = 0; k < 200; ++k) {
    ASSERT_TRUE(run.step()) << run.divergenceReason();
    for (size_t i = 0; i < p0.size(); ++i) moved = std::max(moved, (run.outputs().points[i] - p0[i]).norm());
  }
  EXPECT_LE(moved, 1e-6);
  std::printf(
      "[ measured ] displaced end on a 5 deg slope: %s; acceleration at rest %.2e m/s^2 (bound %.2e); "
      "forces in the plane %.2e N; moved %.2e m in 0.2 s\n",
      init.about.c_str(), init.max_acceleration, init.acceleration_bound, (sum - sum.dot(n) * n).norm(), moved);
}

// 85 m between the top at z = 0 and an anchor on a seabed 40 m down at the top's vertical, rising 8 deg towards
// 30 deg, 60 m away horizontally downhill, uphill or across the fall line: the planar statics on a level seabed at
// the anchor, relaxed in 3D. At rest the friction is zero, so the forces on the line (the holders', the weight)
// less the seabed's, which is along the normal, sum to at most M a_max (the rest check): their part in the plane
// is that small. Uphill the laid part hangs in tension down the fall line, in the vertical plane; across it, it
// bows downhill out of that plane; downhill its weight pushes it onto the anchor (frictionless at rest, it may
// buckle sideways: not checked).
TEST(SpatialSeabedSlope, PinnedOnTheSlopeStartsAtRest) {
  const double theta = 8.0 * kDeg, psi = 30.0 * kDeg, level = -40.0, span = 60.0, M = 80.0 * 85.0, g = 9.81;
  const Vec3 n = normalOf(theta, psi), uphill(std::cos(psi), std::sin(psi), 0.0);
  const Vec3 across = Vec3::UnitZ().cross(uphill);
  for (const char* where : {"downhill", "uphill", "across"}) {
    const std::string w = where;
    const Vec3 u = w == "downhill" ? Vec3(-uphill) : w == "uphill" ? uphill : across;
    Vec3 anchor = span * u;
    anchor.z() = level + std::tan(theta) * uphill.dot(anchor);
    const Scene s = loadSceneText(R"(space: spatial
line: {length: 85.0, elements: 17, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0, axial_damping: 1.0e4, bending_damping: 100.0}
top: {position: [0.0, 0.0, 0.0]}
bottom: {type: pinned, position: )" + vec(anchor) +
                                      R"(}
initial: {type: between_points}
seabed: {level: -40.0, stiffness_normal: 2.0e5, damping_normal: 2.0e3, friction_axial: 0.5, friction_lateral: 0.8, slope: 8.0, slope_heading: 30.0}
solver: {integrator: midpoint, dt: 0.01}
)",
                                  where);
    Run3 run(s);
    const InitialState3& init = run.initial();
    EXPECT_TRUE(init.equilibrium) << where;
    EXPECT_LE(init.max_acceleration, init.acceleration_bound) << where;
    const spatial::Seabed bed(s.seabed, Vec3(0.0, 0.0, -g));
    const LineOutputs3& o = run.outputs();
    int on = 0;
    double deepest = 0.0, bow = 0.0;
    const Vec3 side = Vec3::UnitZ().cross(u);  // normal to the vertical plane through the top and the anchor
    for (const Vec3& p : o.points) {
      on += bed.penetration(p) > 0.0;
      deepest = std::max(deepest, bed.penetration(p));
      // Off the plane, downhill positive (across) or either way (along the fall line: the problem is planar).
      const double off = w == "across" ? -side.dot(p) * (side.dot(uphill) > 0.0 ? 1.0 : -1.0) : std::abs(side.dot(p));
      // (downhill: printed)
      bow = std::max(bow, off);
    }
    EXPECT_GE(on, 4) << where;
    EXPECT_LE(deepest, 2.0 * 80.0 * 5.0 * g / 2.0e5) << where;  // the sink of at most two segments' weight
    EXPECT_LE((o.points.back() - anchor).norm(), 1e-9) << where;
    const Vec3 sum = -o.top_force - o.bottom_force + M * Vec3(0.0, 0.0, -g);  // all but the seabed's
    const Vec3 in_plane = sum - sum.dot(n) * n;
    EXPECT_LE(in_plane.norm(), M * init.max_acceleration + 1e-9 * M * g) << where;
    EXPECT_GT(-sum.dot(n), 0.05 * M * g) << where;  // the slope carries part of the line
    if (w == "across") {
      EXPECT_GT(bow, 0.5) << "the part on the slope bows downhill";
    } else if (w == "uphill") {
      EXPECT_LE(bow, 1e-6) << "uphill: in the vertical plane";
    }
    double moved = 0.0;
    const AlignedVector<Vec3> p0 = o.points;
    for (int k = 0; k < 100; ++k) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      for (size_t i = 0; i < p0.size(); ++i) moved = std::max(moved, (run.outputs().points[i] - p0[i]).norm());
    }
    EXPECT_LE(moved, 1e-5) << where;
    std::printf(
        "[ measured ] pinned %s on an 8 deg slope: %s; acceleration at rest %.2e m/s^2 (bound %.2e); %d "
        "points on it, deepest %.3g m, bow %.3g m; forces in the plane %.2e N (bound %.2e), on the slope %.4g "
        "N of %.4g; moved %.2e m in 1 s\n",
        where, init.about.c_str(), init.max_acceleration, init.acceleration_bound, on, deepest, bow, in_plane.norm(),
        M * init.max_acceleration + 1e-9 * M * g, -sum.dot(n), M * g, moved);
  }
}

}  // namespace
}  // namespace riser_sim
