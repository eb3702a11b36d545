// Every force term's energy report is complete: along any motion q(t), the power of its generalised
// forces is what leaves its potential plus what its non-conservative part feeds in,
//   Q(q, q', t) · q' = -dV/dt + P(q, q', t),
// with dV/dt by central differences of V along q'. A term that forgot its potential or its power (a
// silent 0 that would make the runs' energy balance lie) fails here. Terms with inertia (added mass)
// move forces to the mass matrix and are checked by the runs' energy balance instead (test_energy).
#include <gtest/gtest.h>

#include <random>

#include "riser_sim/planar/absolute_formulation.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/forces/end_load.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// Central differences of V with step ε along q': truncation ε² V''' ~ 1e-12 of the power scale and
// round-off 1e-16 |V| / ε; bound 1e-6 of the largest of |Q·q'|, |P| (measured below 1e-8).
constexpr double kFdStep = 1e-5;
constexpr double kPowerRelTol = 1e-6;

// The Table 1 line in water with every term that the sea, the seabed and the flow give, all on.
Scene everyTermScene() {
  Scene s = validation::table1Scene(6);
  s.line = LineProperties::fromGeometry(0.3, 0.2, 1e9, 600.0);
  s.options.bending = true;
  s.line.EI = 1e6;
  s.line.axial_damping = 2e4;
  s.line.bending_damping = 3e3;
  s.water.enabled = true;
  s.water.surface = -20.0;  // the upper rfes cut the surface
  s.water.current.velocity = Eigen::Vector3d(0.8, 0.0, 0.0);
  s.hydro.enabled = true;
  s.hydro.drag_normal = 1.2;
  s.hydro.drag_tangential = 0.05;
  s.seabed.enabled = true;
  s.seabed.level = -95.0;  // the lower rfes touch
  s.seabed.stiffness_normal = 1e5;
  s.seabed.stiffness_tangential = 1e4;
  s.seabed.damping_normal = 2e3;
  s.seabed.damping_tangential = 1e3;
  s.internal_fluid.density = 800.0;
  s.internal_fluid.velocity = 3.0;
  return s;
}

// Joints closed, velocities consistent: a line bent around hanging, its end near the seabed.
VecX randomMotion(const Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int nq = m.dofs();
  VecX y = VecX::Zero(2 * nq);
  Vec2 A(0.0, 0.0), Ad(u(rng), u(rng));
  for (int i = 0; i < m.bodies(); ++i) {
    const double delta = 1e-3 * u(rng), phi = -M_PI / 2 + 0.6 * u(rng);
    const double delta_d = 0.1 * u(rng), phi_d = 0.4 * u(rng);
    y.segment<4>(4 * i) = Vec4(A.x(), A.y(), delta, phi);
    y.segment<4>(nq + 4 * i) = Vec4(Ad.x(), Ad.y(), delta_d, phi_d);
    const double len = m.rfe(i).length + delta;
    const Vec2 e = unit(phi);
    Ad += delta_d * e + len * phi_d * perp(e);
    A += len * e;
  }
  return y;
}

TEST(TermPower, ForcesPowerIsMinusPotentialRatePlusReportedPower) {
  auto model = buildModel(everyTermScene());
  model->addTerm(std::make_unique<EndLoad>(Vec2(4e3, -1e3)));
  AbsoluteFormulation f(*model, 50.0);
  const int nq = model->dofs();
  std::mt19937 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const VecX y = randomMotion(*model, rng);
    const double t = 0.3 * trial;
    Kinematics kin(model->bodies()), kp(model->bodies()), km(model->bodies());
    f.kinematics(y, PointMotion(), kin);
    VecX yp = y, ym = y;
    yp.head(nq) += kFdStep * y.tail(nq);
    ym.head(nq) -= kFdStep * y.tail(nq);
    f.kinematics(yp, PointMotion(), kp);
    f.kinematics(ym, PointMotion(), km);
    for (const auto& term : model->terms()) {
      if (term->hasInertia()) continue;
      VecX Q = VecX::Zero(nq);
      term->addForces(*model, nullptr, kin, t, Q);
      const double forces_power = Q.dot(y.tail(nq));
      const double v_rate =
          (term->potentialEnergyAt(*model, nullptr, kp, t) - term->potentialEnergyAt(*model, nullptr, km, t)) /
          (2.0 * kFdStep);
      const double reported = term->power(*model, nullptr, kin, t);
      const double scale = std::max({std::abs(forces_power), std::abs(reported), 1.0});
      EXPECT_LT(std::abs(forces_power + v_rate - reported), kPowerRelTol * scale)
          << term->name() << " (trial " << trial << "): Q.q' = " << forces_power << " W, -dV/dt = " << -v_rate
          << " W, reported power " << reported << " W";
      ++checked;
    }
  }
  EXPECT_GE(checked, 6 * 7);  // gravity, axial, bending, buoyancy, drag, seabed, flow (+ end load)
}

}  // namespace
}  // namespace riser_sim
