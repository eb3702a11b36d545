// The 3D implicit step's kept factor (simulator.cpp): Newton reports each converged solve's count and its
// stopping test's margin (OneStageImplicit::lastNewton), and the kept factor is relinearised a step ahead
// when that margin, grown by the steps since the linearisation, predicts a 4th solve. On the step-cost
// bench's line at n = 1000 (rfe 0 is 0.1 m long: its director's linearisation goes stale fastest) that
// takes Newton from 3.1-3.2 to ~2.85 solves per step; the result stays Newton's (compared with fresh
// factors, to its tolerance).
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/implicit_integrators.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/simulator.h"

namespace {

using namespace riser_sim;

// q'' = -ω² q - 2ζω q': the dense Jacobian path of midpoint.
struct Oscillator : OdeSystem {
  double w = 30.0, zeta = 0.01;
  void rhs(double, const VecX& y, VecX& dy) override {
    dy.resize(y.size());
    dy[0] = y[1];
    dy[1] = -w * w * y[0] - 2.0 * zeta * w * y[1];
  }
};

TEST(NewtonReport, ConvergedSolveWithinItsBound) {
  Oscillator sys;
  IntegratorOptions o;
  o.jacobian = JacobianKind::kDense;
  ImplicitMidpoint mid(o);
  mid.reset(StateLayout{2, 1});
  VecX y(2);
  y << 1.0, 0.0;
  double t = 0.0;
  for (int k = 0; k < 50; ++k, t += 0.01) {
    ASSERT_TRUE(mid.step(sys, t, y, 0.01)) << mid.failure();
    EXPECT_GE(mid.lastNewton().solves, 1);
    EXPECT_LE(mid.lastNewton().solves, 12);
    EXPECT_GE(mid.lastNewton().margin, 0.0);
    EXPECT_LE(mid.lastNewton().margin, 1.0);
  }
}

// The bench line (bench/step_cost.cpp, "3D against 2D"): 100 m, EA 1e7 N, EI 1e4 N m², damped, 500 kg end,
// released 20° off the vertical in the x-z plane, the top swaying in x.
std::shared_ptr<spatial::SpatialModel> benchLine(int n) {
  LineProperties p;
  p.mass_per_length = 10.0;
  p.EA = 1e7;
  p.EI = 1e4;
  p.axial_damping = 1e4;
  p.bending_damping = 100.0;
  auto m = std::make_shared<spatial::SpatialModel>(100.0, n, p, ModelOptions(), 500.0, spatial::Vec3(0, 0, -9.81));
  m->addTerm(std::make_unique<spatial::Gravity>());
  m->addTerm(std::make_unique<spatial::AxialSpring>());
  m->addTerm(std::make_unique<spatial::BendingSpring>());
  return m;
}

spatial::Kinematics3 released(const spatial::SpatialModel& m) {
  spatial::Kinematics3 kin(m.bodies());
  const double a = 20.0 * M_PI / 180.0;
  const spatial::Vec3 e(std::sin(a), 0.0, -std::cos(a));
  spatial::Vec3 A = spatial::Vec3::Zero();
  for (int i = 0; i < m.bodies(); ++i) {
    kin[i].A = A;
    kin[i].e = e;
    kin[i].len = m.line().rfe(i).length;
    A += kin[i].len * e;
  }
  return kin;
}

TEST(SpatialFactorReuse, FewerNewtonSolvesOnALongFineLine) {
  auto m = benchLine(1000);
  IntegratorOptions o;
  o.jacobian = JacobianKind::kStructured;
  auto top = [] {
    return std::make_unique<spatial::PlanarMotion3>(
        std::make_unique<SinusoidMotion>(Vec2(-1.0, 0.0), Vec2(1.0, 0.0), 10.0, 0.0));
  };
  spatial::SpatialSimulator sim(m, top(), IntegratorKind::kMidpoint, o);
  sim.reset(released(*m), 0.0);
  const int steps = 120;
  for (int k = 0; k < steps; ++k) ASSERT_TRUE(sim.step(1e-3));
  const double per_step = double(sim.integrator().stats().newton) / steps;
  EXPECT_LE(per_step, 3.0);  // measured 2.8-2.9 (3.1-3.2 before: a 4th solve every 6th step, then a fresh step)
  EXPECT_GE(per_step, 2.0);
}

}  // namespace
