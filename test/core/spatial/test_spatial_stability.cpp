// The 3D explicit stability estimate (Simulator3::estimateStability, through Run3 as the CLI
// runs it) against independent references: the highest mode of the 3D modal analysis (independent
// coordinates, dense generalised eigen-solve), the eigenvalues of a dense finite-difference Jacobian
// (torsion, flex joints, a pinned bottom: what the modal analysis does not take), the torsional rotor
// chain's closed form, the planar estimate on a planar scene; then rk4 at 0.8x the estimate runs and at
// 1.5x it stops naming the limit. And the force-noise monitor on a 3D run that rings vs one that does not.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

using spatial::Run3;

const std::string kSteelPipe =
    "  outer_diameter: 0.05\n  inner_diameter: 0.04\n  youngs_modulus: 2.07e11\n  density: 7850.0\n";
// The steel pipe's mass per length [kg/m] and its default polar inertia per length ρ I_p = m (D² + d²)/8.
const double kPipeMass = 7850.0 * M_PI / 4.0 * (0.05 * 0.05 - 0.04 * 0.04);
const double kPipePolar = kPipeMass * (0.05 * 0.05 + 0.04 * 0.04) / 8.0;

Scene scene(const std::string& text) { return loadSceneText("space: spatial\n" + text, "test_spatial_stability"); }

// A 20 m steel pipe, 50 kg end mass, hanging (free bottom), the top swaying in x and y.
std::string hangingPipe(int n, bool extensible, const std::string& extra_line = "", const std::string& extra = "") {
  return "line:\n  length: 20.0\n  elements: " + std::to_string(n) + "\n" + kSteelPipe + "  end_mass: 50.0\n" +
         (extensible ? "" : "  axial_flexibility: false\n") + extra_line +
         "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [1.0, 0.5, 0]\n    period: 4.0\n" +
         extra;
}
const std::string kRelease = "initial:\n  type: displaced\n  end_offset: [0.0, 4.0]\n  end_force: release\n";

// ω_max from a dense Jacobian of v' over q (central differences at the run's initial state, step 1e-6 of
// the coordinates' scale: truncation ~1e-12 relative, round-off ~1e-10 of the largest entries) and
// Eigen's dense non-symmetric eigen-solve: sqrt of the largest |λ|.
double denseOmegaMax(Run3& run) {
  spatial::Simulator3& sim = run.simulator();
  const int p = sim.formulation().positionSize();
  const VecX y0 = sim.state();
  VecX y = y0, dp(y0.size()), dm(y0.size());
  const double h = 1e-6 * (1.0 + y0.head(p).cwiseAbs().maxCoeff());
  MatX A(p, p);
  for (int c = 0; c < p; ++c) {
    y[c] = y0[c] + h;
    sim.system().rhs(sim.time(), y, dp);
    y[c] = y0[c] - h;
    sim.system().rhs(sim.time(), y, dm);
    y[c] = y0[c];
    A.col(c) = (dp.segment(p, p) - dm.segment(p, p)) / (2.0 * h);
  }
  sim.evaluate();  // leave the simulator's evaluation at its state
  Eigen::EigenSolver<MatX> es(A, false);
  return std::sqrt(es.eigenvalues().cwiseAbs().maxCoeff());
}

// Hanging free: the estimate's ω_max against the highest mode of computeModes3 about the same
// equilibrium (the modes hold A_0 in independent coordinates). The run's natural coordinates hold A_0 and
// the joints by Baumgarte, c'' + 2ω_c c' + ω_c² c = 0 with ω_c = 50 rad/s: a real double eigenvalue -ω_c
// that rk4 integrates too, so the expected ω_max is max(modal highest, ω_c) (the short inextensible line's
// modes lie below 50 rad/s). Arnoldi's outermost Ritz values and the forward difference (1e-7 relative)
// leave < 1e-4 (measured: 3e-7 at most); 1e-3 is the bound.
TEST(SpatialStability, HighestFrequencyMatchesTheModes) {
  constexpr double kOmegaC = 50.0;  // solver.stabilization's default [rad/s]
  for (const bool extensible : {true, false})
    for (const int n : {5, 20}) {
      Run3 run(scene(hangingPipe(n, extensible)));
      const spatial::ModalResult3 modes = computeModes3(run.model(), run.initial().kin);
      const double w_modes = modes.modes.back().omega, expected = std::max(w_modes, kOmegaC);
      const double w = run.highestFrequency();
      std::printf("[stability3] %s n = %d: estimate %.6g rad/s, modal highest %.6g rad/s (%.1e); limit %.4g s\n",
                  extensible ? "extensible" : "inextensible", n, w, w_modes, w / expected - 1.0,
                  run.stableStepEstimate());
      EXPECT_NEAR(w, expected, 1e-3 * expected) << "n = " << n << (extensible ? " extensible" : " inextensible");
      // The undamped line's eigenvalues ±iω hold rk4 to 2.8284/ω, the Baumgarte pair -ω_c to 2.785/ω_c;
      // times the kept share 0.9 (spatial/simulator.cpp); 1 % for the Ritz values of the whole Jacobian.
      EXPECT_LE(run.stableStepEstimate(), 1.01 * 0.9 * 2.8284 / w);
      EXPECT_GE(run.stableStepEstimate(), 0.99 * 0.9 * 2.785 / w);
    }
}

// What the modal analysis does not take (torsion, a flex joint at each end, a pinned bottom): the estimate
// against a dense eigen-solve of the same linearisation (the Krylov estimate's error alone: measured
// < 1e-4, bound 1e-3), and
// the torsional part against the rotor chain: an inextensible line's stiffest motion is its twist, whose
// highest frequency on rfes of length d is (2/d) √(GJ / ρI_p) as n grows (sin of π(2N - 1)/(2(2N + 1))
// below it at N rotors: 0.6 % at N = 20; 2 % is the bound with the half-length end rfes).
TEST(SpatialStability, TorsionFlexJointsPinnedAgainstTheDenseSpectrum) {
  const double GJ = 3.0e4;
  const std::string torsion = "  torsion:\n    stiffness: 3.0e4\n";
  const std::string flex = "  flex_joint:\n    stiffness: 5.0e4\n    damping: 1.0e3\n";
  {
    Run3 run(scene(hangingPipe(20, false, torsion, flex + kRelease)));
    const double dense = denseOmegaMax(run), chain = 2.0 / 1.0 * std::sqrt(GJ / kPipePolar);
    std::printf("[stability3] torsion n = 20: estimate %.6g, dense %.6g, rotor chain %.6g rad/s\n",
                run.highestFrequency(), dense, chain);
    EXPECT_NEAR(run.highestFrequency(), dense, 1e-3 * dense);
    EXPECT_NEAR(run.highestFrequency(), chain, 0.02 * chain);
  }
  {  // between two points, flex joints at both ends, extensible: the axial modes set it
    const std::string text =
        "line:\n  length: 30.0\n  elements: 15\n" + kSteelPipe + torsion + "top:\n  position: [0, 0, 0]\n" + flex +
        "bottom:\n  type: pinned\n  position: [12.0, 3.0, -25.0]\n" + flex + "initial:\n  type: between_points\n";
    Run3 run(scene(text));
    const double dense = denseOmegaMax(run);
    std::printf("[stability3] pinned, flex joints, torsion, n = 15: estimate %.6g, dense %.6g rad/s\n",
                run.highestFrequency(), dense);
    EXPECT_NEAR(run.highestFrequency(), dense, 1e-3 * dense);
  }
}

// A planar scene run through 3D has the planar line's spectrum (its transverse modes twice): the same ω_max
// as the planar estimate (2D absolute formulation, power iteration on ∂a/∂q: within 1 % of its line's
// top mode, the 3D within 1e-3; 2 % between them).
TEST(SpatialStability, PlanarSceneMatchesThePlanarEstimate) {
  for (const bool extensible : {true, false}) {
    const std::string line = "line:\n  length: 20.0\n  elements: 10\n" + kSteelPipe + "  end_mass: 50.0\n" +
                             (extensible ? "" : "  axial_flexibility: false\n");
    const Scene s2 = loadSceneText(line, "planar");
    StaticsResult statics;
    const std::unique_ptr<Simulator> planar = buildSimulator(s2, &statics);
    Run3 run(scene(line));
    std::printf("[stability3] planar scene, %s: 3D %.6g rad/s, planar %.6g rad/s\n",
                extensible ? "extensible" : "inextensible", run.highestFrequency(), planar->highestFrequency());
    EXPECT_NEAR(run.highestFrequency(), planar->highestFrequency(), 0.02 * planar->highestFrequency());
  }
}

// Steps run until `duration` or a divergence; returns whether it ran through.
bool runs(Run3& run, double duration) {
  const long steps = std::lround(duration / run.dt());
  for (long k = 0; k < steps; ++k)
    if (!run.step()) return false;
  return true;
}

// rk4 at 0.8x the estimate runs 3 s (the swing released 4 m to the side; the motion changes the tension);
// at 1.5x (1.35x the raw limit, beyond the 0.99-1.07x measured) it stops early, naming the limit and a
// safe step. Extensible (axial modes), inextensible with torsion and a flex joint, pinned between points.
TEST(SpatialStability, Rk4RunsBelowTheEstimateAndStopsAbove) {
  const std::string torsion = "  torsion:\n    stiffness: 3.0e4\n";
  const std::string flex = "  flex_joint:\n    stiffness: 5.0e4\n    damping: 1.0e3\n";
  const std::vector<std::pair<const char*, std::string>> cases = {
      {"extensible", hangingPipe(10, true, "", kRelease)},
      {"torsion + flex joint", hangingPipe(20, false, torsion, flex + kRelease)},
      {"pinned", "line:\n  length: 30.0\n  elements: 15\n" + kSteelPipe + "  axial_flexibility: false\n" +
                     "top:\n  position: [0, 0, 0]\n  motion:\n    type: sinusoid\n    amplitude: [0, 0, 0.5]\n"
                     "    period: 6.0\n" +
                     flex + "bottom:\n  type: pinned\n  position: [12.0, 0.0, -25.0]\n" + flex +
                     "initial:\n  type: between_points\n"}};
  for (const auto& [label, text] : cases) {
    const double limit = Run3(scene(text + "solver:\n  dt: 1.0e-4\n")).stableStepEstimate();
    const auto at = [&](double factor) {
      char dt[96];
      std::snprintf(dt, sizeof(dt), "solver:\n  dt: %.9g\n  integrator: rk4\n", factor * limit);
      return scene(text + dt);
    };
    Run3 below(at(0.8));
    EXPECT_TRUE(runs(below, 3.0)) << label << " at 0.8x: " << below.divergenceReason();
    EXPECT_TRUE(below.stepAboveLimit().empty()) << below.stepAboveLimit();
    Run3 above(at(1.5));
    EXPECT_NE(above.stepAboveLimit().find("a safe solver.dt is"), std::string::npos) << label;
    EXPECT_FALSE(runs(above, 3.0)) << label << " at 1.5x ran through";
    EXPECT_LT(above.steps(), 3.0 / above.dt()) << label;
    const std::string& why = above.divergenceReason();
    EXPECT_NE(why.find("reduce solver.dt"), std::string::npos) << why;
    EXPECT_NE(why.find("stability limit h ~"), std::string::npos) << why;
    std::printf("[stability3] %s: limit %.4g s; 0.8x ran 3 s; 1.5x stopped at step %ld\n", label, limit, above.steps());
  }
}

// Forces the step does not resolve say so in 3D too. A steel line (axial modes ~1e4 rad/s) starting
// straight at 80° below the horizontal, unstretched: it drops into its stretch and its axial modes ring
// with an amplitude of the order of its tension. Midpoint at 20 ms keeps them undamped, aliased into the
// tension step to step: noise far above the 5 % bound (measured 0.74; a Nyquist tone of amplitude a on a
// force of RMS T gives 4a/√6/T: 0.3 is a ringing of 20 % of the tension at least). generalized_alpha at
// ρ∞ = 0 damps them in a step: measured 0.005, below 3 % (what the planar test holds its resolved run to).
// Both close the energy balance within 1e-4 of m g L, so only the force estimate tells them apart.
TEST(SpatialStability, ForceNoiseWarnsWhenTheAxialModesRing) {
  const std::string base = hangingPipe(20, true) + "initial:\n  type: straight\n  angle: -80\n";
  const auto run10s = [&](const std::string& solver) {
    Run3 run(scene(base + "solver:\n  dt: 0.02\n" + solver));
    EXPECT_TRUE(runs(run, 10.0)) << run.divergenceReason();
    EXPECT_LT(std::abs(run.energyDrift()), 1e-4);
    return run.forceNoise().total();
  };
  const ForceNoise noisy = run10s("  integrator: midpoint\n");
  const ForceNoise clean = run10s("  integrator: generalized_alpha\n  rho_inf: 0.0\n");
  std::printf(
      "[stability3] force noise, midpoint 20 ms: top %.3g, axial %.3g; generalized_alpha rho_inf 0: %.3g, %.3g\n",
      noisy.top, noisy.max_axial, clean.top, clean.max_axial);
  EXPECT_GT(noisy.top, 0.3);
  EXPECT_GT(noisy.max_axial, 0.3);
  EXPECT_LT(clean.worst(), 0.03);
  Run3 run(scene(base + "solver:\n  dt: 0.02\n  integrator: midpoint\n"));
  runs(run, 1.0);
  EXPECT_NE(run.forceWarning(run.forceNoise().total()).find("use solver.integrator generalized_alpha"),
            std::string::npos);
}

}  // namespace
}  // namespace riser_sim
