// Irregular long-crested waves from a JONSWAP spectrum (water.cpp):
// - the spectrum's shape against closed forms: the Pierson-Moskowitz integral ∫ω⁻⁵ e^{-5/4 (ω_p/ω)⁴} dω =
//   1/(5 ω_p⁴), and γ's peak enhancement against the normalisation A_γ = 1 - 0.287 ln γ (DNV-RP-C205 3.5.5.2);
// - the simulated surface elevation: its Fourier amplitudes over its exact repeat period are the requested
//   spectrum's sqrt(2 S Δω), and 4 sqrt(mean η²) is Hs;
// - the kinematics: the sum of the textbook Airy components, incompressible, a = ∂v/∂t;
// - a seed reproduces its sea; the scene keys.
#include <gtest/gtest.h>

#include "riser_sim/spatial/water.h"

#include <cmath>
#include <complex>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {
namespace {

constexpr double kG = 9.81;

WaterSpec jonswap(double hs, double tp, double gamma, int n, unsigned seed, double depth = 200.0) {
  WaterSpec s;
  s.enabled = true;
  s.waves.type = WaveKind::kJonswap;
  s.waves.significant_height = hs;
  s.waves.peak_period = tp;
  s.waves.gamma = gamma;
  s.waves.components = n;
  s.waves.seed = seed;
  s.waves.depth = depth;
  return s;
}

// Midpoint rule on [0.05, 40] ω_p with 4e5 bins (below 0.05 ω_p the shape is < e^{-1e5}), plus the tail beyond
// 40 ω_p in closed form, ∫ω⁻⁵ = 1/(4 ω⁴) (there e^{-5/4 (ω_p/ω)⁴} = 1 - 5e-7 and γ's factor is 1).
double shapeIntegral(double wp, double gamma) {
  const double lo = 0.05 * wp, hi = 40.0 * wp;
  const int n = 400000;
  const double dw = (hi - lo) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += WaterKinematics::jonswapShape(lo + (i + 0.5) * dw, wp, gamma) * dw;
  return sum + 0.25 / std::pow(hi, 4);
}

TEST(WaterJonswap, SpectrumShapeAgainstClosedForms) {
  const double wp = 2.0 * M_PI / 9.0;
  const double pm = shapeIntegral(wp, 1.0);
  EXPECT_NEAR(pm * 5.0 * std::pow(wp, 4), 1.0, 1e-7);
  std::printf("[ measured ] PM integral x 5 w_p^4 = %.10f (closed form 1)\n", pm * 5.0 * std::pow(wp, 4));
  // A_γ is an engineering fit (good to ~1 %: measured 0.2 % at γ 2, 3.3, 5): bound 1 %.
  for (double gamma : {2.0, 3.3, 5.0}) {
    const double ratio = pm / shapeIntegral(wp, gamma);
    EXPECT_NEAR(ratio, 1.0 - 0.287 * std::log(gamma), 0.01) << "gamma " << gamma;
    std::printf("[ measured ] gamma %.1f: PM / JONSWAP integral %.4f, A_gamma %.4f\n", gamma, ratio,
                1.0 - 0.287 * std::log(gamma));
  }
}

// The components sit at half-integer multiples of Δω (0.5 ω_p = N/5 Δω), so η repeats after 4π/Δω: over that
// record (sampled at T_p/40, below Nyquist for 3 ω_p) the Fourier sums at each ω_i return a_i exactly up to
// round-off. Bound 1e-9 of the largest amplitude; Hs = 4 sqrt(mean η²) to 1e-9.
TEST(WaterJonswap, SimulatedElevationHasTheRequestedSpectrum) {
  const double hs = 6.0, tp = 11.0, gamma = 3.3;
  const int n = 50;
  const WaterKinematics w(jonswap(hs, tp, gamma, n, 7), kG);
  const auto& c = w.components();
  ASSERT_EQ(static_cast<int>(c.size()), n);
  const double wp = 2.0 * M_PI / tp, dw = 2.5 * wp / n;
  const double record = 4.0 * M_PI / dw, dt = tp / 40.0;
  const int m = static_cast<int>(std::lround(record / dt));
  std::vector<double> eta(m);
  double var = 0.0;
  for (int j = 0; j < m; ++j) var += (eta[j] = w.elevation(0.0, j * record / m)) * eta[j] / m;
  EXPECT_NEAR(4.0 * std::sqrt(var), hs, 1e-9 * hs);
  double amax = 0.0, err = 0.0, s_peak = 0.0, w_peak = 0.0;
  for (const auto& comp : c) amax = std::max(amax, comp.a);
  for (int i = 0; i < n; ++i) {
    std::complex<double> X = 0.0;
    for (int j = 0; j < m; ++j) X += eta[j] * std::exp(std::complex<double>(0.0, c[i].omega * j * record / m));
    const double a = 2.0 * std::abs(X) / m;
    // The requested spectrum at ω_i, scaled to Hs on the discrete grid.
    err = std::max(err, std::abs(a - c[i].a));
    const double S = a * a / (2.0 * dw);
    if (S > s_peak) s_peak = S, w_peak = c[i].omega;
  }
  EXPECT_LE(err, 1e-9 * amax);
  EXPECT_NEAR(w_peak, wp, dw);  // the estimated spectrum peaks at ω_p
  // The amplitudes follow the shape: a_i² ∝ S(ω_i).
  const double ref = c[n / 4].a * c[n / 4].a / WaterKinematics::jonswapShape(c[n / 4].omega, wp, gamma);
  for (const auto& comp : c)
    EXPECT_NEAR(comp.a * comp.a, ref * WaterKinematics::jonswapShape(comp.omega, wp, gamma), 1e-12 * amax * amax);
  std::printf(
      "[ measured ] JONSWAP Hs %.3g m: 4 sqrt(m0) of the record %.12g m; Fourier amplitudes vs requested "
      "%.2e of the largest; spectral peak at %.4f rad/s (omega_p %.4f)\n",
      hs, 4.0 * std::sqrt(var), err / amax, w_peak, wp);
}

// v, a at a point: the sum over components of the textbook finite-depth Airy formulas (cosh, sinh evaluated
// directly: depth 60 m keeps k h < 30); then continuity and a = ∂v/∂t by central differences (as for the
// regular waves: truncation ~(k δ)², bound 1e-6 of ω_max |v|).
TEST(WaterJonswap, KinematicsAreTheSumOfAiryComponents) {
  WaterSpec s = jonswap(4.0, 8.0, 2.0, 30, 3, 60.0);
  s.surface = 1.5;
  s.waves.direction = -1.0;
  const WaterKinematics w(s, kG);
  const double h = 60.0;
  double scale = 0.0;
  for (const auto& c : w.components()) scale += c.a * c.omega;
  const double om_max = w.components().back().omega;
  for (double z : {0.0, -3.0, -25.0, -60.0})
    for (double t : {0.0, 17.3}) {
      const double x = 21.0;
      Vec2 v, a;
      w.at(Vec2(x, s.surface + z), t, v, a);
      Vec2 v_ref = Vec2::Zero(), a_ref = Vec2::Zero();
      for (const auto& c : w.components()) {
        EXPECT_NEAR(c.omega * c.omega, kG * c.k * std::tanh(c.k * h), 1e-12 * c.omega * c.omega);
        const double th = -c.k * x - c.omega * t + c.phase, amp = c.a * c.omega / std::sinh(c.k * h);
        const double ch = std::cosh(c.k * (z + h)), sh = std::sinh(c.k * (z + h));
        v_ref += Vec2(-amp * ch * std::cos(th), amp * sh * std::sin(th));
        a_ref += Vec2(-amp * c.omega * ch * std::sin(th), -amp * c.omega * sh * std::cos(th));
      }
      EXPECT_NEAR((v - v_ref).norm(), 0.0, 1e-12 * scale) << "z " << z;
      EXPECT_NEAR((a - a_ref).norm(), 0.0, 1e-12 * scale * om_max) << "z " << z;
      if (z == 0.0 || z == -60.0) continue;
      const double d = 1e-4;
      Vec2 vx1, vx0, vz1, vz0, vt1, vt0, dummy;
      const Vec2 p(x, s.surface + z);
      w.at(p + Vec2(d, 0.0), t, vx1, dummy);
      w.at(p - Vec2(d, 0.0), t, vx0, dummy);
      w.at(p + Vec2(0.0, d), t, vz1, dummy);
      w.at(p - Vec2(0.0, d), t, vz0, dummy);
      w.at(p, t + d, vt1, dummy);
      w.at(p, t - d, vt0, dummy);
      EXPECT_NEAR((vx1.x() - vx0.x() + vz1.y() - vz0.y()) / (2.0 * d), 0.0, 1e-6 * om_max * scale);
      EXPECT_NEAR((a - (vt1 - vt0) / (2.0 * d)).norm(), 0.0, 1e-6 * om_max * scale);
    }
}

TEST(WaterJonswap, SeedReproducesTheSea) {
  const WaterKinematics a(jonswap(3.0, 9.0, 3.3, 40, 11), kG), b(jonswap(3.0, 9.0, 3.3, 40, 11), kG),
      c(jonswap(3.0, 9.0, 3.3, 40, 12), kG);
  double same = 0.0, diff = 0.0;
  for (double t = 0.0; t < 100.0; t += 0.7) {
    same = std::max(same, std::abs(a.elevation(3.0, t) - b.elevation(3.0, t)));
    diff = std::max(diff, std::abs(a.elevation(3.0, t) - c.elevation(3.0, t)));
  }
  EXPECT_EQ(same, 0.0);
  EXPECT_GT(diff, 0.5);
}

// Water3 remembers its last wave samples per thread (keyed by the water, the point and the time): a repeated
// sample is bit for bit the computed one, and two waters that differ only in their sea, asked alternately at
// the same points and times, each get their own (no sample crosses between them).
TEST(WaterJonswap, RememberedSamplesAreExactAndPerWater) {
  WaterSpec a;
  a.enabled = true;
  a.waves.type = WaveKind::kJonswap;
  a.waves.significant_height = 4.0;
  a.waves.peak_period = 8.0;
  a.waves.components = 30;
  a.waves.seed = 3;
  a.waves.depth = 80.0;
  WaterSpec b = a;
  b.waves.seed = 4;
  const spatial::Water3 wa(a, spatial::Vec3(0, 0, -9.81)), wb(b, spatial::Vec3(0, 0, -9.81));
  const WaterKinematics pa(a, 9.81), pb(b, 9.81);
  int differ = 0;
  for (int k = 0; k < 50; ++k) {
    const spatial::Vec3 p(3.0 * k, 0.0, -0.7 * k);
    const double t = 0.37 * k;
    spatial::Vec3 first[2][2];
    for (int rep = 0; rep < 2; ++rep)
      for (int which = 0; which < 2; ++which) {
        const spatial::Water3& w = which == 0 ? wa : wb;
        spatial::Vec3 v, acc;
        w.at(p, t, v, acc);
        if (rep == 0) {
          first[which][0] = v, first[which][1] = acc;
          Vec2 v2, a2;  // the planar kinematics of the same sea (heading 0)
          (which == 0 ? pa : pb).at(Vec2(p.x(), p.z()), t, v2, a2);
          EXPECT_NEAR(v.x(), v2.x(), 1e-12 * (1.0 + v2.norm()));
          EXPECT_NEAR(v.z(), v2.y(), 1e-12 * (1.0 + v2.norm()));
          EXPECT_NEAR(acc.x(), a2.x(), 1e-12 * (1.0 + a2.norm()));
        } else {  // remembered: bit for bit
          EXPECT_EQ(v, first[which][0]);
          EXPECT_EQ(acc, first[which][1]);
        }
      }
    Vec2 va, vb, aa, ab;
    pa.at(Vec2(p.x(), p.z()), t, va, aa);
    pb.at(Vec2(p.x(), p.z()), t, vb, ab);
    differ += va != vb;
  }
  EXPECT_GT(differ, 40);  // the two seas do differ at those points
}

TEST(WaterJonswap, SceneKeys) {
  const std::string line =
      "line: {length: 50.0, elements: 5, EA: 1.0e7, EI: 1.0e4, mass_per_length: 80.0, outer_diameter: 0.3}\n";
  const Scene s = loadSceneText(line +
                                    "environment: {water: {}, waves: {type: jonswap, significant_height: 5.0, "
                                    "peak_period: 12.0, gamma: 2.5, components: 80, seed: 4, ramp: 20.0}}\n",
                                "j");
  EXPECT_EQ(s.water.waves.type, WaveKind::kJonswap);
  EXPECT_EQ(s.water.waves.significant_height, 5.0);
  EXPECT_EQ(s.water.waves.components, 80);
  EXPECT_EQ(s.water.waves.seed, 4u);
  EXPECT_TRUE(s.water.waves.active());
  const auto refused = [&](const std::string& waves, const std::string& key) {
    try {
      loadSceneText(line + "environment: {water: {}, waves: " + waves + "}\n", "j");
      ADD_FAILURE() << waves << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused("{type: jonswap, significant_height: 5.0, peak_period: 12.0, height: 2.0}", "environment.waves.height");
  refused("{significant_height: 5.0}", "environment.waves.significant_height");
  refused("{type: jonswap, significant_height: 5.0}", "environment.waves.peak_period");
  refused("{type: jonswap, significant_height: 5.0, peak_period: 12.0, gamma: 0.5}", "environment.waves.gamma");
  refused("{type: jonswap, significant_height: 5.0, peak_period: 12.0, components: 0}", "environment.waves.components");
  refused("{type: swell}", "environment.waves.type");
}

}  // namespace
}  // namespace riser_sim
