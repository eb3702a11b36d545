// RangeGraph (range_graph.h): the min/max envelopes along the line over a run. A line at rest keeps its
// static profile (min == max == the profile); the static profile itself against independent references: a
// vertical chain's tension in water T(s) = w (L - s) + m_s g, and a catenary's curvature against the elastic
// catenary's κ = w H / (T² (1 + T/EA)); add() allocates nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "alloc_counter.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

Scene scene(const std::string& file, const std::vector<std::string>& overrides = {}) {
  return loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/" + file, overrides);
}

// A 100 m chain (EI 0) of 20 kg/m, D 0.1 m, with a 50 kg end mass, hanging at rest in water, n rfes.
std::vector<std::string> chainInWater(int n) {
  return {"line.length=100.0",
          "line.elements=" + std::to_string(n),
          "line.EA=1.0e8",
          "line.mass_per_length=20.0",
          "line.end_mass=50.0",
          "line.outer_diameter=0.1",
          "environment.water={density: 1025.0, surface: 10.0}",
          "initial={type: hanging}",
          "solver.dt=1.0e-4"};
}

// A chain in air pinned at (0, 0) and (60, -50), 100 m long: a catenary with its vertex inside the span.
std::vector<std::string> catenary(int n) {
  return {"line.length=100.0",
          "line.elements=" + std::to_string(n),
          "line.EA=1.0e6",
          "line.mass_per_length=2.0",
          "line.end_mass=0.0",
          "bottom={type: pinned, position: [60.0, -50.0]}",
          "initial={type: between_points}"};
}

TEST(RangeGraph, LineAtRestKeepsItsStaticProfile) {
  // A hanging equilibrium stepped 2000 steps: nothing moves it, so every envelope stays on the static profile.
  // Bound: the statics' residual (initial.tolerance 1e-9 of the weight) starts a motion of that relative size;
  // 1e-7 of the top tension (and of the largest |M| and κ) leaves two decades for the integrator's round-off.
  for (const auto& [file, over] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"hanging_chain.yaml", chainInWater(10)},
           {"demo_riser_3d.yaml", {"environment.waves=null", "environment.current=null"}}}) {
    SCOPED_TRACE(file);
    auto run = buildLineRun(scene(file, over));
    const RunOutputs start = run->outputs();
    RangeGraph g(start, seabedPlane(scene(file, over)));
    const int steps = file == "hanging_chain.yaml" ? 2000 : 100;
    for (int k = 0; k < steps; ++k) {
      ASSERT_TRUE(run->step()) << run->divergenceReason();
      g.add(run->outputs());
    }
    EXPECT_EQ(g.samples(), steps + 1);
    const double T = start.top_tension;
    double M = 1e-12, kappa = 1e-12;
    for (size_t j = 0; j < start.curvature.size(); ++j) {
      M = std::max(M, std::abs(start.bending_moment[j]));
      kappa = std::max(kappa, start.curvature[j]);
    }
    for (size_t i = 0; i < g.stations().size(); ++i) {
      EXPECT_NEAR(g.tension().min[i], start.axial_force[i], 1e-7 * T) << "rfe " << i;
      EXPECT_NEAR(g.tension().max[i], start.axial_force[i], 1e-7 * T) << "rfe " << i;
      EXPECT_LE(g.tension().min[i], start.axial_force[i]);
      EXPECT_GE(g.tension().max[i], start.axial_force[i]);
    }
    for (size_t j = 0; j < g.jointStations().size(); ++j) {
      EXPECT_NEAR(g.moment().min[j], start.bending_moment[j], 1e-7 * M) << "joint " << j;
      EXPECT_NEAR(g.moment().max[j], start.bending_moment[j], 1e-7 * M) << "joint " << j;
      EXPECT_NEAR(g.curvature().min[j], start.curvature[j], 1e-7 * kappa) << "joint " << j;
      EXPECT_NEAR(g.curvature().max[j], start.curvature[j], 1e-7 * kappa) << "joint " << j;
    }
    if (g.hasSeabed()) {  // demo_riser_3d: 150 m to an anchor 128 m away, its last ~30 m on the seabed
      ASSERT_EQ(g.touchdownSamples(), steps + 1);
      EXPECT_EQ(g.touchdownMin(), g.touchdownMax());
      EXPECT_GT(g.touchdownMin(), 100.0);
      EXPECT_LT(g.touchdownMin(), 140.0);
      for (size_t i = 0; i < g.stations().size(); ++i) EXPECT_NEAR(g.clearance().max[i], g.clearance().min[i], 1e-6);
    }
  }
}

TEST(RangeGraph, HangingChainTensionIsItsWetWeightBelow) {
  // Vertical chain in water: the axial force at unstretched arc length s carries the wet weight of the line
  // below, w (L - s), and the end mass, m_s g (a point mass: no displaced volume). w = (m - ρ_w π D²/4) g.
  const double g0 = 9.81, L = 100.0, m = 20.0, D = 0.1, rho = 1025.0, ms = 50.0;
  const double w = (m - rho * kPi * D * D / 4.0) * g0;
  for (const int n : {10, 40}) {
    const Scene sc = scene("hanging_chain.yaml", chainInWater(n));
    auto run = buildLineRun(sc);
    const RangeGraph g(run->outputs(), seabedPlane(sc));
    ASSERT_EQ(g.stations().size(), static_cast<size_t>(n + 1));
    // Rfe i's axial force is the one at its middle, where the weight of the rfe splits evenly: the weight
    // below is exact for a uniform line at any n, and what is left is the statics' residual (initial.tolerance
    // 1e-9 of the weight; measured 4e-6 N, printed below). Bound: 1e-8 of the total load, well below the
    // w d / 2 a spring off the middle by half an rfe would show.
    double worst = 0.0;
    for (size_t i = 0; i < g.stations().size(); ++i) {
      const double s = g.stations()[i], T = w * (L - s) + ms * g0;
      worst = std::max(worst, std::abs(g.tension().max[i] - T));
      EXPECT_NEAR(g.tension().max[i], T, 1e-8 * (w * L + ms * g0)) << "n " << n << ", rfe " << i << " at s = " << s;
      EXPECT_EQ(g.tension().min[i], g.tension().max[i]);
    }
    std::printf("n = %d: largest |T - w (L - s) - m_s g| = %.3g N (w L = %.6g N)\n", n, worst, w * L);
    EXPECT_NEAR(g.tensionMaxS(), g.stations().front(), 0.0);  // the largest tension at the top
  }
}

TEST(RangeGraph, CatenaryCurvatureIsTheElasticCatenarys) {
  // Chain (EI 0) pinned at both ends in air. The elastic catenary: tan θ = V / H with V(s) = V_0 - w s along
  // the unstretched s, so |dθ/ds| = w H / T², and per stretched length κ = w H / (T² (1 + T / EA)), T = sqrt(H²
  // + V²). H and V_0 from the hang-off's force. The joints' curvature is the turn between two chords over the
  // segment, a second-order difference at the inner joints: its error falls as d², measured below at n = 20
  // and 40. The two end joints are left out: a half-length end rfe puts the chords' middles 3/4 d apart while
  // the joint divides the turn by d (their κ reads ~3/4 of the catenary's; docs/validation.md).
  const double g0 = 9.81, w = 2.0 * g0, EA = 1.0e6;
  double previous = 0.0;
  for (const int n : {20, 40}) {
    const Scene sc = scene("hanging_chain.yaml", catenary(n));
    auto run = buildLineRun(sc);
    const RunOutputs& o = run->outputs();
    const RangeGraph g(o, seabedPlane(sc));
    const double H = std::abs(o.top_force.x()), V0 = std::abs(o.top_force.z());
    double worst = 0.0;
    for (size_t j = 1; j + 1 < g.jointStations().size(); ++j) {
      const double V = V0 - w * g.jointStations()[j], T2 = H * H + V * V;
      const double kappa = w * H / (T2 * (1.0 + std::sqrt(T2) / EA));
      worst = std::max(worst, std::abs(g.curvature().max[j] - kappa) / kappa);
    }
    std::printf("n = %d: largest relative |κ - w H / (T² (1 + T/EA))| = %.3g\n", n, worst);
    EXPECT_LT(worst, 2e-2) << "n " << n;
    // Halving d: 0.34 of the error measured (second order: 0.25; first order would give 0.5).
    if (previous > 0.0) EXPECT_LT(worst, 0.42 * previous) << "faster than first order per halving of d";
    previous = worst;
    // The largest curvature is at the vertex (V = 0), where T = H is least.
    EXPECT_NEAR(g.curvatureMax(), w / H, 2e-2 * w / H);
    EXPECT_NEAR(g.curvatureMaxS(), V0 / w, 100.0 / n);
  }
}

TEST(RangeGraph, AddAndRestartAllocateNothing) {
  for (const std::string file : {"lazy_wave_riser.yaml", "spatial_swing.yaml"}) {
    SCOPED_TRACE(file);
    const Scene sc = scene(file);
    auto run = buildLineRun(sc);
    RangeGraph g(run->outputs(), seabedPlane(sc));
    ASSERT_TRUE(run->step());
    const RunOutputs& o = run->outputs();
    const long before = g_allocations.load();
    for (int k = 0; k < 20; ++k) g.add(o);
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_EQ(g.samples(), 21);
    // restart(o): the graph of o alone, as a new one built from o; it allocates nothing either.
    ASSERT_TRUE(run->step());
    const RunOutputs& o2 = run->outputs();
    const long before_restart = g_allocations.load();
    g.restart(o2);
    EXPECT_EQ(g_allocations.load() - before_restart, 0);
    const RangeGraph fresh(o2, seabedPlane(sc));
    EXPECT_EQ(g.samples(), 1);
    for (const auto& [a, b] :
         {std::make_pair(&g.tension(), &fresh.tension()), std::make_pair(&g.moment(), &fresh.moment()),
          std::make_pair(&g.curvature(), &fresh.curvature()), std::make_pair(&g.clearance(), &fresh.clearance())}) {
      EXPECT_EQ(a->min, b->min);
      EXPECT_EQ(a->max, b->max);
    }
    EXPECT_EQ(g.touchdownSamples(), fresh.touchdownSamples());
    if (fresh.touchdownSamples() > 0) EXPECT_EQ(g.touchdownMax(), fresh.touchdownMax());
  }
}

// The clearance is the height above the seabed plane along its normal: on the sloped plane of docs/scene_keys.md,
// z_b(x, y) = level + tan θ (x cos ψ + y sin ψ), a point h above z_b is h cos θ from it (θ = 10°, ψ = 30°).
TEST(RangeGraph, ClearanceAboveASlopedSeabed) {
  const Scene sc = scene("demo_riser_3d.yaml", {"seabed.slope=10.0", "seabed.slope_heading=30.0"});
  const SeabedPlane bed = seabedPlane(sc);
  ASSERT_TRUE(bed.exists);
  const double th = 10.0 * kPi / 180.0, psi = 30.0 * kPi / 180.0, level = sc.seabed.level;
  for (const Vec3& xy : {Vec3(0.0, 0.0, 0.0), Vec3(80.0, 0.0, 0.0), Vec3(-20.0, 35.0, 0.0)}) {
    const double zb = level + std::tan(th) * (xy.x() * std::cos(psi) + xy.y() * std::sin(psi));
    for (const double h : {-0.5, 0.0, 7.0}) {
      const Vec3 p(xy.x(), xy.y(), zb + h);
      EXPECT_NEAR(bed.clearance(p), h * std::cos(th), 1e-12 * (1.0 + std::abs(level) + xy.norm()));
    }
  }
  const SeabedPlane level_bed = seabedPlane(scene("demo_riser_3d.yaml"));
  EXPECT_NEAR(level_bed.clearance(Vec3(3.0, 4.0, level + 2.0)), 2.0, 1e-12);
  EXPECT_FALSE(seabedPlane(scene("hanging_chain.yaml")).exists);
}

TEST(RangeGraph, RefusesMismatchedOutputs) {
  RunOutputs o;
  o.arc_length = {0.5, 1.5};
  o.axial_force = {1.0, 1.0};
  o.points.assign(3, Vec3::Zero());
  o.bending_moment = {0.0};
  o.curvature = {0.0};
  EXPECT_NO_THROW(RangeGraph(o, SeabedPlane{}));
  o.curvature.clear();
  EXPECT_THROW(RangeGraph(o, SeabedPlane{}), std::invalid_argument);
  o.curvature = {0.0};
  o.arc_length = {0.5, 0.4};
  EXPECT_THROW(RangeGraph(o, SeabedPlane{}), std::invalid_argument);
}

}  // namespace
}  // namespace riser_sim
