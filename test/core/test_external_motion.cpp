// ExternalMotion: C2 continuity across sample arrivals, lag and tracking error for a jittery sampled
// sinusoid, hold on timeout, rejection of bad samples, no allocation.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "riser_sim/external_motion.h"

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
    EXPECT_LT(fdMismatch(tr, [](const PointMotion& m) { return m.p; }, [](const PointMotion& m) { return m.v; }),
              tol_v)
        << hz << " Hz";
    EXPECT_LT(fdMismatch(tr, [](const PointMotion& m) { return m.v; }, [](const PointMotion& m) { return m.a; }),
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
  EXPECT_LT(maxError(tr, 1.0), 0.01);  // [m]: noise 1 mm, bias of the prediction small
}

TEST(ExternalMotion, HoldsStillAfterTimeout) {
  ExternalMotion em = startAtTruth();
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
  const double t_now = t + 0.1;                    // integration time (not re-mapped)
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
  std::printf("[ measured ] start against a source at 2 m/s: peak |a| %.3g m/s^2 without a start blend, %.3g with "
              "2 s (3.94 v/T = %.3g); |p - source| %.1e m in the 0.5 s after it, %.1e later\n", peak[0], peak[1],
              3.94 * v / T, handover, after);
  EXPECT_LE(peak[1], 1.1 * 3.94 * v / T);  // one quintic, the first samples' fit aside
  EXPECT_GT(peak[0], 5.0 * peak[1]);
  EXPECT_LE(handover, 1e-4);
  EXPECT_LE(after, 1e-9);
  ExternalMotionOptions bad;
  bad.start_blend = -1.0;
  EXPECT_EQ(bad.validate().rfind("start_blend", 0), 0u);
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
