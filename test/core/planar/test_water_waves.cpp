// Airy wave kinematics (water.cpp) against the textbook finite-depth formulas, the deep-water limit,
// mass conservation and a = ∂v/∂t; the amplitude ramp; the steady sea the statics see. Before: for
// k h beyond ~710 (a 2.35 s wave in 1000 m of water) sinh(k h) overflowed and every velocity was NaN.
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {
namespace {

constexpr double kG = 9.81;

WaterSpec sea(double height, double period, double depth, double ramp = 0.0) {
  WaterSpec s;
  s.enabled = true;
  s.surface = 2.0;  // mean surface at y = 2 m: z = y - 2
  s.waves.height = height;
  s.waves.period = period;
  s.waves.depth = depth;
  s.waves.phase = 0.4;
  s.waves.ramp = ramp;
  return s;
}

// Round-off only: the ratios are evaluated in a different but exact form (e^{kz} ± e^{-k(z+2h)}) /
// (1 - e^{-2kh}) = cosh, sinh(k(z+h)) / sinh(kh); a few ulps of the O(1) factors.
constexpr double kFormTol = 1e-12;

TEST(WaterWaves, MatchesTextbookFiniteDepth) {
  const WaterSpec s = sea(2.5, 7.0, 30.0);
  const WaterKinematics w(s, kG);
  const double k = w.waveNumber(), om = 2.0 * M_PI / 7.0, h = 30.0;
  EXPECT_NEAR(om * om, kG * k * std::tanh(k * h), 1e-12 * om * om);  // dispersion relation
  for (double z : {0.0, -4.0, -17.0, -30.0})
    for (double x : {0.0, 13.0})
      for (double t : {0.0, 2.3}) {
        Vec2 v, a;
        w.at(Vec2(x, s.surface + z), t, v, a);
        const double th = k * x - om * t + s.waves.phase, amp = 0.5 * s.waves.height * om / std::sinh(k * h);
        const double ch = std::cosh(k * (z + h)), sh = std::sinh(k * (z + h));
        const Vec2 v_ref(amp * ch * std::cos(th), amp * sh * std::sin(th));
        const Vec2 a_ref(amp * om * ch * std::sin(th), -amp * om * sh * std::cos(th));
        const double scale = 0.5 * s.waves.height * om;
        EXPECT_NEAR((v - v_ref).norm(), 0.0, kFormTol * scale) << "z " << z;
        EXPECT_NEAR((a - a_ref).norm(), 0.0, kFormTol * scale * om) << "z " << z;
      }
}

// Deep water (k h = 1006 and 786): finite, and the deep-water limit (H/2) ω e^{kz} (e^{-2kh} ~ 0).
TEST(WaterWaves, DeepWaterIsFiniteAndExponential) {
  for (const auto& c : {std::pair<double, double>{2.0, 1000.0}, {8.0, 12500.0}}) {
    const WaterSpec s = sea(1.5, c.first, c.second);
    const WaterKinematics w(s, kG);
    const double om = 2.0 * M_PI / c.first, k = om * om / kG;
    EXPECT_NEAR(w.waveNumber(), k, 1e-12 * k);
    for (double z : {0.0, -0.7, -3.0, -c.second}) {
      Vec2 v, a;
      w.at(Vec2(5.0, s.surface + z), 1.1, v, a);
      ASSERT_TRUE(v.allFinite() && a.allFinite()) << "T " << c.first << " depth " << c.second << " z " << z;
      const double th = k * 5.0 - om * 1.1 + s.waves.phase, amp = 0.5 * s.waves.height * om * std::exp(k * z);
      EXPECT_NEAR(v.x(), amp * std::cos(th), kFormTol * 0.5 * s.waves.height * om);
      EXPECT_NEAR(v.y(), amp * std::sin(th), kFormTol * 0.5 * s.waves.height * om);
    }
  }
}

// Independent of the formulas: incompressible (∂u/∂x + ∂w/∂z = 0) and a = ∂v/∂t, by central
// differences (step 1e-4 m / 1e-4 s: truncation ~(k δ)² ~ 1e-9, round-off ~1e-12 / 1e-4), also while
// the amplitude ramps up (a then has the ramp's rate term). Tolerance 1e-6 of ω |v|.
TEST(WaterWaves, IncompressibleAndAccelerationIsTheRate) {
  for (double ramp : {0.0, 9.0}) {
    const WaterSpec s = sea(3.0, 6.0, 40.0, ramp);
    const WaterKinematics w(s, kG);
    const double om = 2.0 * M_PI / 6.0, scale = 0.5 * s.waves.height * om, dx = 1e-4, dt = 1e-4;
    for (double z : {-1.0, -12.0, -35.0})
      for (double t : {0.7, 4.1, 11.0}) {
        const Vec2 p(3.0, s.surface + z);
        Vec2 v, a, vx1, vx0, vz1, vz0, vt1, vt0, dummy;
        w.at(p, t, v, a);
        w.at(p + Vec2(dx, 0.0), t, vx1, dummy);
        w.at(p - Vec2(dx, 0.0), t, vx0, dummy);
        w.at(p + Vec2(0.0, dx), t, vz1, dummy);
        w.at(p - Vec2(0.0, dx), t, vz0, dummy);
        w.at(p, t + dt, vt1, dummy);
        w.at(p, t - dt, vt0, dummy);
        const double div = (vx1.x() - vx0.x() + vz1.y() - vz0.y()) / (2.0 * dx);
        EXPECT_NEAR(div, 0.0, 1e-6 * om * scale) << "ramp " << ramp << " z " << z << " t " << t;
        EXPECT_NEAR((a - (vt1 - vt0) / (2.0 * dt)).norm(), 0.0, 1e-6 * om * scale) << "ramp " << ramp << " t " << t;
      }
  }
}

// The ramp: nothing at t <= 0, half the amplitude at half the ramp, all of it from the ramp's end on.
TEST(WaterWaves, RampScalesTheAmplitude) {
  WaterSpec s = sea(2.0, 5.0, 50.0, 8.0);
  s.current.velocity = Eigen::Vector3d(0.3, 0.0, 0.0);
  WaterSpec full = s;
  full.waves.ramp = 0.0;
  const WaterKinematics w(s, kG), wf(full, kG);
  const Vec2 p(1.0, s.surface - 3.0), current(0.3, 0.0);
  Vec2 v, a, vf, af;
  for (double t : {-1.0, 0.0}) {
    w.at(p, t, v, a);
    EXPECT_NEAR((v - current).norm(), 0.0, 1e-15);
    EXPECT_NEAR(a.norm(), 0.0, 1e-15);
  }
  w.at(p, 4.0, v, a);
  wf.at(p, 4.0, vf, af);
  EXPECT_NEAR((v - current - 0.5 * (vf - current)).norm(), 0.0, 1e-14);
  for (double t : {8.0, 13.0}) {
    w.at(p, t, v, a);
    wf.at(p, t, vf, af);
    EXPECT_NEAR((v - vf).norm(), 0.0, 1e-15);
    EXPECT_NEAR((a - af).norm(), 0.0, 1e-15);
  }
}

// The scene key: read, and refused when negative, named.
TEST(WaterWaves, RampKey) {
  const std::string scene =
      "line: {length: 10, elements: 4, outer_diameter: 0.1, youngs_modulus: 2e11, density: 7850}\n"
      "environment:\n  water: {}\n  waves: {height: 1, period: 6, ramp: ";
  EXPECT_EQ(loadSceneText(scene + "12.5}\n", "ramp").water.waves.ramp, 12.5);
  try {
    loadSceneText(scene + "-1}\n", "ramp");
    ADD_FAILURE() << "a negative ramp was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("environment.waves.ramp"), std::string::npos) << e.what();
  }
}

// What the statics see: no waves, the current at its velocity at t, no acceleration.
TEST(WaterWaves, SteadySeaDropsWavesAndFreezesTheCurrent) {
  WaterSpec s = sea(2.0, 5.0, 50.0);
  s.current.velocity = Eigen::Vector3d(0.2, 0.0, 0.0);
  s.current.acceleration = Eigen::Vector3d(0.05, 0.0, 0.0);
  s.current.profile = {{0.0, 0.6}, {20.0, 0.1}};
  const WaterKinematics steady = WaterKinematics(s, kG).steady(4.0);
  Vec2 v, a;
  steady.at(Vec2(0.0, s.surface - 10.0), 123.0, v, a);
  EXPECT_NEAR(v.x(), 0.35 + 0.05 * 4.0, 1e-15);  // profile at 10 m depth, current at t = 4 s
  EXPECT_NEAR(v.y(), 0.0, 1e-15);
  EXPECT_NEAR(a.norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace riser_sim
