// Spatial force terms against their energies, on random states with a tilted gravity vector:
// - conservative parts (velocities zero): Q = -∂V/∂q on the tangent space (the e part projected
//   orthogonally to e), by central differences of V;
// - power identity with velocities (damping on): Q·q' = -dV/dt + P, dV/dt by central differences along q';
// - the bending spring at θ = 0 exactly and near π: finite forces; its θ/sinθ series against asin, and its
//   force k θ on either side of the series' switch.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "riser_sim/spatial/forces/flex_joint.h"
#include "spatial_force_checks.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using namespace spatial_test;

LineSpec spec() {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 5;
  return s;
}

TEST(SpatialForces, ConservativeForcesAreMinusTheTangentGradient) {
  auto m = spatial_test::spatialModel(spec(), Vec3(1.2, -0.7, -9.5));
  for (const auto& term : m->terms()) checkGradient(*term, *m);
}

TEST(SpatialForces, PowerIdentityWithDamping) {
  auto m = spatial_test::spatialModel(spec(), Vec3(1.2, -0.7, -9.5));
  for (const auto& term : m->terms()) checkPower(*term, *m);
}

// Flex joints at both ends (random axes): the spring against its energy, the damper's power, and the moment
// on the holder is minus the joint's torque on the rfe (its e part, τ × e, is what the line feels).
TEST(SpatialForces, FlexJointsAgainstTheirEnergy) {
  auto m = spatial_test::spatialModel(spec(), Vec3(1.2, -0.7, -9.5));
  const FlexJoint top(FlexJoint::End::kTop, Vec3(0.3, 0.2, -1.0), 5e3, 20.0);
  const FlexJoint bottom(FlexJoint::End::kBottom, Vec3(-0.1, 0.5, 1.0), 2e3, 7.0);
  for (const FlexJoint* j : {&top, &bottom}) {
    checkGradient(*j, *m);
    checkPower(*j, *m);
  }
  // A joint turned by 0.2 rad about x from its axis -z: moment k θ about x on the holder, and the
  // rfe's generalised force turns it back.
  Kinematics3 kin(m->bodies());
  for (int i = 0; i < m->bodies(); ++i) kin[i].e = Vec3(0, 0, -1), kin[i].len = m->rfe(i).length;
  kin[0].e = Vec3(0.0, std::sin(0.2), -std::cos(0.2));
  const FlexJoint j(FlexJoint::End::kTop, Vec3(0, 0, -1), 5e3, 0.0);
  EXPECT_NEAR(j.angle(*m, kin, 0.0), 0.2, 1e-15);
  const Vec3 M = j.moment(*m, kin, 0.0);
  EXPECT_NEAR(M.x(), 5e3 * 0.2, 1e-9);  // e rotated by +0.2 about x: the holder is turned the same way
  EXPECT_NEAR(M.y(), 0.0, 1e-12);
  EXPECT_NEAR(M.z(), 0.0, 1e-12);
  EXPECT_THROW(FlexJoint(FlexJoint::End::kTop, Vec3::Zero(), 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(FlexJoint(FlexJoint::End::kTop, Vec3(0, 0, -1), 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(FlexJoint(FlexJoint::End::kTop, Vec3(0, 0, -1), 1.0, -1.0), std::invalid_argument);
}

TEST(SpatialForces, BendingAtZeroAndNearFoldedAngle) {
  auto m = spatial_test::spatialModel(spec(), Vec3(0, 0, -9.81));
  spatial::BendingSpring spring;
  Kinematics3 kin(m->bodies());
  for (int i = 0; i < m->bodies(); ++i) kin[i].e = Vec3(0, 0, -1), kin[i].len = m->rfe(i).length;
  VecX Q = VecX::Zero(m->dofs());
  spring.addForces(*m, kin, 0.0, Q);  // θ = 0 exactly everywhere
  EXPECT_TRUE(Q.allFinite());
  EXPECT_EQ(Q.cwiseAbs().maxCoeff(), 0.0);
  kin[1].e = Vec3(1e-9, 0, 1).normalized();  // θ ≈ π - 1e-9 between rfes 0 and 1
  kin[2].e = -kin[1].e;                      // θ = π exactly between rfes 1 and 2: documented zero force
  Q.setZero();
  spring.addForces(*m, kin, 0.0, Q);
  EXPECT_TRUE(Q.allFinite());
  // Near π the force on e_1 is c θ / |e_0| ≈ c π (tangent, lever of unit length).
  const Vec3 q1 = Q.segment<3>(kDofPerBody3 * 0 + kE);
  EXPECT_NEAR(q1.norm(), m->bendingStiffness(1) * (M_PI - 1e-9), 1e-6 * m->bendingStiffness(1));
}

// θ/sinθ by its series (sin²θ <= 0.01) against asin(x)/x from libm: the series' truncation is 1.2e-18 there
// (bending_spring.cpp), so what is left is rounding, a few ulp; 1e-15 relative allows ~4.5 ulp.
constexpr double kSeriesUlps = 1e-15;

TEST(SpatialForces, BendingSeriesAgainstAsin) {
  double worst = 0.0;
  for (int k = 1; k <= 1000; ++k) {
    const double x = 0.1 * k / 1000.0;
    const double exact = std::asin(x) / x, series = spatial::BendingSpring::asinOverSin(x * x);
    worst = std::max(worst, std::abs(series - exact) / exact);
  }
  std::printf("[spatial forces] θ/sinθ series vs asin(x)/x, x <= 0.1: %.1e relative at worst\n", worst);
  EXPECT_LT(worst, kSeriesUlps);
}

// Two unit directors at θ: the spring's force on e_1 is k θ (θ/sinθ times the tangent a - cosθ b of length
// sinθ), on either side of the series' switch (sin²θ = 0.01, θ = 0.10017 rad) and far from it.
TEST(SpatialForces, BendingForceIsKThetaAcrossTheSeriesSwitch) {
  auto m = spatial_test::spatialModel(spec(), Vec3(0, 0, -9.81));
  spatial::BendingSpring spring;
  const double k = m->bendingStiffness(1), switch_angle = std::asin(0.1);
  for (double theta : {1e-6, 1e-3, 0.05, switch_angle - 1e-9, switch_angle + 1e-9, 0.3, 2.0}) {
    Kinematics3 kin(m->bodies());
    for (int i = 0; i < m->bodies(); ++i) kin[i].e = Vec3(0, 0, -1), kin[i].len = m->rfe(i).length;
    kin[1].e = Vec3(std::sin(theta), 0, -std::cos(theta));
    for (int i = 2; i < m->bodies(); ++i) kin[i].e = kin[1].e;  // one bent joint, between rfes 0 and 1
    VecX Q = VecX::Zero(m->dofs());
    spring.addForces(*m, kin, 0.0, Q);
    const double q1 = Q.segment<3>(kDofPerBody3 * 1 + kE).norm();
    EXPECT_NEAR(q1, k * theta, 1e-14 * k * theta) << "θ = " << theta;
  }
}

}  // namespace
}  // namespace riser_sim
