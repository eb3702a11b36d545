// Added mass in 3D, across and along the line (hydrodynamics.inertia_coefficient C_M, axial_added_mass C_a,t),
// and the Froude-Krylov force on both components:
// - each rfe's block and velocity term against their definition Σ J_cᵀ T J_c, J_cᵀ T (∂(J_c u')/∂q) u'
//   (pointJacobian, finite differences), on random states crossing the surface;
// - the closed-form per-rfe solve against the dense one;
// - the independent-coordinate formulation against the natural one (different assembly, same physics);
// - a planar sea with added mass yawed into 3D against the planar core (its own HydroInertia);
// - the energy balance with the added mass's kinetic energy and power, out of every plane;
// - small oscillations under water: the axial modes scale by sqrt(μ/(μ + C_a,t ρ A)) exactly, the transverse
//   pairs sit at the planar modes with their added mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "riser_sim/planar/forces/hydro_inertia.h"
#include "riser_sim/planar/modal.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/simulator.h"
#include "riser_sim/spatial/forces/added_mass.h"
#include "riser_sim/spatial/forces/froude_krylov.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_force_checks.h"
#include "spatial_independent_util.h"
#include "spatial_sea_scenes.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kCaNormal = 1.0, kCaAxial = 0.5;  // C_M = 2 (the paper's), C_a,t a typical axial value

WaterSpec water(double surface) {
  WaterSpec w;
  w.enabled = true;
  w.surface = surface;
  w.current.velocity = Vec3(0.4, -0.3, 0.0);
  w.current.acceleration = Vec3(0.05, 0.03, 0.0);  // the water accelerates: Froude-Krylov acts
  return w;
}

std::shared_ptr<Model3> wetModel(int segments, double surface, bool fk) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = segments;
  s.props.outer_diameter = 0.3;
  auto m = spatial_test::spatialModel(s, Vec3(0.0, 0.0, -s.g));
  const Water3 w(water(surface), m->gravity());
  m->addTerm(std::make_unique<AddedMass>(w, kCaNormal, kCaAxial));
  if (fk) m->addTerm(std::make_unique<FroudeKrylov>(w, 1.0 + kCaNormal, 1.0 + kCaAxial));
  return m;
}

// The block against Σ_c m_w J_cᵀ T J_c and h against Σ_c m_w J_cᵀ T (J_c' u'), J_c' u' by central differences of
// J_c(q) u' along q + ε u' (all parts, random states whose parts cross the surface). Bound 1e-9 of the largest
// entry (differences: ε² ~ 1e-10 relative).
TEST(SpatialAddedMass, BlockAndVelocityTermAgainstTheirDefinition) {
  auto m = wetModel(5, -4.0, false);
  const Water3 w(water(-4.0), m->gravity());
  const AddedMass term(w, kCaNormal, kCaAxial);
  const double rhoA = w.spec().density * m->line().line().externalArea();
  std::mt19937 rng(11);
  const NaturalFormulation f(*m, 50.0);
  int wet = 0, dry = 0;
  double worst_M = 0.0, worst_h = 0.0;
  for (int trial = 0; trial < 4; ++trial) {
    Kinematics3 kin(m->bodies());
    f.kinematics(spatial_test::randomState(*m, rng, true), kin);
    std::vector<AddedMass3> added(m->bodies());
    term.addInertia(*m, kin, added);
    for (int i = 0; i < m->bodies(); ++i) {
      const BodyKinematics3& b = kin[i];
      Mat7 M = Mat7::Zero(), Mref = Mat7::Zero();
      addAddedMassBlock(added[i], b, true, M);
      Vec7 h = Vec7::Zero(), href = Vec7::Zero();
      addAddedVelocityTerms(added[i], b, h.data());
      const Vec3 n = b.e.normalized();
      const Mat3 T = kCaNormal * (Mat3::Identity() - n * n.transpose()) + kCaAxial * n * n.transpose();
      for (int p = 0; p < 2; ++p) {
        const WetPart3 wp = wetPart3(m->line(), b, i, p, w);
        (wp.length > 0.0 ? wet : dry)++;
        if (!(wp.length > 0.0)) continue;
        const auto J = pointJacobian(b, wp.s0, wp.kappa);
        Mref += rhoA * wp.length * J.transpose() * T * J;
        Vec7 u;
        u << b.A_dot, b.delta_dot, b.e_dot;
        const double eps = 1e-3;  // J_c is linear in q: central differences are exact but for round-off
        BodyKinematics3 bp = b, bm = b;
        bp.A += eps * b.A_dot, bp.delta += eps * b.delta_dot, bp.e += eps * b.e_dot;
        bm.A -= eps * b.A_dot, bm.delta -= eps * b.delta_dot, bm.e -= eps * b.e_dot;
        const Vec3 Jd_u = (pointJacobian(bp, wp.s0, wp.kappa) * u - pointJacobian(bm, wp.s0, wp.kappa) * u) / (2 * eps);
        href += rhoA * wp.length * J.transpose() * T * Jd_u;
      }
      worst_M = std::max(worst_M, (M - Mref).cwiseAbs().maxCoeff() / std::max(1.0, Mref.cwiseAbs().maxCoeff()));
      worst_h = std::max(worst_h, (h - href).cwiseAbs().maxCoeff() / std::max(1.0, href.cwiseAbs().maxCoeff()));
    }
  }
  EXPECT_GT(wet, 0);
  EXPECT_GT(dry, 0);
  EXPECT_LT(worst_M, 1e-12);
  EXPECT_LT(worst_h, 1e-9);
  std::printf(
      "[ measured ] added-mass block vs Σ J_cᵀ T J_c: %.1e, velocity term vs differences: %.1e (%d wet, %d dry "
      "parts)\n",
      worst_M, worst_h, wet, dry);
}

// The closed-form per-rfe inverse (the mass split along and across e) against the dense 7x7 Cholesky, with the
// added mass making the split anisotropic: equal to round-off (bound 1e-10 of the largest |u''|).
TEST(SpatialAddedMass, ClosedFormEqualsDense) {
  for (bool pinned : {false, true}) {
    auto m = wetModel(6, -3.0, true);
    if (pinned) m->setBottom(BottomBoundary::kPinned, Vec3(1.0, 0.5, -9.0));
    NaturalFormulation closed(*m, 50.0, true), dense(*m, 50.0, false);
    auto dc = closed.makeData(), dd = dense.makeData();
    std::mt19937 rng(5 + pinned);
    const PointMotion3 top{Vec3(0.01, 0.02, -0.01), Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5)};
    double worst = 0.0;
    for (int trial = 0; trial < 5; ++trial) {
      const VecX y = spatial_test::randomState(*m, rng, true);
      VecX f1 = VecX::Zero(y.size()), f2 = VecX::Zero(y.size());
      closed.derivative(0.3, y, top, f1, *dc);
      dense.derivative(0.3, y, top, f2, *dd);
      worst = std::max(worst, (f1 - f2).cwiseAbs().maxCoeff() / f1.cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-10);
    std::printf("[ measured ] added mass, closed form vs dense (pinned %d): %.1e of max |u''|\n", pinned, worst);
  }
}

// The natural (directors, joint multipliers) and the independent (charts, no multipliers) formulations with the
// added mass and Froude-Krylov force, fully submerged, the top oscillating in 3D: rk4 at h = 1e-4 s over 2 s.
// Bound 1e-9 m as between the dry formulations (test_spatial_independent: truncation, 16x per halving).
TEST(SpatialAddedMass, IndependentFormulationAgrees) {
  auto m = wetModel(8, 100.0, true);
  std::vector<Vec3> dirs;
  for (int i = 0; i < m->bodies(); ++i) dirs.push_back(Vec3(0.4 + 0.05 * i, 0.3 - 0.08 * i, -1.0).normalized());
  const Kinematics3 kin0 = rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
  auto top = [] {
    return std::make_unique<spatial_test::OscillatingTop>(Vec3(0.5, 0.4, 0.2),
                                                          Vec3(2 * M_PI / 2.0, 2 * M_PI / 1.3, M_PI));
  };
  Simulator3 nat(m, top(), IntegratorKind::kRk4);
  IndependentSimulator3 ind(m, top(), IntegratorKind::kRk4);
  nat.reset(kin0, 0.0);
  ind.reset(kin0, 0.0);
  AlignedVector<Vec3> pn(m->bodies() + 1), pi(m->bodies() + 1);
  double worst = 0.0, energy = 0.0, dry_gap = 0.0;
  const double h = 1e-4;
  for (int k = 1; k <= 20000; ++k) {
    ASSERT_TRUE(nat.step(h));
    ASSERT_TRUE(ind.step(h));
    if (k % 500) continue;
    nat.positions(pn);
    ind.positions(pi);
    for (size_t i = 0; i < pn.size(); ++i) worst = std::max(worst, (pn[i] - pi[i]).norm());
    energy = std::max(energy, std::abs(nat.energy() - ind.energy()));
  }
  // The check sees the added mass: the same run dry ends metres away.
  auto dry = spatial_test::spatialModel(
      [] {
        spatial_test::LineSpec s = spatial_test::flexibleLine();
        s.segments = 8;
        s.props.outer_diameter = 0.3;
        return s;
      }(),
      Vec3(0.0, 0.0, -9.81));
  Simulator3 drysim(dry, top(), IntegratorKind::kRk4);
  drysim.reset(kin0, 0.0);
  for (int k = 0; k < 20000; ++k) ASSERT_TRUE(drysim.step(h));
  AlignedVector<Vec3> pd(m->bodies() + 1);
  drysim.positions(pd);
  dry_gap = (pd.back() - pn.back()).norm();
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(dry_gap, 0.05);
  std::printf(
      "[ measured ] added mass + Froude-Krylov, independent vs natural: %.2e m, energy %.2e J; the dry run "
      "ends %.3g m away\n",
      worst, energy, dry_gap);
}

// Small oscillations of a line hanging fully under still water (added mass only, no end mass), against the dry
// line and the planar modal analysis with the planar HydroInertia's added mass:
// - axial modes: the straight line's axial motion carries each part's mass and its axial added mass, both
//   proportional to the part's length, and the stiffness is the dry one (the added mass has no force): ω scales
//   by sqrt(μ/(μ + C_a,t ρ A)) exactly (bound 1e-9, the eigen-solve's round-off);
// - transverse modes: degenerate pairs at the planar modes with C_M, the axial ones at the planar ones with C_a,t
//   (bound 1e-9 as the dry pairs, test_spatial_modal), and near the continuum's sqrt(μ/(μ + C_a,n ρ A)) (bound 1 %: the
//   lumped added mass has no rotary inertia, the structure's parts do).
TEST(SpatialAddedMass, ModesUnderWater) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = 10;
  s.end_mass = 0.0;
  s.props.outer_diameter = 0.3;
  WaterSpec still;
  still.enabled = true;
  still.surface = 100.0;
  auto dry = spatial_test::spatialModel(s, Vec3(0.0, 0.0, -s.g));
  auto wet = spatial_test::spatialModel(s, Vec3(0.0, 0.0, -s.g));
  wet->addTerm(std::make_unique<AddedMass>(Water3(still, wet->gravity()), kCaNormal, kCaAxial));
  const std::vector<Vec3> down(dry->bodies(), Vec3(0.0, 0.0, -1.0));
  const Kinematics3 eq = equilibrium3(*dry, rigidChain(dry->line(), Vec3::Zero(), down, Vec3::Zero(), Vec3::Zero()));
  const ModalResult3 rd = computeModes3(*dry, eq), rw = computeModes3(*wet, eq);
  const double mu = s.props.mass_per_length, rhoA = still.density * M_PI * 0.25 * 0.3 * 0.3;
  std::vector<double> ad, aw, tw, td;
  for (const auto& m : rd.modes) (m.axial ? ad : td).push_back(m.omega);
  for (const auto& m : rw.modes) (m.axial ? aw : tw).push_back(m.omega);
  ASSERT_EQ(ad.size(), aw.size());
  ASSERT_EQ(ad.size(), size_t(dry->bodies()));
  double axial = 0.0;
  for (size_t k = 0; k < ad.size(); ++k)
    axial = std::max(axial, std::abs(aw[k] / ad[k] / std::sqrt(mu / (mu + kCaAxial * rhoA)) - 1.0));
  EXPECT_LT(axial, 1e-9);

  // The planar line at the same equilibrium with its added mass.
  auto m2 = spatial_test::planarModel(s);
  m2->addTerm(std::make_unique<HydroInertia>(WaterKinematics(still, s.g), 1.0 + kCaNormal, kCaAxial));
  const Kinematics kin2 = spatial_test::planarHanging(eq);
  ModalOptions o;
  o.modes = 2 * m2->bodies();
  std::vector<double> t2, a2;
  for (const auto& m : computeModes(*m2, kin2, Vec2::Zero(), o).modes) {
    if (m.character == "axial")
      a2.push_back(m.omega);
    else
      t2.push_back(m.omega), t2.push_back(m.omega);
  }
  std::sort(t2.begin(), t2.end());
  ASSERT_EQ(t2.size(), tw.size());
  ASSERT_EQ(a2.size(), aw.size());
  double pairs = 0.0;
  for (size_t k = 0; k < tw.size(); ++k) pairs = std::max(pairs, std::abs(tw[k] / t2[k] - 1.0));
  for (size_t k = 0; k < aw.size(); ++k) pairs = std::max(pairs, std::abs(aw[k] / a2[k] - 1.0));  // the planar C_a,t
  EXPECT_LT(pairs, 1e-9);
  const double lowest = tw[0] / td[0] / std::sqrt(mu / (mu + kCaNormal * rhoA)) - 1.0;
  EXPECT_LT(std::abs(lowest), 0.01);
  std::printf(
      "[ measured ] modes under water: axial ω ratio vs sqrt(μ/(μ + C_a,t ρA)) %.1e; transverse (pairs) "
      "and axial vs planar %.1e; lowest transverse ratio vs the continuum's %.2e (ω %.4f wet, %.4f dry rad/s)\n",
      axial, pairs, lowest, tw[0], td[0]);
}

// The 60 m sea line (spatial_sea_scenes.h) with the hydrodynamic inertia across (C_M = 2) and along it
// (C_a,t = 0.5); later sets override.
Scene inertiaScene(const std::string& rest, std::vector<std::string> sets = {}) {
  sets.insert(sets.begin(), {"hydrodynamics.inertia_coefficient=2", "hydrodynamics.axial_added_mass=0.5"});
  return loadSceneText(std::string(spatial_test::kSeaLine) + rest, "added_mass", sets);
}

// A planar sea (current profile, ramped waves, a top crossing the surface and moving) with C_M = 2 and
// C_a,t = 0.5, yawed by 35 deg into 3D, against the planar core: 1e-9 m at h = 1e-3 s over 4 s (the two cores'
// rk4 truncation differs: ~16x per halving, as the dry sea of test_spatial_sea).
TEST(SpatialAddedMass, YawedPlanarSeaMatchesThePlanarCore) {
  const double psi = 35.0;
  const spatial_test::YawedSea sea = spatial_test::yawedSea(psi);
  const std::string sea2 = sea.planar;
  double worst[2] = {0.0, 0.0}, dry_gap = 0.0;
  for (int r = 0; r < 2; ++r) {
    const std::vector<std::string> dt = {r == 0 ? "solver.dt=0.002" : "solver.dt=0.001"};
    riser_sim::Run planar = buildRun(inertiaScene(sea2, dt));
    Run3 run(inertiaScene(sea.spatial, dt));
    worst[r] = spatial_test::planarVs3D(planar, run, spatial_test::yawDeg(psi), 4.0);
    const long steps = std::lround(4.0 / run.dt());
    Kinematics kin2(planar.model->bodies());
    planar.sim->kinematics(kin2);
    if (r == 1) {  // the same planar run without the hydrodynamic inertia ends visibly elsewhere
      riser_sim::Run bare = buildRun(inertiaScene(
          sea2, {"solver.dt=0.001", "hydrodynamics.inertia_coefficient=1", "hydrodynamics.axial_added_mass=0"}));
      for (long k = 0; k < steps; ++k) ASSERT_TRUE(bare.sim->step());
      Kinematics kb(bare.model->bodies());
      bare.sim->kinematics(kb);
      dry_gap = (kb.back().end() - kin2.back().end()).norm();
    }
  }
  EXPECT_LE(worst[1], 1e-9);
  EXPECT_GT(worst[0] / worst[1], 8.0);
  EXPECT_GT(dry_gap, 1e-3);
  std::printf(
      "[ measured ] planar sea with added mass yawed %g deg through 3D vs the planar core, 4 s: %.2e m (h = 2e-3 "
      "s), %.2e m (1e-3 s); C_M = 1, C_a,t = 0 moves the end by %.3g m\n",
      psi, worst[0], worst[1], dry_gap);
}

// Fully submerged (the top 5 m down), waves towards 60 deg across the current's plane and the top circling: E - E0 - W
// with the added mass's kinetic energy in E and its power (T turning with e) and the Froude-Krylov power in W stays at
// rk4's truncation level (16x per halving; bound 1e-6 of m g L as the dry sea's).
TEST(SpatialAddedMass, EnergyBalanceOutOfPlane) {
  const std::string sea = R"(space: spatial
top:
  position: [0.0, 0.0, -5.0]
  motion: {type: sinusoid, amplitude: [1.0, 1.0, 0.3], period: 5.0}
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {velocity: [0.3, -0.2, 0.0]}
  waves: {height: 3.0, period: 6.0, depth: 150.0, ramp: 1.0, heading: 60.0}
)";
  double drift[2];
  for (int r = 0; r < 2; ++r) {
    Scene sc = inertiaScene(sea);
    sc.solver.dt = r == 0 ? 0.01 : 0.005;
    Run3 run(sc);
    double worst = 0.0;
    for (long k = 0; k < std::lround(3.0 / sc.solver.dt); ++k) {
      ASSERT_TRUE(run.step()) << run.divergenceReason();
      worst = std::max(worst, std::abs(run.energyDrift()));
    }
    EXPECT_GT(std::abs(run.outputs().points.back().y()), 0.2);
    drift[r] = worst;
  }
  EXPECT_LE(drift[1], 1e-6);
  EXPECT_GT(drift[0] / drift[1], 8.0);
  std::printf("[ measured ] added mass energy balance |E - E0 - W| / m g L: %.2e (h = 0.01 s), %.2e (0.005 s)\n",
              drift[0], drift[1]);
}

}  // namespace
}  // namespace riser_sim
