// The implicit integrators' structured O(n) solves (chain_shifted_solver.h) against the dense solve
// with a finite-difference Jacobian of the equations of motion. At a static equilibrium at rest the
// structured matrix is the exact Jacobian (every term there reports its stiffness; drag and the
// velocity terms vanish at rest with their derivatives), so both solves must agree to the accuracy of
// the central differences.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <random>

#include "riser_sim/recursive_formulation.h"
#include "riser_sim/independent_formulation.h"
#include "riser_sim/scene.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// Central-difference steps: positions relative 1e-6 of the coordinate scale (truncation ~1e-12, round-off
// ~1e-10: the Jacobian is good to ~1e-9 relative); rates 1e-8 [1/s, m/s], because the central
// difference of the quadratic drag |v| v at v = 0 is |h|, not 0.
constexpr double kFdStep = 1e-6, kFdStepRate = 1e-8;
// Agreement of x = (I - cJ)^-1 b, relative to |x|_inf: the Jacobian's 1e-9 amplified by the conditioning
// of I - cJ at the largest c (measured worst 7e-9 over the cases below).
constexpr double kAgree = 1e-7;

struct Case {
  const char* name;
  Scene scene;
};

// A catenary in water pinned at both ends, partly resting on the seabed, with bending.
Scene pinnedCatenary(bool axial, bool water, bool seabed, bool hydro = true) {
  Scene s;
  s.length = 120.0;
  s.elements = 12;
  s.line = LineProperties::fromGeometry(0.3, 0.26, 2.07e11, 7850.0);
  s.options.axial_flexibility = axial;
  s.bottom = BottomBoundary::kPinned;
  s.top.position = Vec2(0.0, -1.0);  // every rfe fully wet (the wet length's change is not linearised)
  s.bottom_point = Vec2(80.0, -61.0);
  s.initial.type = "between_points";
  s.solver.stabilization = 0.0;  // the structured solve holds the pin exactly (see pinnedRates)
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
  s.initial.type = "hanging";
  return s;
}

// Chain rates v with the pinned end at rest: the last two φ rates absorb the end velocity.
void pinnedRates(Formulation& f, const Model& model, VecX y, VecX& v) {
  const int p = f.positionSize();
  Kinematics kin(model.bodies());
  auto end = [&](const VecX& w) {
    y.segment(p, p) = w;
    f.kinematics(y, kin);
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

void compare(const char* name, Scene scene, const std::string& formulation) {
  scene.solver.formulation = formulation;
  StaticsResult st;
  auto sim = buildSimulator(scene, &st);
  const Model& model = sim->model();
  std::unique_ptr<Formulation> f;
  if (formulation == "recursive") f = std::make_unique<RecursiveFormulation>(model, scene.solver.stabilization);
  else f = std::make_unique<IndependentFormulation>(model, scene.solver.stabilization);
  ASSERT_TRUE(f->hasShiftedSolve());
  const int p = f->positionSize(), m = 2 * p, n = static_cast<int>(sim->state().size());
  const PointMotion top = buildTopMotion(scene.top)->at(0.0);
  const VecX y0 = sim->state();
  VecX dy(n), dp(n), dm(n);
  f->derivative(0.0, y0, top, dy);
  ASSERT_LT(dy.segment(p, p).cwiseAbs().maxCoeff(), 1e-6) << name << ": not at rest in equilibrium";

  // Dense Jacobian of (q', v') by central differences.
  MatX J(m, m);
  const double scale = 1.0 + y0.head(p).cwiseAbs().maxCoeff();
  for (int j = 0; j < m; ++j) {
    VecX yp = y0, ym = y0;
    const double h = j < p ? kFdStep * scale : kFdStepRate;
    yp[j] += h;
    ym[j] -= h;
    f->derivative(0.0, yp, top, dp);
    f->derivative(0.0, ym, top, dm);
    J.col(j) = (dp.head(m) - dm.head(m)) / (2.0 * h);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const bool pinned = model.bottom() == BottomBoundary::kPinned;
  double worst = 0.0;
  for (double c : {1e-4, 1e-2, 0.1}) {
    VecX b = VecX::Zero(n);
    for (int i = 0; i < m; ++i) b[i] = u(rng);
    if (pinned) {
      VecX v = b.segment(p, p);
      pinnedRates(*f, model, y0, v);
      b.segment(p, p) = v;
    }
    const VecX ref = (MatX::Identity(m, m) - c * J).partialPivLu().solve(b.head(m));
    f->derivative(0.0, y0, top, dy);
    f->linearize(0.0);
    f->factorShifted(c);
    VecX x = VecX::Zero(n);
    f->solveShifted(b, x);
    const double err = (x.head(m) - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
    worst = std::max(worst, err);
    EXPECT_LT(err, kAgree) << name << " (" << formulation << "), c = " << c;
  }
  std::printf("  %-28s %-11s p = %3d: worst relative difference %.2e\n", name, formulation.c_str(), p, worst);
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
    for (const char* form : {"recursive", "independent"}) compare(c.name, c.scene, form);
}

}  // namespace
}  // namespace riser_sim
