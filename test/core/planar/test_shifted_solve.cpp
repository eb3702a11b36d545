// The implicit integrators' structured O(n) solves (chain_shifted_solver.h) against the dense solve
// with a finite-difference Jacobian of the equations of motion. At a static equilibrium at rest the
// structured matrix is the exact Jacobian (every term there reports its stiffness; drag and the
// velocity terms vanish at rest with their derivatives), so both solves must agree to the accuracy of
// the central differences. Away from equilibrium (displaced, moving, every hydro term) it is an
// approximation whose distance to the exact solve is bounded below. A pinned end is held by Baumgarte
// stabilisation (E'' = -2ω E' - ω² E): the structured solve must carry that row, for any right-hand side.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <random>

#include "riser_sim/planar/recursive_formulation.h"
#include "riser_sim/planar/independent_formulation.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// Central-difference steps: positions relative 1e-6 of the coordinate scale (truncation ~1e-12, round-off
// ~1e-10: the Jacobian is good to ~1e-9 relative); rates 1e-8 [1/s, m/s], because the central
// difference of the quadratic drag |v| v at v = 0 is |h|, not 0.
constexpr double kFdStep = 1e-6, kFdStepRate = 1e-8;
// Agreement of x = (I - cJ)^-1 b, relative to |x|_inf: the Jacobian's 1e-9 amplified by the conditioning
// of I - cJ (measured worst 1.9e-7: a pinned inextensible line, ω_c = 5 rad/s, c = 0.1, independent; 3e-8
// elsewhere). A wrong term is O(0.1..1) here (the pinned row held at zero gave 0.2..1.7), so 5e-7 still
// separates the two by six orders of magnitude.
constexpr double kAgree = 5e-7;

struct Case {
  const char* name;
  Scene scene;
};

// A catenary in water pinned at both ends, partly resting on the seabed, with bending.
Scene pinnedCatenary(bool axial, bool water, bool seabed, bool hydro = true, double stabilization = 50.0) {
  Scene s;
  s.length = 120.0;
  s.elements = 12;
  s.line = LineProperties::fromGeometry(0.3, 0.26, 2.07e11, 7850.0);
  s.options.axial_flexibility = axial;
  s.bottom = BottomBoundary::kPinned;
  s.top.position = Eigen::Vector3d(0.0, 0.0, -1.0);  // every rfe fully wet (the wet length's change is not linearised)
  s.bottom_point = Eigen::Vector3d(80.0, 0.0, -61.0);
  s.initial.type = InitialKind::kBetweenPoints;
  s.solver.stabilization = stabilization;
  if (water) {
    s.water.enabled = true;
    s.hydro.enabled = hydro;
    s.hydro.drag_normal = 1.0;
    s.hydro.inertia_coefficient = 2.0;
  }
  if (seabed) {
    s.seabed.enabled = true;
    s.seabed.level = -64.0;  // ~3 m of the line on the seabed
    s.seabed.stiffness_normal = 1e6;
    s.seabed.stiffness_tangential = 1e5;
    s.seabed.damping_normal = 1e3;
  }
  return s;
}

Scene hangingWithMass(bool axial) {
  Scene s = validation::table1Scene(10);
  s.options.axial_flexibility = axial;
  s.options.bending = true;
  s.line.EI = 1e4;
  s.initial.type = InitialKind::kHanging;
  return s;
}

// The paper's 170 m J-lay scene (free end on the seabed; buoyancy, drag, added mass, contents, seabed) at
// n = 12, optionally elastic.
Scene jlay(bool axial) {
  Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml");
  s.elements = 12;
  s.options.axial_flexibility = axial;
  return s;
}

// Chain rates v with the pinned end at rest: the last two φ rates absorb the end velocity.
void pinnedRates(const Formulation& f, const Model& model, const PointMotion& top, VecX y, VecX& v) {
  const int p = f.positionSize();
  Kinematics kin(model.bodies());
  auto end = [&](const VecX& w) {
    y.segment(p, p) = w;
    f.kinematics(y, top, kin);
    return Vec2(kin.back().endVelocity());
  };
  const int k = p / model.bodies(), a = p - 1, b = p - 1 - k;
  Eigen::Matrix2d G;
  VecX e = VecX::Zero(p);
  e[a] = 1.0;
  G.col(0) = end(e);
  e[a] = 0.0;
  e[b] = 1.0;
  G.col(1) = end(e);
  const Vec2 fix = G.partialPivLu().solve(-end(v));
  v[a] += fix[0];
  v[b] += fix[1];
}

// The state the solves are compared at.
enum class State {
  kEquilibrium,  // the static equilibrium at rest
  kDisplaced,    // at rest, every φ moved by up to 0.05 rad, Δ by 1e-5 m: out of equilibrium (a ≠ 0)
  kMoving,       // displaced and moving: φ' up to 0.05 rad/s, Δ' up to 1e-3 m/s
};

// Largest relative difference between the structured and the dense solve over c in {1e-4, 1e-2, 0.1}.
double compare(const char* name, Scene scene, const std::string& formulation, State state = State::kEquilibrium) {
  scene.solver.formulation = toChoice<FormulationKind>(formulation);
  StaticsResult st;
  auto sim = buildSimulator(scene, &st);
  const Model& model = sim->model();
  std::unique_ptr<Formulation> f;
  if (formulation == "recursive")
    f = std::make_unique<RecursiveFormulation>(model, scene.solver.stabilization);
  else
    f = std::make_unique<IndependentFormulation>(model, scene.solver.stabilization);
  EXPECT_TRUE(f->hasShiftedSolve());
  const std::unique_ptr<FormulationData> fd = f->makeData();
  const int p = f->positionSize(), m = 2 * p, n = static_cast<int>(sim->state().size());
  const int k = p / model.bodies();  // coordinates per rfe
  const PointMotion top = buildTopMotion(scene.top)->at(0.0);
  VecX y0 = sim->state();
  VecX dy(n), dp(n), dm(n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const bool pinned = model.bottom() == BottomBoundary::kPinned;
  if (state != State::kEquilibrium) {
    // A pinned line keeps its equilibrium positions (a displaced one would leave the anchor).
    if (!pinned)
      for (int i = 0; i < p; ++i) y0[i] += (k == 2 && i % 2 == 0 ? 1e-5 : 0.05) * u(rng);
    if (state == State::kMoving) {
      VecX v(p);
      for (int i = 0; i < p; ++i) v[i] = (k == 2 && i % 2 == 0 ? 1e-3 : 0.05) * u(rng);
      if (pinned) pinnedRates(*f, model, top, y0, v);
      y0.segment(p, p) = v;
    }
  }
  f->derivative(0.0, y0, top, dy, *fd);
  if (state == State::kEquilibrium)
    EXPECT_LT(dy.segment(p, p).cwiseAbs().maxCoeff(), 1e-6) << name << ": not at rest in equilibrium";
  else
    EXPECT_GT(dy.segment(p, p).cwiseAbs().maxCoeff(), 1e-3) << name << ": still in equilibrium";

  // Dense Jacobian of (q', v') by central differences.
  MatX J(m, m);
  const double scale = 1.0 + y0.head(p).cwiseAbs().maxCoeff();
  for (int j = 0; j < m; ++j) {
    VecX yp = y0, ym = y0;
    const double h = j < p ? kFdStep * scale : kFdStepRate;
    yp[j] += h;
    ym[j] -= h;
    f->derivative(0.0, yp, top, dp, *fd);
    f->derivative(0.0, ym, top, dm, *fd);
    J.col(j) = (dp.head(m) - dm.head(m)) / (2.0 * h);
  }
  double worst = 0.0;
  for (double c : {1e-4, 1e-2, 0.1}) {
    VecX b = VecX::Zero(n);
    for (int i = 0; i < m; ++i) b[i] = u(rng);  // pinned too: b moves the end (Newton residuals do)
    const VecX ref = (MatX::Identity(m, m) - c * J).partialPivLu().solve(b.head(m));
    f->derivative(0.0, y0, top, dy, *fd);
    f->linearize(0.0, y0, top, *fd);
    f->factorShifted(c, *fd);
    VecX x = VecX::Zero(n);
    f->solveShifted(b, x, *fd);
    EXPECT_TRUE(x.head(m).allFinite()) << name;
    const double err = (x.head(m) - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
    worst = std::max(worst, err);
    std::printf("    c = %-6g %.2e", c, err);
  }
  const char* what[] = {"equilibrium", "displaced", "moving"};
  std::printf("  <- %-32s %-11s %-11s p = %3d: worst relative difference %.2e\n", name, formulation.c_str(),
              what[int(state)], p, worst);
  return worst;
}

TEST(ShiftedSolve, MatchesDenseJacobianAtEquilibrium) {
  const Case cases[] = {
      {"hanging, end mass, elastic", hangingWithMass(true)},
      {"hanging, end mass, inext.", hangingWithMass(false)},
      {"pinned catenary, elastic", pinnedCatenary(true, false, false)},
      {"pinned catenary, inext.", pinnedCatenary(false, false, false)},
      {"pinned, water", pinnedCatenary(true, true, false)},
      {"pinned, seabed", pinnedCatenary(true, false, true)},
      {"pinned, buoyancy, seabed", pinnedCatenary(true, true, true, false)},
      {"pinned, water, seabed", pinnedCatenary(true, true, true)},
      {"pinned, water, seabed, inext.", pinnedCatenary(false, true, true)},
  };
  for (const Case& c : cases)
    for (const char* form : {"recursive", "independent"}) EXPECT_LT(compare(c.name, c.scene, form), kAgree) << c.name;
}

// Out of equilibrium at rest the accelerations are not zero, but the structured matrix is still the exact
// Jacobian: the joint forces λ in the geometric stiffness carry the inertia of the rfes below, and every
// velocity term (drag without current, the chain's Coriolis and centrifugal terms) vanishes at rest with
// its derivative. So the same bound holds, with drag, added mass, buoyancy, seabed and the internal
// fluid's mass (no flow) on.
// Away from equilibrium the structured matrix is an approximation. Left out: the terms proportional to
// the accelerations (Jᵀ M (∂J/∂θ) θ'' and (∂M/∂θ) q'': the absolute accelerations turn with the chain),
// the velocity terms (the chain's Coriolis and centrifugal terms, drag damping) and the internal flow.
// rosenbrock2 keeps its order with any matrix (a W-method); the midpoint rule's Newton then converges
// linearly at a rate ~ this difference, so it must stay well below 1 over c = 1e-4..0.1 (h up to 0.2 s).
// Measured worst: 0.33, the inextensible line whipping a 1000 kg end mass 0.05 rad out of equilibrium
// (c = 0.01; the left-out terms there are as large as the geometric stiffness); the J-lay scene with every
// hydro term 0.03, with drag coefficient 10 0.21. kAwayBound = 0.5: Newton still gains 3 digits in 10
// iterations at worst.
constexpr double kAwayBound = 0.5;

// The pinned end's row for Baumgarte frequencies from none to stiff (ω c up to 50): the increment's end
// motion is G x_v = (G b_v - ω² c G b_q) / (1 + ω c)², not 0.
TEST(ShiftedSolve, PinnedEndFollowsBaumgarteRow) {
  for (double w : {0.0, 5.0, 50.0, 500.0})
    for (bool axial : {true, false}) {
      char name[64];
      std::snprintf(name, sizeof(name), "pinned, omega_c %g%s", w, axial ? "" : ", inext.");
      for (const char* form : {"recursive", "independent"})
        EXPECT_LT(compare(name, pinnedCatenary(axial, false, false, true, w), form), kAgree) << name;
    }
}

TEST(ShiftedSolve, CloseToDenseJacobianDisplacedAtRest) {
  const Case cases[] = {
      {"hanging, end mass, elastic", hangingWithMass(true)},
      {"hanging, end mass, inext.", hangingWithMass(false)},
      {"J-lay, elastic", jlay(true)},
      {"J-lay, inext.", jlay(false)},
  };
  for (const Case& c : cases)
    for (const char* form : {"recursive", "independent"})
      EXPECT_LT(compare(c.name, c.scene, form, State::kDisplaced), kAwayBound) << c.name;
}

// In motion, with every hydro term: drag (up to coefficient 10, with a current), added mass, buoyancy,
// the contents' mass and a 10 m/s internal flow, seabed contact.
TEST(ShiftedSolve, CloseToDenseJacobianInMotionWithHydroTerms) {
  Scene flow = jlay(true);
  flow.internal_fluid.velocity = 10.0;  // flow term: no stiffness reported
  Scene drag10 = jlay(true);
  drag10.hydro.drag_normal = 10.0;
  drag10.hydro.drag_tangential = 1.0;
  Scene current = jlay(true);
  current.water.current.velocity = Eigen::Vector3d(1.0, 0.0, 0.0);
  const Case cases[] = {
      {"hanging, end mass, elastic", hangingWithMass(true)},
      {"hanging, end mass, inext.", hangingWithMass(false)},
      {"pinned, water, seabed", pinnedCatenary(true, true, true)},
      {"J-lay, elastic", jlay(true)},
      {"J-lay, inext.", jlay(false)},
      {"J-lay, flow 10 m/s", flow},
      {"J-lay, drag 10", drag10},
      {"J-lay, current 1 m/s", current},
  };
  for (const Case& c : cases)
    for (const char* form : {"recursive", "independent"})
      EXPECT_LT(compare(c.name, c.scene, form, State::kMoving), kAwayBound) << c.name;
}

}  // namespace
}  // namespace riser_sim
