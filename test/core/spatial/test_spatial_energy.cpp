// Energy balance of the spatial run with a moving top and damping: E(t) - E(0) = W(t), W the work of the
// top's reaction and of the damping terms integrated alongside the motion (the stepping wrapper's W);
// and the generalised force of a point force / torque has the power F·v_p / τ·ω.
#include <gtest/gtest.h>

#include <random>

#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

TEST(SpatialEnergy, BalanceWithMovingTopAndDamping) {
  const spatial_test::LineSpec s = spatial_test::flexibleLine();
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  std::vector<Vec3> dirs(m->bodies(), Vec3(0.3, 0.2, -1.0));
  const Mat3 R0 = spatial_test::yawTilt(0.3, 0.5);
  Simulator3 sim(m, std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), R0),
                 IntegratorKind::kRk4);
  sim.reset(rigidChain(m->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3(0.2, -0.3, 0.5)), 0.0);
  const double e0 = sim.energy(), scale = (s.props.mass_per_length * s.length + s.end_mass) * s.g * s.length;
  constexpr double kStep = 1e-4;  // [s]
  double worst = 0.0, w_abs = 0.0;
  for (int k = 1; k <= 10000; ++k) {  // 1 s
    ASSERT_TRUE(sim.step(kStep));
    if (k % 100) continue;
    worst = std::max(worst, std::abs(sim.energy() - e0 - sim.work()) / scale);
    w_abs = std::max(w_abs, std::abs(sim.work()) / scale);
  }
  std::printf("[spatial energy] |E - E0 - W| / (m g L) = %.2e with |W| up to %.2e m g L\n", worst, w_abs);
  EXPECT_GT(w_abs, 1e-3);  // the top and the dampers do work
  // W by the same rk4 as the motion: balance error O(h⁴) like the planar test_energy (measured there ~1e-12);
  // a missing power (the top's reaction, a damper) shows at the size of W.
  EXPECT_LT(worst, 1e-9);
}

TEST(SpatialEnergy, PointForceAndTorquePower) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    BodyKinematics3 b;
    b.A = Vec3(u(rng), u(rng), u(rng));
    b.A_dot = Vec3(u(rng), u(rng), u(rng));
    b.delta = 0.01 * u(rng);
    b.delta_dot = u(rng);
    b.e = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Vec3 r(u(rng), u(rng), u(rng));
    b.e_dot = r - r.dot(b.e) * b.e;
    Vec7 v;
    v << b.A_dot, b.delta_dot, b.e_dot;
    const Vec3 F(u(rng), u(rng), u(rng)), tau(u(rng), u(rng), u(rng));
    for (double kappa : {0.0, 1.0}) {
      Vec7 q = Vec7::Zero();
      addPointForce(b, 0.3, kappa, F, q.data());
      EXPECT_NEAR(q.dot(v), F.dot(b.velocity(0.3, kappa)), 1e-14);
    }
    Vec7 q = Vec7::Zero();
    addTorque(b, tau, q.data());
    EXPECT_NEAR(q.dot(v), tau.dot(b.omega()), 1e-14);
  }
}

}  // namespace
}  // namespace riser_sim
