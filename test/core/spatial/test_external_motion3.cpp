// ExternalMotion3: each axis is the planar ExternalMotion's (to round-off), bad samples are refused and
// change nothing, reset / shiftSampleTimes, no allocation, and a Run3 driven by it (RunInputs3): its
// top, and a pinned bottom. The attitude on SO(3): through every orientation (pitch through ±90°, turns, a
// tumble), continuous across re-bases; a gap's rejoin in position and attitude; a flex joint through pitch 90°.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "alloc_counter.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/external_motion.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace spatial {
namespace {

// A smooth 3D vessel path: surge and sway circles (8 s) and heave (6 s).
Vec3 path(double t) {
  const double w = 2.0 * M_PI / 8.0, wh = 2.0 * M_PI / 6.0;
  return Vec3(3.0 + 2.0 * std::cos(w * t), -1.0 + 2.0 * std::sin(w * t), -4.0 + 0.7 * std::sin(wh * t));
}

struct Sample {
  double stamp, apply;
};
// Jittery 10 Hz stamps, each applied at the first 1 ms step at or after stamp + latency.
std::vector<Sample> schedule(double t_end, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Sample> s;
  for (int k = 1; k * 0.1 < t_end; ++k) {
    const double stamp = 0.1 * k + 0.03 * (2.0 * u(rng) - 1.0);
    s.push_back({stamp, std::ceil((stamp + 0.02 * u(rng)) / 1e-3) * 1e-3});
  }
  return s;
}

TEST(ExternalMotion3, EachAxisIsThePlanarExternalMotion) {
  ExternalMotionOptions opt;
  opt.fit_window = 0.6;
  ExternalMotion3 m3(path(0.0), 0.0, opt);
  // x and z against ExternalMotion on (x, z); y against one on (y, z): another pairing, same y to round-off.
  ExternalMotion xz(Vec2(path(0.0).x(), path(0.0).z()), 0.0, opt), yz(Vec2(path(0.0).y(), path(0.0).z()), 0.0, opt);
  const std::vector<Sample> samples = schedule(12.0, 3);
  size_t next = 0;
  double worst = 0.0, worst_track = 0.0;
  for (long i = 0; i <= 12000; ++i) {
    const double t = i * 1e-3;
    while (next < samples.size() && samples[next].apply <= t + 1e-12) {
      const Vec3 p = path(samples[next].stamp);
      ASSERT_TRUE(m3.addSample(samples[next].stamp, p, t));
      ASSERT_TRUE(xz.addSample(samples[next].stamp, Vec2(p.x(), p.z()), t));
      ASSERT_TRUE(yz.addSample(samples[next].stamp, Vec2(p.y(), p.z()), t));
      ++next;
    }
    const PointMotion3 m = m3.at(t);
    const PointMotion a = xz.at(t), b = yz.at(t);
    const Vec3 p(a.p.x(), b.p.x(), a.p.y()), v(a.v.x(), b.v.x(), a.v.y()), acc(a.a.x(), b.a.x(), a.a.y());
    worst = std::max(
        {worst, (m.p - p).cwiseAbs().maxCoeff(), (m.v - v).cwiseAbs().maxCoeff(), (m.a - acc).cwiseAbs().maxCoeff()});
    if (t > 1.0) worst_track = std::max(worst_track, (m.p - path(t)).norm());
  }
  EXPECT_LT(worst, 1e-12);  // [m, m/s, m/s^2]: the same arithmetic per axis
  // Tracking of the 10 Hz jittery samples (prediction on; 3 m/s peak): measured 14 mm.
  EXPECT_LT(worst_track, 0.02) << "worst tracking error " << worst_track << " m";
  std::printf("ExternalMotion3: per-axis mismatch %.3g, tracking error %.3g m\n", worst, worst_track);
}

TEST(ExternalMotion3, RefusesBadSamplesChangingNothing) {
  ExternalMotion3 m(Vec3(1, 2, 3), 0.0);
  ASSERT_TRUE(m.addSample(0.1, Vec3(1.1, 2.1, 3.0), 0.1));
  const PointMotion3 before = m.at(0.15);
  const double nan = std::nan("");
  EXPECT_FALSE(m.addSample(0.2, Vec3(1.0, nan, 3.0), 0.12));       // NaN in y only
  EXPECT_FALSE(m.addSample(0.2, Vec3(INFINITY, 2.0, 3.0), 0.12));  // Inf
  EXPECT_FALSE(m.addSample(nan, Vec3(1.0, 2.0, 3.0), 0.12));       // NaN stamp
  EXPECT_FALSE(m.addSample(0.2, Vec3(1.0, 2.0, 3.0), nan));        // NaN time now
  EXPECT_FALSE(m.addSample(0.1, Vec3(5.0, 5.0, 5.0), 0.12));       // repeated stamp
  EXPECT_FALSE(m.addSample(0.05, Vec3(5.0, 5.0, 5.0), 0.12));      // out of order
  EXPECT_EQ(m.sampleCount(), 2);
  EXPECT_EQ(m.position().sampleCount(), 2);
  const PointMotion3 after = m.at(0.15);
  EXPECT_EQ(after.p, before.p);
  EXPECT_EQ(after.v, before.v);
  EXPECT_EQ(after.a, before.a);
  EXPECT_TRUE(m.addSample(0.2, Vec3(1.2, 2.2, 3.0), 0.2));
  EXPECT_THROW(ExternalMotion3(Vec3::Zero(), 0.0,
                               [] {
                                 ExternalMotionOptions o;
                                 o.stop_time = 0.0;
                                 return o;
                               }()),
               std::invalid_argument);
}

TEST(ExternalMotion3, ResetShiftHoldAndNoAllocation) {
  ExternalMotion3 m(Vec3::Zero(), 0.0);
  for (int k = 1; k <= 10; ++k) ASSERT_TRUE(m.addSample(0.1 * k, Vec3(0.1 * k, -0.2 * k, 0.05 * k), 0.1 * k));
  // After the last sample: coast and stop, then hold still.
  const PointMotion3 held = m.at(m.holdTime() + 1.0);
  EXPECT_TRUE(held.v.isZero() && held.a.isZero());
  EXPECT_GT(held.p.x(), 1.0);
  EXPECT_LT(held.p.y(), -2.0);
  m.shiftSampleTimes(0.5);
  EXPECT_NEAR(m.lastSampleTime(), 0.5, 1e-12);
  EXPECT_FALSE(m.addSample(0.45, Vec3::Zero(), 1.1));  // older than the shifted last one
  m.reset(2.0, Vec3(7, 8, 9));
  EXPECT_EQ(m.sampleCount(), 1);
  EXPECT_EQ(m.at(2.5).p, Vec3(7, 8, 9));
  EXPECT_EQ(m.at(0.0).p, Vec3(7, 8, 9));
  const long a0 = g_allocations;
  double sum = 0.0;
  for (int k = 1; k <= 100; ++k) {
    m.addSample(2.0 + 0.01 * k, Vec3(7, 8 + 0.001 * k, 9), 2.0 + 0.01 * k);
    sum += m.at(2.0 + 0.01 * k + 0.005).p.y();
  }
  EXPECT_EQ(g_allocations - a0, 0);
  EXPECT_GT(sum, 0.0);
  // With an attitude (re-based at every sample) and across a gap's rejoin: nothing allocated either.
  ExternalMotion3 r(Vec3::Zero(), Eigen::Quaterniond::Identity(), 0.0);
  const long a1 = g_allocations;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.01 * k + (k > 50 ? 2.0 : 0.0);
    r.addSample(t, Vec3(0.1 * t, 0, 0), Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * t, Vec3::UnitY())), t);
    sum += r.at(t + 0.005).w.y() + r.angularAcceleration(t + 0.005).y();
  }
  EXPECT_EQ(g_allocations - a1, 0);
  EXPECT_EQ(r.gaps().count, 1);
}

// The 3D run built on a given top (the node's way): starts in the statics hanging from that point and
// its top follows the samples.
TEST(ExternalMotion3, DrivesASpatialRun) {
  const Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/test/ros/scenes/small_riser_3d.yaml");
  const Vec3 top(5.0, -3.0, 2.0);
  RunInputs3 in;
  in.top = top;
  auto motion = std::make_unique<ExternalMotion3>(top, 0.0);
  ExternalMotion3* em = motion.get();
  in.motion = std::move(motion);
  Run3 run(scene, std::move(in));
  const LineOutputs3& o0 = run.outputs();
  EXPECT_LT((o0.points.front() - top).norm(), 1e-9);
  // Hanging: the end straight below the top, the force on the hang-off the weight, 1471.5 N, downwards.
  EXPECT_LT((o0.points.back() - (top - Vec3(0, 0, 20.0))).norm(), 1e-6);
  EXPECT_NEAR(o0.top_force.z(), -1471.5, 1.0);
  EXPECT_NEAR(o0.top_force.head<2>().norm(), 0.0, 1e-6);
  // The vessel moves 1 m in +y over 1 s (10 Hz samples); the top follows, the end leaves the x-z plane of the top.
  for (int k = 1; k <= 20; ++k) {
    const double t = 0.1 * k;
    em->addSample(t, top + Vec3(0.0, std::min(t, 1.0), 0.0), run.time());
    while (run.time() < t - 1e-9) ASSERT_TRUE(run.step()) << run.divergenceReason();
  }
  const LineOutputs3& o = run.outputs();
  EXPECT_NEAR(o.points.front().y(), top.y() + 1.0, 0.02);
  EXPECT_NEAR(o.points.front().x(), top.x(), 1e-6);
  EXPECT_GT(o.points.back().y(), top.y() + 0.1);
  EXPECT_TRUE(o.top_force.allFinite());
}

// A pinned bottom driven by a second feed (RunInputs3::bottom_motion, the node's ROV end): the statics end
// at its position, the anchor and the line's end follow its samples, the energy balance holds.
TEST(ExternalMotion3, DrivesAPinnedBottom) {
  Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/test/ros/scenes/tether_3d.yaml");
  scene.bottom_motion.type = MotionKind::kExternal;
  const Vec3 top(8.0, 0.0, 0.0), rov(1.0, -2.0, -14.0);
  RunInputs3 in;
  in.top = top;
  in.motion = std::make_unique<ExternalMotion3>(top, 0.0);
  auto bottom = std::make_shared<ExternalMotion3>(rov, 0.0);
  in.bottom_motion = bottom;
  Run3 run(scene, std::move(in));
  EXPECT_TRUE(run.bottomMoves());
  EXPECT_LT((run.outputs().points.back() - rov).norm(), 1e-6);
  // The ROV moves 1 m in +y over 1 s (10 Hz samples), then holds.
  for (int k = 1; k <= 30; ++k) {
    const double t = 0.1 * k;
    bottom->addSample(t, rov + Vec3(0.0, std::min(t, 1.0), 0.0), run.time());
    while (run.time() < t - 1e-9) ASSERT_TRUE(run.step()) << run.divergenceReason();
  }
  const LineOutputs3& o = run.outputs();
  const Vec3 moved = rov + Vec3(0.0, 1.0, 0.0);
  EXPECT_LT((o.bottom_point - moved).norm(), 0.02);
  EXPECT_LT((o.points.back() - o.bottom_point).norm(), 1e-3);
  EXPECT_LT((o.points.front() - top).norm(), 1e-6);
  EXPECT_TRUE(o.bottom_force.allFinite() && o.bottom_force.norm() > 10.0);
  EXPECT_LT(std::abs(run.energyDrift()), 1e-2);
  // A driven bottom needs a pinned one.
  Scene free_end = scene;
  free_end.bottom = BottomBoundary::kFree;
  free_end.initial.type = InitialKind::kHanging;
  RunInputs3 bad;
  bad.bottom_motion = std::make_shared<ExternalMotion3>(rov, 0.0);
  EXPECT_THROW(Run3(free_end, std::move(bad)), std::invalid_argument);
}

}  // namespace
}  // namespace spatial
}  // namespace riser_sim

namespace riser_sim {
namespace spatial {
namespace {

// A vessel yawing at 0.5 rad/s (through ±π three times in 20 s) while it rolls and pitches; 10 Hz samples of
// its attitude: the smoothed R follows the true one and w its angular velocity, with no jump where the yaw
// wraps; R stays a rotation.
Mat3 attitude(double t) {
  return (Eigen::AngleAxisd(0.5 * t + 2.5, Vec3::UnitZ()) * Eigen::AngleAxisd(0.05 * std::sin(0.8 * t), Vec3::UnitY()) *
          Eigen::AngleAxisd(0.1 * std::sin(1.2 * t), Vec3::UnitX()))
      .toRotationMatrix();
}
Vec3 angularVelocity(double t) {  // ψ' z + θ' Rz y + φ' Rz Ry x
  const Mat3 Rz = Eigen::AngleAxisd(0.5 * t + 2.5, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 Rzy = Rz * Eigen::AngleAxisd(0.05 * std::sin(0.8 * t), Vec3::UnitY()).toRotationMatrix();
  return 0.5 * Vec3::UnitZ() + 0.04 * std::cos(0.8 * t) * Rz.col(1) + 0.12 * std::cos(1.2 * t) * Rzy.col(0);
}

TEST(ExternalMotion3, FollowsTheHoldersAttitude) {
  const Eigen::Quaterniond q0(attitude(0.0));
  ExternalMotion3 m(Vec3(1, 2, 3), q0, 0.0);
  EXPECT_TRUE(m.rotates());
  EXPECT_LT((m.at(0.0).R - attitude(0.0)).norm(), 1e-12);
  double worst_R = 0.0, worst_w = 0.0, worst_orth = 0.0;
  for (int k = 1; k <= 200; ++k) {
    const double t = 0.1 * k;
    ASSERT_TRUE(m.addSample(t, Vec3(1, 2, 3), Eigen::Quaterniond(attitude(t)), t));
    for (double s = t; s < t + 0.1 - 1e-9; s += 0.01) {
      const PointMotion3 p = m.at(s);
      worst_orth = std::max(worst_orth, (p.R.transpose() * p.R - Mat3::Identity()).norm());
      if (s < 2.0) continue;  // after the fit's window has filled
      worst_R = std::max(worst_R, Eigen::AngleAxisd(p.R * attitude(s).transpose()).angle());
      worst_w = std::max(worst_w, (p.w - angularVelocity(s)).norm());
    }
  }
  std::printf("ExternalMotion3 attitude: |R error| <= %.2e rad, |w error| <= %.2e rad/s, |RᵀR - I| <= %.1e\n", worst_R,
              worst_w, worst_orth);
  // The smoothing's lag on a 0.5 rad/s turn with 1.2 rad/s roll: its fit and blend (as on the position's own
  // axes, ExternalMotion). A yaw jump of 2π at the wrap would be an error of ~π.
  EXPECT_LT(worst_R, 2e-3);
  EXPECT_LT(worst_w, 2e-2);
  EXPECT_LT(worst_orth, 1e-13);  // R = R_b Exp(r): a product of two rotations, each orthogonal to round-off
  // Bad attitudes are refused and change nothing.
  const int n = m.sampleCount();
  EXPECT_FALSE(m.addSample(21.0, Vec3(1, 2, 3), Eigen::Quaterniond(0, 0, 0, 0), 21.0));
  EXPECT_FALSE(m.addSample(21.0, Vec3(1, 2, 3), Eigen::Quaterniond(NAN, 0, 0, 1), 21.0));
  EXPECT_EQ(m.sampleCount(), n);
  // Without an attitude: R = I, w = 0.
  ExternalMotion3 plain(Vec3(1, 2, 3), 0.0);
  EXPECT_FALSE(plain.rotates());
  EXPECT_TRUE(plain.at(1.0).R.isIdentity() && plain.at(1.0).w.isZero());
}

// A Run3 on a rotating ExternalMotion3 (the node's): its top flex joint turns with the vessel; on one
// without an attitude, the joint's axis is fixed in the world.
TEST(ExternalMotion3, TurnsTheTopFlexJoint) {
  Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/test/ros/scenes/small_riser_3d.yaml");
  scene.top_flex_joint.enabled = true;
  scene.top_flex_joint.stiffness = 1e4;
  const Vec3 top(0.0, 0.0, 0.0);
  const Eigen::Quaterniond yawed(Eigen::AngleAxisd(0.7, Vec3::UnitZ()) * Eigen::AngleAxisd(0.1, Vec3::UnitX()));
  for (bool turning : {true, false}) {
    RunInputs3 in;
    in.top = top;
    auto motion =
        turning ? std::make_unique<ExternalMotion3>(top, yawed, 0.0) : std::make_unique<ExternalMotion3>(top, 0.0);
    ExternalMotion3* em = motion.get();
    in.motion = std::move(motion);
    Run3 run(scene, std::move(in));
    ASSERT_NE(run.topFlexJoint(), nullptr);
    EXPECT_EQ(run.topFlexJoint()->turnsWithHolder(), turning);
    // The vessel rolls 0.2 rad more over 1 s: a joint that turns with it is loaded; one fixed in the world is not.
    const Eigen::Quaterniond rolled(Eigen::AngleAxisd(0.7, Vec3::UnitZ()) * Eigen::AngleAxisd(0.3, Vec3::UnitX()));
    for (int k = 1; k <= 10; ++k)
      em->addSample(0.1 * k, top, k == 10 ? rolled : yawed.slerp(0.1 * k, rolled), run.time());
    const Vec3 d0 = run.topFlexJoint()->axis(0.0).d;
    EXPECT_LT((d0 - Vec3(0, 0, -1)).norm(), 1e-9);  // unloaded along the hanging line at the start
    const Vec3 d = run.topFlexJoint()->axis(5.0).d;
    const Vec3 expected = turning ? Vec3(em->at(5.0).R * em->at(0.0).R.transpose() * d0) : d0;
    EXPECT_LT((d - expected).norm(), 1e-12) << (turning ? "turning" : "fixed");
    if (turning) {  // held near the last sample's roll: past it by the coast at 0.2 rad/s (coast_time 0.2 s, then
                    // stop_time 0.5 s of decay: ~0.09 rad); the axis turned with it
      const double past = Eigen::AngleAxisd(em->at(5.0).R * rolled.toRotationMatrix().transpose()).angle();
      EXPECT_LT(past, 0.12);
      EXPECT_NEAR(std::acos(d.dot(d0)), 0.2 + past, 0.02);
    }
  }
}

// A driven bottom with a flex joint (the ROV's end of a tether): on an ExternalMotion3 with the ROV's attitude
// the bottom joint turns with the ROV, and the ROV's yaw of 0.5 rad turns its axis by that yaw.
TEST(ExternalMotion3, TurnsTheBottomFlexJointWithTheRov) {
  Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/test/ros/scenes/tether_3d.yaml");
  scene.bottom_motion.type = MotionKind::kExternal;
  scene.bottom_flex_joint.enabled = true;
  scene.bottom_flex_joint.stiffness = 5e3;
  const Vec3 top(8.0, 0.0, 0.0), rov(1.0, -2.0, -14.0);
  RunInputs3 in;
  in.top = top;
  in.motion = std::make_unique<ExternalMotion3>(top, 0.0);
  auto bottom = std::make_shared<ExternalMotion3>(rov, Eigen::Quaterniond::Identity(), 0.0);
  in.bottom_motion = bottom;
  Run3 run(scene, std::move(in));
  ASSERT_NE(run.bottomFlexJoint(), nullptr);
  EXPECT_TRUE(run.bottomFlexJoint()->turnsWithHolder());
  EXPECT_FALSE(run.topFlexJoint() && run.topFlexJoint()->turnsWithHolder());
  const Vec3 d0 = run.bottomFlexJoint()->axis(0.0).d;
  for (int k = 1; k <= 20; ++k) {  // yaw 0.5 rad over 1 s, then held
    const double t = 0.1 * k;
    bottom->addSample(t, rov, Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * std::min(t, 1.0), Vec3::UnitZ())), run.time());
    while (run.time() < t - 1e-9) ASSERT_TRUE(run.step()) << run.divergenceReason();
  }
  const Vec3 d = run.bottomFlexJoint()->axis(run.time()).d;
  const Vec3 expected = Eigen::AngleAxisd(0.5, Vec3::UnitZ()) * d0;
  // The smoothed yaw at 2 s, 1 s after the last change: within the blend's settling of the held value.
  EXPECT_LT((d - expected).norm(), 1e-3 * d0.head<2>().norm() + 1e-12);
  EXPECT_GT((d - d0).norm(), 0.4 * d0.head<2>().norm());  // it did turn (the axis is off the vertical)
  EXPECT_TRUE(run.outputs().bottom_moment.allFinite());
}

}  // namespace
}  // namespace spatial
}  // namespace riser_sim

namespace riser_sim {
namespace spatial {
namespace {

Vec3 vee(const Mat3& S) { return 0.5 * Vec3(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1)); }

// A holder turning through every attitude, sampled at `hz` with ±30 % stamp jitter and up to 10 ms latency,
// each sample applied at the first 1 ms step after it arrives; at() recorded on that grid.
struct AttitudeTrace {
  double err_R = 0.0, err_w = 0.0, fd_R = 0.0, fd_w = 0.0, max_dw = 0.0, max_rate = 0.0, jump = 0.0;
};
template <class Attitude>
AttitudeTrace followAttitude(Attitude truth, double hz, double t_end, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto rate = [&](double t) {  // w = vee(Ṙ Rᵀ), central differences (1e-9 rad/s)
    const double h = 1e-5;
    return vee((truth(t + h) - truth(t - h)) / (2.0 * h) * truth(t).transpose());
  };
  ExternalMotion3 m(Vec3::Zero(), Eigen::Quaterniond(truth(0.0)), 0.0);
  AttitudeTrace tr;
  const double period = 1.0 / hz;
  int k = 1;
  double stamp = period * (1.0 + 0.3 * (2.0 * u(rng) - 1.0)), arrive = stamp + 0.01 * u(rng);
  PointMotion3 prev;
  Vec3 prev_alpha = Vec3::Zero();
  const double h = 1e-3;
  for (long i = 0; i * h <= t_end; ++i) {
    const double t = i * h;
    while (arrive <= t) {
      const PointMotion3 before = m.at(t);
      const Vec3 alpha_before = m.angularAcceleration(t);
      EXPECT_TRUE(m.addSample(stamp, Vec3::Zero(), Eigen::Quaterniond(truth(stamp)), t));
      // The new blend starts from the re-based state: R, w and the angular acceleration unchanged.
      const PointMotion3 after = m.at(t);
      tr.jump = std::max({tr.jump, (after.R - before.R).norm(), (after.w - before.w).norm(),
                          (m.angularAcceleration(t) - alpha_before).norm()});
      ++k;
      stamp = period * (k + 0.3 * (2.0 * u(rng) - 1.0));
      arrive = stamp + 0.01 * u(rng);
    }
    const PointMotion3 p = m.at(t);
    const Vec3 alpha = m.angularAcceleration(t);
    if (t > 1.5) {  // the fit's window filled, the start's catch-up (0 to |w| within min_blend) over
      // R against w, w against the angular acceleration: O(h²) for smooth pieces, half of any jump.
      tr.fd_R = std::max(tr.fd_R, (Eigen::AngleAxisd(p.R * prev.R.transpose()).angle() *
                                       Eigen::AngleAxisd(p.R * prev.R.transpose()).axis() / h -
                                   0.5 * (p.w + prev.w))
                                      .norm());
      tr.fd_w = std::max(tr.fd_w, ((p.w - prev.w) / h - 0.5 * (alpha + prev_alpha)).norm());
      tr.max_dw = std::max(tr.max_dw, (p.w - prev.w).norm());
    }
    if (t > 1.5) {
      tr.err_R = std::max(tr.err_R, Eigen::AngleAxisd(p.R * truth(t).transpose()).angle());
      tr.err_w = std::max(tr.err_w, (p.w - rate(t)).norm());
      tr.max_rate = std::max(tr.max_rate, rate(t).norm());
    }
    prev = p;
    prev_alpha = alpha;
  }
  return tr;
}

// Pitch through ±90° (a full loop about the pitch axis), yaw through several turns, and a tumble about a tilted
// axis at a constant rate, at 10, 25 and 50 Hz with jitter: R follows within a tenth of what one blend of lag
// would cost (|w| T, T = max(period, min_blend) = 0.1 s) — the prediction removes the lag as for the position —
// w within a tenth of the rate, and no jump: w consistent with R, and the angular acceleration with w, to O(h²)
// on the 1 ms grid (a jump of J in w would show as J / (2h)), at every re-base included.
TEST(ExternalMotion3, AttitudeThroughEveryOrientation) {
  const Vec3 n = Vec3(1.0, 2.0, 0.5).normalized();
  const auto pitch = [](double t) {
    return Mat3((Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.8 * t, Vec3::UnitY()) *
                 Eigen::AngleAxisd(0.2 + 0.1 * std::sin(t), Vec3::UnitX()))
                    .toRotationMatrix());
  };
  const auto yaw = [](double t) {
    return Mat3((Eigen::AngleAxisd(1.5 * t, Vec3::UnitZ()) * Eigen::AngleAxisd(0.3 * std::sin(t), Vec3::UnitY()))
                    .toRotationMatrix());
  };
  const auto tumble = [n](double t) {
    return Mat3((Eigen::AngleAxisd(1.2 * t, n) * Eigen::AngleAxisd(0.7, Vec3::UnitX())).toRotationMatrix());
  };
  int seed = 1;
  for (double hz : {10.0, 25.0, 50.0}) {
    const AttitudeTrace a = followAttitude(pitch, hz, 12.0, seed++);  // pitch 9.6 rad: 1.5 loops
    const AttitudeTrace b = followAttitude(yaw, hz, 20.0, seed++);    // yaw 30 rad: 4.8 turns
    const AttitudeTrace c = followAttitude(tumble, hz, 12.0, seed++);
    for (const auto& [name, e] : {std::pair<const char*, AttitudeTrace>{"pitch", a}, {"yaw", b}, {"tumble", c}}) {
      std::printf(
          "[ measured ] %s at %.0f Hz: |R error| %.2e rad, |w error| %.2e rad/s (|w| <= %.2f), fd R-w %.1e, "
          "fd w-alpha %.1e, max |dw| per ms %.1e rad/s, jump at a sample %.1e\n",
          name, hz, e.err_R, e.err_w, e.max_rate, e.fd_R, e.fd_w, e.max_dw, e.jump);
      EXPECT_LT(e.err_R, 0.1 * e.max_rate * 0.1) << name << " " << hz;
      EXPECT_LT(e.err_w, 0.1 * e.max_rate) << name << " " << hz;
      EXPECT_LT(e.jump, 1e-9) << name << " " << hz;  // round-off of the re-base
      // O(h²/12 |d²w/dt²|) (the 10 Hz blends' jerk: hundreds of rad/s³); a jump of J rad in R would show as J / h.
      EXPECT_LT(e.fd_R, 1e-4) << name << " " << hz;  // [rad/s]
      // O(h |jump of the angular jerk at a blend's start| / 8): tens of rad/s³ at 10 Hz, which is no jump in
      // the angular acceleration (that is `jump` above); a jump of J rad/s in w would show as J / h.
      EXPECT_LT(e.fd_w, 0.05) << name << " " << hz;    // [rad/s²]
      EXPECT_LT(e.max_dw, 1e-2) << name << " " << hz;  // [rad/s] per 1 ms: |alpha| < 10 rad/s²
    }
  }
}

}  // namespace
}  // namespace spatial
}  // namespace riser_sim

namespace riser_sim {
namespace spatial {
namespace {

// A 3D holder at 0.37 m/s turning at 0.3 rad/s about z, 20 Hz samples, silent for 3 s: the position's acceleration
// stays within rejoin_max_acceleration, the angular acceleration within rejoin_max_angular_acceleration (the bound
// is on r̈; α = R_b (J̇_l ṙ + J_l r̈) adds O(|r| |ṙ|, |r| |r̈|) for the r ~ 1 rad the gap leaves: 10 %), R, w, p,
// v continuous, and both rejoin their source.
TEST(ExternalMotion3, GapRejoinsPositionAndAttitude) {
  const Vec3 vel(0.3, -0.2, 0.1);
  const auto R = [](double t) {
    return Mat3((Eigen::AngleAxisd(0.3 * t, Vec3::UnitZ()) * Eigen::AngleAxisd(0.4, Vec3::UnitX())).toRotationMatrix());
  };
  const ExternalMotionOptions o;
  ExternalMotion3 m(Vec3::Zero(), Eigen::Quaterniond(R(0.0)), 0.0, o);
  double peak_a = 0.0, peak_alpha = 0.0, jump = 0.0, err_after = 0.0;
  const double h = 1e-3;
  PointMotion3 prev = m.at(0.0);
  for (long i = 1; i * h <= 30.0; ++i) {
    const double t = i * h;
    if (i % 50 == 0 && (t < 4.0 || t > 7.0)) {
      const PointMotion3 before = m.at(t);
      ASSERT_TRUE(m.addSample(t, vel * t, Eigen::Quaterniond(R(t)), t));
      const PointMotion3 after = m.at(t);
      jump = std::max({jump, (after.p - before.p).norm(), (after.v - before.v).norm(), (after.a - before.a).norm(),
                       (after.R - before.R).norm(), (after.w - before.w).norm()});
    }
    const PointMotion3 p = m.at(t);
    // No jump between 1 ms steps once the start's catch-up is over: |Δv| <= h |a|max, |Δw| likewise.
    if (t > 1.0) jump = std::max(jump, std::max((p.v - prev.v).norm(), (p.w - prev.w).norm()) - h * 0.6);
    prev = p;
    if (t > 3.9) {
      peak_a = std::max(peak_a, p.a.norm());
      peak_alpha = std::max(peak_alpha, m.angularAcceleration(t).norm());
    }
    if (t > 7.1 && t > m.gaps().rejoin_end + 1.0)  // the first sample after the gap came at 7.05 s
      err_after = std::max({err_after, (p.p - vel * t).norm(), Eigen::AngleAxisd(p.R * R(t).transpose()).angle(),
                            (p.w - 0.3 * Vec3::UnitZ()).norm()});
  }
  std::printf(
      "[ measured ] 3D gap of 3 s: peak |a| %.3f m/s^2, |alpha| %.3f rad/s^2, rejoin until t = %.2f s, then "
      "error %.1e; largest jump %.1e\n",
      peak_a, peak_alpha, m.gaps().rejoin_end, err_after, jump);
  EXPECT_EQ(m.gaps().count, 1);
  EXPECT_NEAR(m.gaps().last, 3.1, 1e-9);  // samples at 3.95 and 7.05 s
  EXPECT_LE(peak_a, 1.01 * o.rejoin_max_acceleration);
  EXPECT_LE(peak_alpha, 1.1 * o.rejoin_max_angular_acceleration);
  EXPECT_LT(jump, 1e-9);
  EXPECT_LT(err_after, 1e-6);
  EXPECT_LT(m.gaps().rejoin_end, 20.0);
}

// A flex joint on an ROV that pitches from level to 137° (through straight down, 90°) and back to rest, its
// attitude sampled at 20 Hz: the joint's moment follows smoothly. Between consecutive 2 ms outputs it changes by
// at most what the spring's rate at the pitch's peak rate allows twice over, 2 k ω_max dt (= 50 N m here; the line's
// own swing included), where the Z-Y-X smoothing jumped by thousands of N m at 90°.
TEST(ExternalMotion3, FlexJointMomentSmoothThroughPitchNinety) {
  Scene scene = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/spatial_tether.yaml");
  scene.bottom_motion.type = MotionKind::kExternal;
  const Vec3 top(0.0, 0.0, 0.0), rov(12.0, 0.0, -25.0);
  const double k = scene.bottom_flex_joint.stiffness, theta_max = 2.4, Tp = 6.0;
  const auto pitch = [&](double t) { return t >= Tp ? theta_max : 0.5 * theta_max * (1.0 - std::cos(M_PI * t / Tp)); };
  const double w_max = 0.5 * theta_max * M_PI / Tp;
  RunInputs3 in;
  in.top = top;
  in.motion = std::make_unique<ExternalMotion3>(top, 0.0);
  auto bottom = std::make_shared<ExternalMotion3>(rov, Eigen::Quaterniond::Identity(), 0.0);
  in.bottom_motion = bottom;
  Run3 run(scene, std::move(in));
  ASSERT_NE(run.bottomFlexJoint(), nullptr);
  Vec3 prev = run.outputs().bottom_moment;
  double max_step = 0.0, at_90 = 0.0, peak = 0.0;
  for (int s = 1; s <= 160; ++s) {  // 8 s at 20 Hz
    const double t = 0.05 * s;
    bottom->addSample(t, rov, Eigen::Quaterniond(Eigen::AngleAxisd(pitch(t), Vec3::UnitY())), run.time());
    while (run.time() < t - 1e-9) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      const Vec3 M = run.outputs().bottom_moment;
      max_step = std::max(max_step, (M - prev).norm());
      peak = std::max(peak, M.norm());
      if (std::abs(pitch(run.time()) - M_PI / 2) < 0.01) at_90 = M.norm();
      prev = M;
    }
  }
  const double bound = 2.0 * k * w_max * scene.solver.dt;
  std::printf(
      "[ measured ] ROV pitching through 90 deg: bottom joint moment %.0f N m at 90 deg, peak %.0f N m; largest "
      "change between 2 ms outputs %.2f N m (bound 2 k w dt = %.1f)\n",
      at_90, peak, max_step, bound);
  EXPECT_LT(max_step, bound);
  EXPECT_GT(peak, 1000.0);  // the joint is loaded: the pitch turns its axis away from the line
}

}  // namespace
}  // namespace spatial
}  // namespace riser_sim
