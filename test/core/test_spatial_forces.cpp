// Spatial force terms against their energies, on random states with a tilted gravity vector:
// - conservative parts (velocities zero): Q = -∂V/∂q on the tangent space (the e part projected
//   orthogonally to e), by central differences of V;
// - power identity with velocities (damping on): Q·q' = -dV/dt + P, dV/dt by central differences along q';
// - the bending spring at θ = 0 exactly and near π: finite forces.
#include <gtest/gtest.h>

#include <random>

#include "riser_sim/spatial/forces/flex_joint.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using spatial_test::LineSpec;

// Central differences with step ε: truncation ε² V''' / 6 ~ 1e-10 of the force scale, round-off
// 1e-16 |V| / ε ~ 1e-11 of it; bound 1e-6 relative to the largest |Q| entry (measured 1.4e-10 gravity,
// 2.1e-11 bending, 3e-15 axial).
constexpr double kFdStep = 1e-5;
constexpr double kRelTol = 1e-6;

LineSpec spec() {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 5;
  return s;
}

// Random state near a hanging line: Δ ~ 1e-3 m, directions spread over the sphere around -z, with a
// straight joint (θ = 0 exactly) between rfes 1 and 2; velocities random, e' tangent.
VecX randomState(const SpatialModel& m, std::mt19937& rng, bool moving) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kinematics3 kin(m.bodies());
  Vec3 A(u(rng), u(rng), u(rng));
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics3& b = kin[i];
    b.A = A;
    b.delta = 1e-3 * u(rng);
    b.e = i == 2 ? kin[1].e : Vec3(0.9 * u(rng), 0.9 * u(rng), -1.0 + 0.5 * u(rng)).normalized();
    b.len = m.rfe(i).length + b.delta;
    if (moving) {
      b.A_dot = Vec3(u(rng), u(rng), u(rng));
      b.delta_dot = 0.1 * u(rng);
      const Vec3 r(u(rng), u(rng), u(rng));
      b.e_dot = r - r.dot(b.e) * b.e;
    }
    A = b.end() + Vec3(1e-3 * u(rng), 0, 0);  // joints need not close for a term's check
  }
  NaturalFormulation f(m, 50.0);
  VecX y = VecX::Zero(2 * m.dofs());
  f.packState(kin, y);
  return y;
}

double energy(const SpatialForceTerm& term, const SpatialModel& m, const NaturalFormulation& f, const VecX& y) {
  Kinematics3 kin(m.bodies());
  f.kinematics(y, kin);
  return term.potentialEnergy(m, kin);
}

// Projects the e part of every rfe's generalised vector orthogonally to e.
VecX tangent(const SpatialModel& m, const VecX& y, VecX g) {
  for (int i = 0; i < m.bodies(); ++i) {
    const Vec3 e = y.segment<3>(kDofPerBody3 * i + kE);
    auto ge = g.segment<3>(kDofPerBody3 * i + kE);
    ge -= ge.dot(e) / e.squaredNorm() * e;
  }
  return g;
}

void checkGradient(const SpatialForceTerm& term, const SpatialModel& m) {
  std::mt19937 rng(7);
  NaturalFormulation f(m, 50.0);
  const int nq = m.dofs();
  for (int trial = 0; trial < 5; ++trial) {
    VecX y = randomState(m, rng, false);
    Kinematics3 kin(m.bodies());
    f.kinematics(y, kin);
    VecX Q = VecX::Zero(nq);
    term.addForces(m, kin, 0.0, Q);
    VecX grad = VecX::Zero(nq);
    for (int j = 0; j < nq; ++j) {
      VecX yp = y, ym = y;
      yp[j] += kFdStep;
      ym[j] -= kFdStep;
      grad[j] = (energy(term, m, f, yp) - energy(term, m, f, ym)) / (2 * kFdStep);
    }
    const VecX q_t = tangent(m, y, Q), g_t = tangent(m, y, grad);
    const double scale = std::max(q_t.cwiseAbs().maxCoeff(), 1e-12);
    const double err = (q_t + g_t).cwiseAbs().maxCoeff() / scale;
    EXPECT_LT(err, kRelTol) << term.name() << " trial " << trial;
    if (trial == 0) std::printf("[spatial %s] |Q + dV/dq| / |Q| = %.2e (tangent)\n", term.name().c_str(), err);
  }
}

void checkPower(const SpatialForceTerm& term, const SpatialModel& m) {
  std::mt19937 rng(11);
  NaturalFormulation f(m, 50.0);
  const int nq = m.dofs();
  for (int trial = 0; trial < 5; ++trial) {
    const VecX y = randomState(m, rng, true);
    Kinematics3 kin(m.bodies());
    f.kinematics(y, kin);
    VecX Q = VecX::Zero(nq);
    const double P = term.addForcesAndPower(m, kin, 0.0, Q);
    const double Qv = Q.dot(y.segment(nq, nq));
    VecX yp = y, ym = y;
    yp.head(nq) += kFdStep * y.segment(nq, nq);
    ym.head(nq) -= kFdStep * y.segment(nq, nq);
    const double dV = (energy(term, m, f, yp) - energy(term, m, f, ym)) / (2 * kFdStep);
    const double scale = std::max({std::abs(Qv), std::abs(P), 1e-12});
    EXPECT_LT(std::abs(Qv + dV - P) / scale, kRelTol) << term.name() << " trial " << trial;
    if (trial == 0)
      std::printf("[spatial %s] Q·v = %.6e, -dV/dt + P = %.6e, P = %.3e\n", term.name().c_str(), Qv, -dV + P, P);
  }
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
  EXPECT_NEAR(j.angle(*m, kin), 0.2, 1e-15);
  const Vec3 M = j.moment(*m, kin);
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
  EXPECT_NEAR(q1.norm(), m->bendingStiffness() * (M_PI - 1e-9), 1e-6 * m->bendingStiffness());
}

}  // namespace
}  // namespace riser_sim
