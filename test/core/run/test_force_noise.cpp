// ForceNoiseMonitor: its estimate against signals whose noise is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "riser_sim/run/force_noise.h"

namespace riser_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// White noise of RMS σ on a steady force T0: rms(d) = √6 σ exactly in expectation; 1e5 samples give the
// RMS to ~0.5 % (its relative standard error is ~1/√(2N) times a factor of order 1), 3 % is the bound.
TEST(ForceNoise, WhiteNoiseIsMeasuredAtItsRms) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  ForceNoiseMonitor m;
  const double T0 = 1e5, sigma = 2e3;
  for (int k = 0; k < 100000; ++k) m.add(T0 + sigma * noise(rng), 2.0 * T0 + 2.0 * sigma * noise(rng), 0.01);
  const double rms_T = std::hypot(T0, sigma);
  EXPECT_NEAR(m.total().top, sigma / rms_T, 0.03 * sigma / rms_T);
  EXPECT_NEAR(m.total().max_axial, sigma / rms_T, 0.03 * sigma / rms_T);
}

// A tone at the step's Nyquist frequency (what an undamped unresolved mode becomes): rms(d) = 4 a, the
// estimate 4 a / √6 against the tone's RMS a / √2: 2.31x conservative.
TEST(ForceNoise, NyquistToneIsOverestimatedNotMissed) {
  ForceNoiseMonitor m;
  const double T0 = 1e5, a = 1e3;
  for (int k = 0; k < 1000; ++k) m.add(T0 + a * (k % 2 ? 1.0 : -1.0), T0, 0.1);
  EXPECT_NEAR(m.total().top, 4.0 * a / std::sqrt(6.0) / std::hypot(T0, a), 1e-6);
  EXPECT_EQ(m.total().max_axial, 0.0);  // a steady force has no noise
}

// A resolved force: the J-lay's surge (27 s) at h = 0.1 s, half the tension swinging. d ≈ -h² ω² A sin,
// rms(d) = h² ω² A / √2, so the estimate is h² ω² A / √2 / √6 / rms(T) = 0.01 · 0.0542 · 0.5 / 1.414 /
// 2.449 / 1.061 ≈ 7.4e-5 (5 %: the sin²(ωh/2) vs (ωh/2)² difference is 1e-4 relative).
TEST(ForceNoise, ResolvedForceIsQuiet) {
  ForceNoiseMonitor m;
  const double h = 0.1, w = 2.0 * kPi / 27.0;
  for (int k = 0; k < 2700; ++k) m.add(1e5 * (1.0 + 0.5 * std::sin(w * k * h)), 1e5, h);
  const double expected = h * h * w * w * 0.5 / std::sqrt(2.0) / std::sqrt(6.0) / std::sqrt(1.0 + 0.125);
  EXPECT_NEAR(m.total().top, expected, 0.05 * expected);
  EXPECT_LT(m.total().worst(), 0.01 * kForceNoiseWarning);
}

// The recent estimate forgets: noise for 100 s then none for 100 s (10 windows: e^-10 of the noise's
// weight remains, so the recent estimate is below 1 % of the total one).
TEST(ForceNoise, RecentEstimateForgetsOldNoise) {
  ForceNoiseMonitor m;
  for (int k = 0; k < 20000; ++k) m.add(1e5 + (k < 10000 ? 5e3 * (k % 2 ? 1.0 : -1.0) : 0.0), 1e5, 0.01);
  EXPECT_GT(m.total().top, kForceNoiseWarning);
  EXPECT_LT(m.recent().top, 0.01 * m.total().top);
}

// Non-finite input is not counted (the divergence check reports it); reset() starts over.
TEST(ForceNoise, NonFiniteSkippedAndResetClears) {
  ForceNoiseMonitor m;
  for (int k = 0; k < 10; ++k) m.add(k % 2 ? 1.0 : 2.0, 1.0, 0.1);
  m.add(NAN, 1.0, 0.1);
  EXPECT_EQ(m.samples(), 10);
  EXPECT_TRUE(std::isfinite(m.total().top));
  m.reset();
  EXPECT_EQ(m.samples(), 0);
  EXPECT_EQ(m.total().top, 0.0);
}

}  // namespace
}  // namespace riser_sim
