// Stability at the extremes in 3D, through the scene builder (Run3, its divergence checks and energy
// balance): n = 1 and n = 1000, a soft cord, steel on short elements beyond and within the explicit limit,
// a snap load, a whirl near resonance. Each case ends sound (finite outputs, energy balance and joint gaps
// within the stated bound) or stops cleanly naming solver.dt - never NaN in a run that reports success.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

using spatial::LineOutputs3;
using spatial::Run3;
using spatial::Vec3;

bool finite(const LineOutputs3& o) {
  for (const auto& p : o.points)
    if (!p.allFinite()) return false;
  for (double f : o.axial_force)
    if (!std::isfinite(f)) return false;
  return o.top_force.allFinite() && std::isfinite(o.kinetic_energy) && std::isfinite(o.potential_energy);
}

// A scene: the line block, then the rest.
Scene scene(const std::string& line, const std::string& rest) {
  return loadSceneText("space: spatial\nline:\n" + line + rest, "test_spatial_extremes");
}

// Joint gaps of a sound run: explicit steps at a resolved h keep them ~1e-12 m; the implicit ones through
// their Baumgarte rows ~1e-6 d (docs/spatial.md). 1e-3 d is 50x below the divergence threshold 0.05 d.
constexpr double kGapPerD = 1e-3;

struct Sound {
  double drift = 0.0, peak_tension = 0.0;
};

// Runs to `duration`; a divergence fails the test (these cases must be sound).
Sound runSound(const Scene& s, double duration, double energy_bound) {
  Run3 run(s);
  Sound r;
  const long steps = std::lround(duration / run.dt());
  for (long k = 0; k < steps; ++k) {
    if (!run.step()) {
      ADD_FAILURE() << "diverged at t = " << run.time() << ": " << run.divergenceReason();
      return r;
    }
    r.peak_tension = std::max(r.peak_tension, run.outputs().max_tension);
  }
  const LineOutputs3& o = run.outputs();
  EXPECT_TRUE(finite(o));
  r.drift = run.energyDrift();
  EXPECT_LE(std::abs(r.drift), energy_bound);
  EXPECT_LE(run.maxConstraintError(), kGapPerD * run.model().line().segmentLength());
  return r;
}

const std::string kSteelPipe =
    "  outer_diameter: 0.05\n  inner_diameter: 0.04\n  youngs_modulus: 2.07e11\n  density: 7850.0\n";

// One segment (two half-length rfes), released 4 m to the side: a 3D swing. rk4 at 2 ms resolves it: the
// balance closes to rounding (~1e-12 measured), 1e-6 leaves rk4's h^4 error room.
TEST(SpatialExtremes, OneSegmentSwings) {
  const Scene s =
      scene("  length: 20.0\n  elements: 1\n" + kSteelPipe + "  end_mass: 50.0\n  axial_flexibility: false\n",
            "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [1.0, 0.5, 0]\n"
            "    period: 4.0\ninitial:\n  type: displaced\n  end_offset: [0.0, 4.0]\n"
            "solver:\n  dt: 0.002\n  integrator: rk4\n");
  const Sound r = runSound(s, 2.0, 1e-6);
  std::printf("[extremes3] n = 1: energy balance %.2e of m g L\n", r.drift);
}

// n = 1000 (1 m segments of a 1000 m steel line, bending, inextensible), straight down (an equilibrium),
// the top swaying in x and y: the structured O(n) midpoint at 20 ms. Midpoint conserves the quadratic
// invariants; the bound 1e-4 covers Newton's tolerance summed over the steps.
TEST(SpatialExtremes, ThousandSegmentsStructuredMidpoint) {
  const Scene s = scene("  length: 1000.0\n  elements: 1000\n" + kSteelPipe + "  axial_flexibility: false\n",
                        "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [2.0, 1.0, 0]\n"
                        "    period: 10.0\n    phase: [3.141592653589793, 3.141592653589793, 0]\n"
                        "initial:\n  type: straight\n  angle: -90\nsolver:\n  dt: 0.02\n  integrator: midpoint\n");
  const Sound r = runSound(s, 0.4, 1e-4);
  std::printf("[extremes3] n = 1000 midpoint: energy balance %.2e of m g L\n", r.drift);
}

// A soft cord (EA 1e3 N, 1 kg/m, 1 kg end) released horizontally along a 30° heading: it falls and
// stretches by tens of per cent. rk4 at 1e-4 s (its axial limit ~2.8/sqrt(2 EA/(d m_rfe)) = 6e-3 s).
TEST(SpatialExtremes, SoftCordStretchesAndSwings) {
  const Scene s = scene(
      "  length: 10.0\n  elements: 10\n  EA: 1.0e3\n  EI: 1.0\n  mass_per_length: 1.0\n"
      "  end_mass: 1.0\n",
      "initial:\n  type: straight\n  angle: 0\n  heading: 30\n"
      "solver:\n  dt: 1.0e-4\n  integrator: rk4\n");
  const Sound r = runSound(s, 2.0, 1e-6);
  const double weight = (10.0 + 1.0) * 9.81;
  std::printf("[extremes3] soft cord: energy balance %.2e, peak tension %.1f N (weight %.1f N)\n", r.drift,
              r.peak_tension, weight);
  EXPECT_GT(r.peak_tension, weight);  // the fall loads the cord beyond its static tension
}

// Steel on 0.1 m segments (highest frequency 1.1e5 rad/s by the 3D estimate, the end rfes' axial
// springs: rk4's limit 2.3e-5 s). rk4 at 1 ms must stop cleanly, early, naming solver.dt (and the limit),
// with finite outputs before; the structured midpoint at the same step runs sound.
TEST(SpatialExtremes, SteelShortElementsBeyondTheExplicitLimit) {
  const std::string line = "  length: 10.0\n  elements: 100\n" + kSteelPipe + "  end_mass: 10.0\n";
  const std::string rest =
      "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [0.5, 0.5, 0]\n"
      "    period: 2.0\n    phase: [3.141592653589793, 3.141592653589793, 0]\n"
      "solver:\n  dt: 0.001\n  integrator: ";
  {
    Run3 run(scene(line, rest + "rk4\n"));
    bool ok = true;
    int k = 0;
    for (; k < 200 && ok; ++k) {
      ok = run.step();
      if (ok) EXPECT_TRUE(finite(run.outputs())) << "non-finite outputs in a step reported sound, t = " << run.time();
    }
    std::printf("[extremes3] steel n = 100 rk4 1 ms: %s after %d steps\n", ok ? "ran" : run.divergenceReason().c_str(),
                k);
    ASSERT_FALSE(ok) << "rk4 at 40x its stability limit ran 200 steps";
    EXPECT_LE(k, 50) << "caught late";
    EXPECT_NE(run.divergenceReason().find("solver.dt"), std::string::npos) << run.divergenceReason();
  }
  const Sound r = runSound(scene(line, rest + "midpoint\n"), 0.2, 1e-4);
  std::printf("[extremes3] steel n = 100 midpoint 1 ms: energy balance %.2e\n", r.drift);
}

// Snap load: an extensible line (no bending) standing 3° off straight up, heading 30°, falls; its end mass
// drops ~2 L and the line snaps taut. The peak spring tension must exceed 2 m g (the snap) and stay below
// what energy allows: no spring holds more than all the potential energy released,
// c Δ ≤ sqrt(2 E_avail c), E_avail = E0 - V_min, V_min = -g (m_line L / 2 + m_end L) (1 % for the stretch).
TEST(SpatialExtremes, SnapLoadOnReTension) {
  for (const std::string integ : {"rk4", "midpoint", "generalized_alpha"}) {
    SCOPED_TRACE(integ);
    // rk4 at 5e-5 s resolves the snap (balance 6e-4 of m g L; 2e-4 s: 0.21, 1e-4 s: 1.4e-2, fourth order);
    // the implicit schemes at 1 ms do not (midpoint 0.05, generalized_alpha 0.4 lost) and are flagged by
    // the run's energy-balance warning (1e-3): they may lose energy, never create it.
    const std::string dt = integ == "rk4" ? "5.0e-5" : "1.0e-3";
    const Scene s = scene(
        "  length: 10.0\n  elements: 20\n  EA: 1.0e7\n  mass_per_length: 10.0\n  end_mass: 50.0\n"
        "  bending: false\n",
        "initial:\n  type: straight\n  angle: 87\n  heading: 30\nsolver:\n  dt: " + dt + "\n  integrator: " + integ +
            "\n");
    Run3 run(s);
    const double g = 9.81, m_line = 100.0, m_end = 50.0, L = 10.0;
    const double e0 = run.outputs().kinetic_energy + run.outputs().potential_energy;
    const double e_avail = e0 + 1.01 * g * (0.5 * m_line * L + m_end * L);
    double c_max = 0.0;
    for (int i = 0; i < run.model().bodies(); ++i) c_max = std::max(c_max, run.model().rfe(i).axial_stiffness);
    const double bound = std::sqrt(2.0 * e_avail * c_max), weight = (m_line + m_end) * g;
    double peak = 0.0;
    bool ok = true;
    const long steps = std::lround(2.5 / run.dt());
    for (long k = 0; k < steps && ok; ++k) {
      ok = run.step();
      if (ok) peak = std::max(peak, run.outputs().max_tension);
    }
    std::printf("[extremes3] snap %-17s %s: peak %.4g N (weight %.4g N, energy bound %.4g N), balance %.2e\n",
                integ.c_str(), ok ? "ok" : run.divergenceReason().c_str(), peak, weight, bound,
                ok ? run.energyDrift() : 0.0);
    if (!ok) {  // a clean stop is acceptable; silent garbage is not
      EXPECT_NE(run.divergenceReason().find("solver.dt"), std::string::npos) << run.divergenceReason();
      continue;
    }
    EXPECT_TRUE(finite(run.outputs()));
    EXPECT_GE(peak, 2.0 * weight) << "no snap load";
    EXPECT_LE(peak, bound) << "more tension than the released energy allows";
    EXPECT_LE(run.energyDrift(), 1e-3) << "energy created";
    if (integ == "rk4") EXPECT_LE(std::abs(run.energyDrift()), 1e-3);
  }
}

// A whirl: the top on a 5 cm horizontal circle at the hanging line's pendulum period 2π sqrt(L_eff / g)
// (heavy end mass: L_eff ~ L). The end's circle grows well beyond the top's; the balance E - E0 - W holds
// from 1 s on (the circle starts with a velocity jump, which shows in the first step's balance). rk4 at
// 2e-4 s: the axial limit is ~1e-3 s (EA 1e6 N on 0.5 m segments of 0.5 kg).
TEST(SpatialExtremes, WhirlNearResonanceKeepsEnergyBalance) {
  const double L = 10.0, period = 2.0 * M_PI * std::sqrt(L / 9.81);
  char top[256];
  std::snprintf(top, sizeof(top),
                "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [0.05, 0.05, 0]\n"
                "    period: %.17g\n    phase: [0, -1.5707963267948966, 0]\n",
                period);
  const Scene s = scene(
      "  length: 10.0\n  elements: 20\n  EA: 1.0e6\n  EI: 10.0\n  mass_per_length: 1.0\n"
      "  end_mass: 50.0\n",
      std::string(top) + "solver:\n  dt: 2.0e-4\n  integrator: rk4\n");
  Run3 run(s);
  double drift1 = 0.0, r_max = 0.0;
  const long steps = std::lround(30.0 / run.dt());
  for (long k = 1; k <= steps; ++k) {
    ASSERT_TRUE(run.step()) << run.divergenceReason();
    if (k == 5000) drift1 = run.energyDrift();
    const Vec3 end = run.outputs().points.back();
    r_max = std::max(r_max, std::hypot(end.x(), end.y()));
  }
  EXPECT_TRUE(finite(run.outputs()));
  const double drift = run.energyDrift() - drift1;
  std::printf("[extremes3] whirl: end radius up to %.3f m (top 0.05 m), balance from 1 s %.2e\n", r_max, drift);
  EXPECT_GT(r_max, 10.0 * 0.05) << "no resonance";
  EXPECT_LE(std::abs(drift), 1e-7);
}

}  // namespace
}  // namespace riser_sim
