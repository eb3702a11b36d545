// ExternalMotion: C2 continuity across sample arrivals, lag and tracking error for a jittery sampled
// sinusoid, hold on timeout, rejection of bad samples, no allocation.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "riser_sim/motion/external_motion.h"

// Counts heap allocations while g_count_allocs is set (to prove at() / addSample() allocate nothing).
static std::atomic<bool> g_count_allocs{false};
static std::atomic<long> g_allocs{0};
void* operator new(std::size_t n) {
  if (g_count_allocs) ++g_allocs;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace riser_sim {
namespace {

// Vessel heave/surge used throughout: amplitude 2 m, period 8 s (a typical wave period).
constexpr double kAmp = 2.0;
constexpr double kOmega = 2.0 * M_PI / 8.0;
Vec2 truth(double t) { return Vec2(kAmp * std::sin(kOmega * t), -5.0 + 0.5 * kAmp * std::cos(kOmega * t)); }

struct Trace {
  std::vector<double> t;
  std::vector<PointMotion> m;
  std::vector<double> arrivals;  // times at which samples were applied
};

// Samples truth() at nominal rate `hz` with stamp jitter ±jitter·period, position noise, and delivery
// latency in [0, max_latency]; applies each at the first grid time >= its arrival, like the node does
// at step boundaries. Records at() on the grid of step h.
Trace run(ExternalMotion& em, double hz, double jitter, double noise, double max_latency, double t_end, double h,
          unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double period = 1.0 / hz;
  struct S {
    double stamp, arrive;
    Vec2 p;
  };
  std::vector<S> samples;
  for (int k = 1; k * period < t_end; ++k) {
    const double stamp = k * period + jitter * period * u(rng);
    const Vec2 p = truth(stamp) + noise * Vec2(gauss(rng), gauss(rng));
    samples.push_back({stamp, stamp + max_latency * 0.5 * (1.0 + u(rng)), p});
  }
  Trace tr;
  size_t next = 0;
  const long steps = std::lround(t_end / h);
  for (long i = 0; i <= steps; ++i) {
    const double t = i * h;
    while (next < samples.size() && samples[next].arrive <= t) {
      em.addSample(samples[next].stamp, samples[next].p, t);
      tr.arrivals.push_back(t);
      ++next;
    }
    tr.t.push_back(t);
    tr.m.push_back(em.at(t));
  }
  return tr;
}

// Largest mismatch between a finite difference of f and the trapezoid mean of its derivative g:
// O(h²·f''') for a C¹ pair, but at least |jump of g| / 2 where g jumps.
template <class F, class G>
double fdMismatch(const Trace& tr, F f, G g) {
  double worst = 0.0;
  for (size_t i = 0; i + 1 < tr.t.size(); ++i) {
    const double h = tr.t[i + 1] - tr.t[i];
    const Vec2 fd = (f(tr.m[i + 1]) - f(tr.m[i])) / h;
    const Vec2 mean = 0.5 * (g(tr.m[i]) + g(tr.m[i + 1]));
    worst = std::max(worst, (fd - mean).cwiseAbs().maxCoeff());
  }
  return worst;
}

ExternalMotion startAtTruth() { return ExternalMotion(truth(0.0), 0.0); }

TEST(ExternalMotion, ContinuousPositionVelocityAccelerationAcrossArrivals) {
  for (double hz : {10.0, 100.0}) {
    ExternalMotion em = startAtTruth();
    const double h = 1e-5;  // small enough that the start-up transient's O(h²) term stays < 1e-4
    const Trace tr = run(em, hz, 0.3, 0.0, 0.01, 3.0, h);
    ASSERT_GT(tr.arrivals.size(), 25u);
    // Smooth pieces give O(h²) mismatches (< 1e-4 here); a jump of size J would give >= J/2.
    const double tol_v = 1e-4;  // [m/s]: any velocity jump > 2e-4 m/s would fail
    const double tol_a = 1e-3;  // [m/s²]: any acceleration jump > 2e-3 m/s² would fail
    EXPECT_LT(fdMismatch(
                  tr, [](const PointMotion& m) { return m.p; }, [](const PointMotion& m) { return m.v; }),
              tol_v)
        << hz << " Hz";
    EXPECT_LT(fdMismatch(
                  tr, [](const PointMotion& m) { return m.v; }, [](const PointMotion& m) { return m.a; }),
              tol_a)
        << hz << " Hz";
  }
}

TEST(ExternalMotion, NewSegmentStartsExactlyFromCurrentState) {
  ExternalMotion em = startAtTruth();
  double t = 0.0;
  for (int k = 1; k < 40; ++k) {
    t += 0.1;
    const PointMotion before = em.at(t);
    ASSERT_TRUE(em.addSample(t - 0.003, truth(t - 0.003), t));
    const PointMotion after = em.at(t);
    // Round-off only: the new quintic's coefficients are the old state (1e-12 relative).
    EXPECT_LT((after.p - before.p).norm(), 1e-12);
    EXPECT_LT((after.v - before.v).norm(), 1e-11);
    EXPECT_LT((after.a - before.a).norm(), 1e-10);
  }
}

// Lag τ that best aligns the motion with the truth: argmin over τ of the RMS of p(t) - truth(t - τ).
double bestLag(const Trace& tr, double t_from) {
  double best_tau = 0.0, best = 1e300;
  for (double tau = -0.2; tau <= 0.4; tau += 1e-3) {
    double s = 0.0;
    for (size_t i = 0; i < tr.t.size(); ++i)
      if (tr.t[i] >= t_from) s += (tr.m[i].p - truth(tr.t[i] - tau)).squaredNorm();
    if (s < best) best = s, best_tau = tau;
  }
  return best_tau;
}

double maxError(const Trace& tr, double t_from) {
  double e = 0.0;
  for (size_t i = 0; i < tr.t.size(); ++i)
    if (tr.t[i] >= t_from) e = std::max(e, (tr.m[i].p - truth(tr.t[i])).norm());
  return e;
}

TEST(ExternalMotion, LagAtMostOnePeriodFor10HzJitterySinusoid) {
  const double period = 0.1;
  const double warmup = 1.0;  // fit window 0.5 s filled twice
  ExternalMotion em = startAtTruth();
  const Trace tr = run(em, 10.0, 0.3, 0.0, 0.02, 12.0, 1e-3);
  const double lag = bestLag(tr, warmup);
  EXPECT_LE(lag, period);
  EXPECT_GE(lag, -period);
  // Predicting to the blend end removes the systematic lag: measured |τ| ~ 1 ms.
  EXPECT_LT(std::abs(lag), 0.01);
  // Without prediction the lag is the blend time plus the mean latency (0.1 + 0.01 s).
  ExternalMotionOptions o;
  o.predict = false;
  ExternalMotion slow(truth(0.0), 0.0, o);
  const Trace tr2 = run(slow, 10.0, 0.3, 0.0, 0.02, 12.0, 1e-3);
  EXPECT_NEAR(bestLag(tr2, warmup), period + 0.01, 0.02);
}

TEST(ExternalMotion, TrackingErrorBound) {
  // One period of lag would give an error up to A ω T = 0.157 m; the prediction error is second order,
  // ~ ½ A ω² (T + latency)² ≈ 0.009 m, plus the fit's bias. Bound: a tenth of the one-period-lag error.
  const double lag_error = kAmp * kOmega * 0.1;
  ExternalMotion em = startAtTruth();
  const Trace tr = run(em, 10.0, 0.3, 0.0, 0.02, 12.0, 1e-3);
  EXPECT_LT(maxError(tr, 1.0), 0.1 * lag_error);
  // At 100 Hz the error is far smaller still.
  ExternalMotion fast = startAtTruth();
  const Trace tr2 = run(fast, 100.0, 0.3, 0.0, 0.005, 6.0, 1e-3);
  EXPECT_LT(maxError(tr2, 1.0), 0.01 * lag_error);
}

TEST(ExternalMotion, NoisySamplesGiveBoundedAcceleration) {
  // 100 Hz poses with 1 mm noise: the fit and the minimum blend time keep A_0's acceleration within a
  // few times the true peak (A ω² = 1.23 m/s²) instead of amplifying the noise by 1/T² (~600 m/s²).
  ExternalMotion em = startAtTruth();
  const Trace tr = run(em, 100.0, 0.3, 1e-3, 0.005, 8.0, 1e-3);
  double amax = 0.0;
  for (size_t i = 0; i < tr.t.size(); ++i)
    if (tr.t[i] > 1.0) amax = std::max(amax, tr.m[i].a.norm());
  EXPECT_LT(amax, 4.0 * kAmp * kOmega * kOmega);  // measured 2.7 m/s² (seed 1)
  EXPECT_LT(maxError(tr, 1.0), 0.01);             // [m]: noise 1 mm, bias of the prediction small
}

TEST(ExternalMotion, HoldsStillAfterTimeout) {
  // The stop takes stop_time when its deceleration 1.5 |v| / stop_time is within rejoin_max_acceleration (here
  // raised; the bounded stop: GapsRejoinWithBoundedAccelerationAndSpeed).
  ExternalMotionOptions opt;
  opt.rejoin_max_acceleration = 100.0;
  ExternalMotion em(truth(0.0), 0.0, opt);
  run(em, 20.0, 0.2, 0.0, 0.005, 3.0, 1e-3);  // last sample applied just before t = 3 s
  const double t_hold = em.holdTime();
  const ExternalMotionOptions& o = em.options();
  EXPECT_LE(t_hold, 3.0 + em.blendTime() + o.coast_time + o.stop_time + 1e-9);
  const PointMotion h1 = em.at(t_hold), h2 = em.at(t_hold + 100.0);
  EXPECT_EQ(h1.v.norm(), 0.0);
  EXPECT_EQ(h1.a.norm(), 0.0);
  EXPECT_EQ((h2.p - h1.p).norm(), 0.0);
  // The stop continues smoothly and the speed falls monotonically during the decay.
  const double t_stop = t_hold - o.stop_time;
  double prev = em.at(t_stop).v.norm();
  for (double t = t_stop; t <= t_hold; t += 1e-3) {
    const double s = em.at(t).v.norm();
    EXPECT_LE(s, prev + 1e-12);
    prev = s;
  }
  // The held point stays near the vessel's last position: at most its speed times the bounded
  // extrapolation (blend + coast + half the stop) away.
  const double vmax = kAmp * kOmega * 1.2;
  EXPECT_LT((h1.p - truth(3.0)).norm(), vmax * (em.blendTime() + o.coast_time + 0.5 * o.stop_time) + 0.05);
}

TEST(ExternalMotion, RejectsBadSamplesWithoutChange) {
  ExternalMotion em(Vec2(1.0, -2.0), 0.0);
  ASSERT_TRUE(em.addSample(0.1, Vec2(1.1, -2.0), 0.1));
  const PointMotion ref = em.at(0.15);
  const double nan = std::nan("");
  EXPECT_FALSE(em.addSample(0.2, Vec2(nan, 0.0), 0.12));
  EXPECT_FALSE(em.addSample(0.2, Vec2(1.0, INFINITY), 0.12));
  EXPECT_FALSE(em.addSample(nan, Vec2(1.0, 0.0), 0.12));
  EXPECT_FALSE(em.addSample(0.1, Vec2(5.0, 0.0), 0.12));   // duplicate stamp
  EXPECT_FALSE(em.addSample(0.05, Vec2(5.0, 0.0), 0.12));  // out of order
  EXPECT_EQ(em.sampleCount(), 2);
  const PointMotion now = em.at(0.15);
  EXPECT_EQ((now.p - ref.p).norm(), 0.0);
  EXPECT_EQ((now.v - ref.v).norm(), 0.0);
}

TEST(ExternalMotion, ShiftedSampleTimesKeepTheVelocityEstimate) {
  // Constant velocity 1 m/s along x; after the clock is re-mapped by 0.5 s the estimate is unchanged.
  ExternalMotion em(Vec2::Zero(), 0.0);
  double t = 0.0;
  for (int k = 1; k <= 10; ++k) {
    t = 0.1 * k;
    em.addSample(t, Vec2(t, 0.0), t);
  }
  em.shiftSampleTimes(0.5);
  const double t_now = t + 0.1;                        // integration time (not re-mapped)
  em.addSample(t_now - 0.5, Vec2(t_now, 0.0), t_now);  // stamp in the new mapping
  const PointMotion end = em.at(t_now + em.blendTime());
  EXPECT_NEAR(end.v.x(), 1.0, 1e-9);
}

TEST(ExternalMotion, AllocatesNothing) {
  ExternalMotion em = startAtTruth();
  g_allocs = 0;
  g_count_allocs = true;
  double sum = 0.0;
  for (int k = 1; k < 200; ++k) {
    const double t = 0.01 * k;
    em.addSample(t, truth(t), t);
    for (int j = 0; j < 10; ++j) sum += em.at(t + 1e-3 * j).a.x();
  }
  g_count_allocs = false;
  EXPECT_EQ(g_allocs.load(), 0);
  EXPECT_TRUE(std::isfinite(sum));
}

// Started at rest against a source already moving at v = 2 m/s (50 Hz samples from t = 0): without a start
// blend the top catches up within min_blend, with a jolt of ~v/min_blend; with start_blend = 2 s one quintic from
// rest to the source's state at t = 2 s (peak 3.94 v/T: p = vT(6τ³ - 8τ⁴ + 3τ⁵)), and from then on it tracks the
// source: to 1e-4 m as the last blends of the window hand over to the usual ones, then exactly (a linear
// motion is fitted and predicted without error).
TEST(ExternalMotion, StartBlendSpreadsTheCatchUp) {
  const double v = 2.0, T = 2.0;
  double peak[2] = {0.0, 0.0}, handover = 0.0, after = 0.0;
  for (int on = 0; on < 2; ++on) {
    ExternalMotionOptions o;
    o.start_blend = on ? T : 0.0;
    ExternalMotion em(Vec2::Zero(), 0.0, o);
    for (int k = 1; k <= 200; ++k) {  // 4 s
      const double t = 0.02 * k;
      for (int j = 0; j < 20; ++j) peak[on] = std::max(peak[on], em.at(t - 0.02 + 1e-3 * j).a.norm());
      em.addSample(t, Vec2(v * t, 0.0), t);
      const double gap = std::abs(em.at(t).p.x() - v * t);
      if (on && t >= T) (t < T + 0.5 ? handover : after) = std::max(t < T + 0.5 ? handover : after, gap);
    }
  }
  std::printf(
      "[ measured ] start against a source at 2 m/s: peak |a| %.3g m/s^2 without a start blend, %.3g with "
      "2 s (3.94 v/T = %.3g); |p - source| %.1e m in the 0.5 s after it, %.1e later\n",
      peak[0], peak[1], 3.94 * v / T, handover, after);
  EXPECT_LE(peak[1], 1.1 * 3.94 * v / T);  // one quintic, the first samples' fit aside
  EXPECT_GT(peak[0], 5.0 * peak[1]);
  EXPECT_LE(handover, 1e-4);
  EXPECT_LE(after, 1e-9);
  ExternalMotionOptions bad;
  bad.start_blend = -1.0;
  EXPECT_EQ(bad.validate().rfind("start_blend", 0), 0u);
}

// A source at constant velocity `vel` (displaced by `jump` during the gap), 20 Hz samples with ±0.01 s stamp
// jitter, each applied at the first 1 ms step after its stamp plus up to 5 ms of latency; silent for `gap` s from
// t = 4 s. Records at() on the 1 ms grid from t = 1 s (the start's catch-up over).
struct GapTrace {
  std::vector<double> t;
  std::vector<PointMotion> m;
  double t_return = 0.0;  // when the first sample after the gap was applied [s]
  MotionGaps gaps;
};
GapTrace runGap(double gap, const Vec2& vel, const Vec2& jump, const ExternalMotionOptions& o, double t_end) {
  const Vec2 p0(3.0, -20.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ExternalMotion em(p0, 0.0, o);
  GapTrace tr;
  double stamp = 0.05 + 0.01 * (2.0 * u(rng) - 1.0), apply = stamp + 0.005 * u(rng);
  int k = 1;
  const long steps = std::lround(t_end / 1e-3);
  for (long i = 0; i <= steps; ++i) {
    const double t = i * 1e-3;
    while (apply <= t) {
      const bool after = stamp > 4.0 + gap;
      if (stamp < 4.0 || after) {
        if (after && tr.t_return == 0.0) tr.t_return = t;
        EXPECT_TRUE(em.addSample(stamp, p0 + vel * stamp + (after ? jump : Vec2::Zero()), t));
      }
      ++k;
      stamp = 0.05 * k + 0.01 * (2.0 * u(rng) - 1.0);
      apply = stamp + 0.005 * u(rng);
    }
    if (t >= 1.0) {
      tr.t.push_back(t);
      tr.m.push_back(em.at(t));
    }
  }
  tr.gaps = em.gaps();
  return tr;
}

// After gaps of 0.5, 1.5, 3 and 10 s (and a 3 s gap after which the source is 10 m off its track), the stop during
// the gap and the rejoin after it keep |a| within rejoin_max_acceleration (the source's own acceleration is 0) and
// |v| within rejoin_max_velocity of the source's speed; p, v, a stay continuous on the 1 ms grid; the motion is
// back on the source once the rejoin ends; the gap is counted with its length. Without the bound (a_max huge: the
// former behaviour, one min_blend to the returning source) the same returns cost tens to thousands of m/s².
TEST(ExternalMotion, GapsRejoinWithBoundedAccelerationAndSpeed) {
  const ExternalMotionOptions o;  // rejoin_max_acceleration 0.5 m/s², rejoin_max_velocity 2 m/s
  const Vec2 vel(0.4, -0.3);      // 0.5 m/s
  struct Case {
    double gap;
    Vec2 jump;
  };
  for (const Case& c : {Case{0.5, Vec2::Zero()}, Case{1.5, Vec2::Zero()}, Case{3.0, Vec2::Zero()},
                        Case{10.0, Vec2::Zero()}, Case{3.0, Vec2(6.0, 8.0)}}) {
    const double t_end = 4.0 + c.gap + 30.0;
    const GapTrace tr = runGap(c.gap, vel, c.jump, o, t_end);
    double peak_a = 0.0, peak_v = 0.0, fd_v = 0.0, fd_a = 0.0, err_after = 0.0;
    for (size_t i = 0; i + 1 < tr.t.size(); ++i) {
      const PointMotion &m = tr.m[i], &n = tr.m[i + 1];
      const double h = tr.t[i + 1] - tr.t[i];
      // Smooth pieces: O(h²) mismatches (< 1e-7 here); a jump of J in v or a would give J / 2.
      fd_v = std::max(fd_v, ((n.p - m.p) / h - 0.5 * (m.v + n.v)).norm());
      fd_a = std::max(fd_a, ((n.v - m.v) / h - 0.5 * (m.a + n.a)).norm());
      if (tr.t[i] > 3.9) peak_a = std::max(peak_a, m.a.norm()), peak_v = std::max(peak_v, m.v.norm());
      if (tr.t[i] > tr.gaps.rejoin_end + 1.0) {
        const Vec2 src = Vec2(3.0, -20.0) + vel * tr.t[i] + c.jump;
        err_after = std::max({err_after, (m.p - src).norm(), (m.v - vel).norm()});
      }
    }
    ExternalMotionOptions off = o;
    off.rejoin_max_acceleration = off.rejoin_max_velocity = 1e6;
    const GapTrace old = runGap(c.gap, vel, c.jump, off, 4.0 + c.gap + 2.0);
    double old_peak = 0.0;
    for (size_t i = 0; i < old.t.size(); ++i)
      if (old.t[i] > 3.9) old_peak = std::max(old_peak, old.m[i].a.norm());
    std::printf(
        "[ measured ] gap %.1f s%s: peak |a| %.3f m/s^2 (%.1f unbounded), peak |v| %.3f m/s, rejoin %.2f s, "
        "then |p - source| + |v - source| %.1e; fd mismatch v %.1e, a %.1e\n",
        c.gap, c.jump.norm() > 0.0 ? " + 10 m" : "", peak_a, old_peak, peak_v, tr.gaps.rejoin_end - tr.t_return,
        err_after, fd_v, fd_a);
    // The bound is checked at 64 points per planned quintic: between them its cubic acceleration exceeds the
    // checked values by O((T/64)² |a''|) ~ 1e-3 relative; 1 % leaves room.
    EXPECT_LE(peak_a, 1.01 * o.rejoin_max_acceleration) << c.gap;
    EXPECT_LE(peak_v, vel.norm() + o.rejoin_max_velocity) << c.gap;
    EXPECT_LT(fd_v, 1e-5) << c.gap;       // [m/s]
    EXPECT_LT(fd_a, 1e-4) << c.gap;       // [m/s²]
    EXPECT_LT(err_after, 1e-6) << c.gap;  // a linear source is fitted and predicted exactly
    EXPECT_GT(old_peak, 10.0 * peak_a) << c.gap;
    EXPECT_EQ(tr.gaps.count, 1) << c.gap;
    // The silence (4, 4 + gap) is bracketed by stamps up to a period + the jitter outside it, on each side.
    EXPECT_GE(tr.gaps.last, c.gap) << c.gap;
    EXPECT_LE(tr.gaps.last, c.gap + 2.0 * (0.05 + 0.01) + 0.005) << c.gap;
    EXPECT_EQ(tr.gaps.longest, tr.gaps.last);
    EXPECT_GT(tr.gaps.rejoin_end, tr.t_return);
  }
  ExternalMotionOptions bad;
  bad.rejoin_max_acceleration = 0.0;
  EXPECT_EQ(bad.validate().rfind("rejoin_max_acceleration", 0), 0u);
  bad = ExternalMotionOptions();
  bad.rejoin_max_velocity = -1.0;
  EXPECT_EQ(bad.validate().rfind("rejoin_max_velocity", 0), 0u);
  bad = ExternalMotionOptions();
  bad.rejoin_max_angular_acceleration = NAN;
  EXPECT_EQ(bad.validate().rfind("rejoin_max_angular_acceleration", 0), 0u);
  bad = ExternalMotionOptions();
  bad.rejoin_max_angular_velocity = 0.0;
  EXPECT_EQ(bad.validate().rfind("rejoin_max_angular_velocity", 0), 0u);
}

// Samples that keep coming (no gap) never trigger a rejoin: the jittery 10 Hz sinusoid of the tracking tests
// counts no gap, and a 100 Hz feed with a 0.2 s hiccup neither (less than blend + coast).
TEST(ExternalMotion, RegularSamplesAreNoGap) {
  ExternalMotion em = startAtTruth();
  run(em, 10.0, 0.3, 0.0, 0.02, 12.0, 1e-3);
  EXPECT_EQ(em.gaps().count, 0);
  ExternalMotion fast = startAtTruth();
  for (int k = 1; k <= 300; ++k)
    if (k < 100 || k > 120) fast.addSample(0.01 * k, truth(0.01 * k), 0.01 * k);
  EXPECT_EQ(fast.gaps().count, 0);
  fast.addSample(3.5, truth(3.5), 3.5);  // 0.5 s
  EXPECT_EQ(fast.gaps().count, 1);
  EXPECT_NEAR(fast.gaps().last, 0.5, 1e-9);
}

TEST(ExternalMotion, InvalidOptionsNameTheField) {
  ExternalMotionOptions o;
  o.stop_time = 0.0;
  EXPECT_EQ(o.validate().rfind("stop_time", 0), 0u);
  try {
    ExternalMotion em(Vec2::Zero(), 0.0, o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stop_time"), std::string::npos);
  }
}

}  // namespace
}  // namespace riser_sim
