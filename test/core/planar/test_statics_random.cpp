// Property test of the statics over random legal scenes (fixed seed): small lines with random seabed
// level and stiffness, current, waves, pinned ends, displaced ends and end masses. Each statics solve
// either fails with a reason (a non-empty message naming what failed) or returns a state that passes
// checkEquilibrium() and that a 1 s rk4 run at 0.8x the stable step keeps finite; where nothing moves
// the line (no current, no waves, the end held), the run must also stay at rest.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/statics.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

struct RandomScene {
  std::string yaml;
  bool quiet = true;  // nothing drives the line: it must stay at rest
};

RandomScene randomScene(std::mt19937& rng) {
  auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto chance = [&](double p) { return U(0.0, 1.0) < p; };
  RandomScene r;
  std::ostringstream y;
  const double L = U(5.0, 40.0);
  const int n = 4 + static_cast<int>(U(0.0, 11.0));
  const bool water = chance(0.5), axial = chance(0.5);
  double line_mass;
  y << "name: random\nline:\n  length: " << L << "\n  elements: " << n << "\n";
  if (water || chance(0.5)) {  // steel pipe
    const double D = U(0.05, 0.3), Di = D * U(0.0, 0.8);
    line_mass = 7850.0 * M_PI / 4.0 * (D * D - Di * Di) * L;
    y << "  outer_diameter: " << D << "\n  inner_diameter: " << Di << "\n  youngs_modulus: 2.07e11\n"
      << "  density: 7850\n  bending: " << (chance(0.7) ? "true" : "false") << "\n";
  } else {  // chain
    const double mpl = U(1.0, 20.0);
    line_mass = mpl * L;
    y << "  mass_per_length: " << mpl << "\n  EA: " << std::exp(U(std::log(1e5), std::log(1e8)))
      << "\n  EI: 0\n  bending: false\n";
  }
  y << "  axial_flexibility: " << (axial ? "true" : "false") << "\n";
  y << "  end_mass: " << (chance(0.5) ? U(0.0, 5.0) * line_mass : 0.0) << "\n";
  y << "top:\n  position: [0, 0]\n";
  const bool seabed = chance(0.6);
  const double level = -L * U(0.3, 1.2);
  const double kind = U(0.0, 1.0);
  if (kind < 0.4) {
    y << "initial:\n  type: hanging\n";
  } else if (kind < 0.7) {
    const bool hold = chance(0.5);
    y << "initial:\n  type: displaced\n  end_dx: " << (chance(0.5) ? -1.0 : 1.0) * U(0.2, 0.9) * L
      << "\n  end_force: " << (hold ? "hold" : "release") << "\n";
    r.quiet = hold;
  } else {
    const double reach = U(0.0, 0.95) * L, angle = U(-M_PI, 0.0);
    double ax = reach * std::cos(angle), ay = reach * std::sin(angle);
    if (seabed && chance(0.5)) ay = level;  // on the seabed
    if (!axial && std::hypot(ax, ay) > 0.95 * L) ax = 0.0, ay = -0.9 * L;
    y << "bottom:\n  type: pinned\n  position: [" << ax << ", " << ay << "]\ninitial:\n  type: between_points\n";
  }
  if (water) {
    y << "environment:\n  water: {density: 1025, surface: " << U(-0.2 * L, 2.0) << "}\n";
    if (chance(0.5)) {
      y << "  current: {velocity: [" << U(-1.5, 1.5) << ", 0]}\n";
      r.quiet = false;
    }
    if (chance(0.4)) {
      const double depth = chance(0.5) ? 1000.0 : (chance(0.5) ? 60.0 : 15000.0);
      y << "  waves: {height: " << U(0.5, 4.0) << ", period: " << U(2.0, 12.0) << ", depth: " << depth
        << (chance(0.5) ? ", ramp: 5" : "") << "}\n";
      r.quiet = false;
    }
    y << "hydrodynamics: {drag_normal: " << U(0.7, 1.2) << ", inertia_coefficient: " << U(1.0, 2.0) << "}\n";
  }
  if (seabed)
    y << "seabed: {level: " << level << ", stiffness_normal: " << std::exp(U(std::log(1e3), std::log(1e7))) << "}\n";
  r.yaml = y.str();
  return r;
}

TEST(StaticsRandom, SolvedStatesPassTheChecksOrFailWithAReason) {
  std::mt19937 rng(20240611);
  int solved = 0, refused = 0;
  for (int k = 0; k < 80; ++k) {
    const RandomScene rs = randomScene(rng);
    SCOPED_TRACE("scene " + std::to_string(k) + ":\n" + rs.yaml);
    Scene s = loadSceneText(rs.yaml, "random");
    StaticsResult st;
    std::unique_ptr<Simulator> sim;
    try {
      sim = buildSimulator(s, &st);
    } catch (const std::exception& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("initial: ", 0), 0u) << what;
      EXPECT_GT(what.size(), 30u) << what;
      ++refused;
      std::printf("[random statics] scene %d refused: %.160s...\n", k, what.c_str());
      continue;
    }
    ++solved;
    auto model = buildModel(s);
    const EquilibriumCheck check = checkEquilibrium(*model, staticsProblem(s), st.kin, st.end_force);
    EXPECT_TRUE(check.ok) << check.message;
    // 1 s of rk4 at 0.8x its stable step.
    s.solver.integrator = IntegratorKind::kRk4;
    s.solver.dt = 0.8 * sim->stableStepEstimate();
    sim = buildSimulator(s);
    const AlignedVector<Vec2> start = sim->outputs().points;
    ASSERT_TRUE(sim->advanceTo(1.0)) << sim->divergenceReason();
    const LineOutputs& o = sim->outputs();
    EXPECT_TRUE(allFinite(o));
    if (rs.quiet) {  // at rest: nothing moved by more than 1e-3 L (a wrong or unstable state falls away)
      double moved = 0.0;
      for (size_t i = 0; i < start.size(); ++i) moved = std::max(moved, (o.points[i] - start[i]).norm());
      EXPECT_LT(moved, 1e-3 * s.length);
    }
  }
  std::printf("[random statics] %d solved, %d refused with a reason\n", solved, refused);
  EXPECT_GE(solved, 60);  // the property is not vacuous
}

}  // namespace
}  // namespace riser_sim
