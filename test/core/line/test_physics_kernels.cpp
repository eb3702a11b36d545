// The point-physics kernels (include/riser_sim/physics/) against hand computations:
// - Morison drag on a cylinder at 30° to the flow: normal ½ ρ C_n D l |v_n| v_n, tangential ½ ρ C_t D l v_t²,
//   2D and 3D alike; its damping matrix against central differences;
// - buoyancy: Archimedes' ρ g V for a submerged cylinder, its potential's slope; Froude-Krylov C_M ρ A l a across
//   the axis and C_m,t ρ A l a along it;
// - seabed contact: C_n δ - c_n v_n, never pulling; the smoothed Coulomb friction saturating at μ F_n and viscous
//   below the sliding speed;
// - a point body: Archimedes' lift, the sphere's drag ½ ρ C_d A |u| u and the seabed's normal force.
// Tolerances: the kernels do a few roundings on O(1..1e4) numbers, so 1e-12 relative; the central differences
// (step 1e-6 on O(1) velocities) have truncation O(h²) ~ 1e-12 and rounding ~ ε/h ~ 1e-10 relative: 1e-6.
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/physics/buoyancy.h"
#include "riser_sim/physics/morison_drag.h"
#include "riser_sim/physics/point_body.h"
#include "riser_sim/physics/seabed_contact.h"

namespace riser_sim {
namespace {

using physics::VecD;
using Vec3 = Eigen::Vector3d;

constexpr double kRho = 1025.0, kD = 0.5, kL = 2.0, kCn = 1.2, kCt = 0.1;

// A cylinder in the xz plane at 30° to a 2 m/s flow along x (the water moves, the cylinder is still: V' = -u).
TEST(PhysicsKernels, MorisonDragOnAnInclinedCylinderByHand) {
  const double th = M_PI / 6.0, U = 2.0;
  const Vec3 e(std::cos(th), 0.0, std::sin(th)), rel(-U, 0.0, 0.0);
  const Vec3 F = physics::morisonDrag<3>(rel, e, kRho, kD, kL, kCt, kCn);
  // v_t = -U cos30° (v_t² = 3), |v_n| = U sin30° = 1: normal ½·1025·1.2·0.5·2·1² = 615 N along -v_n,
  // tangential ½·1025·0.1·0.5·2·3 = 153.75 N along -v_t e.
  const double vt = e.dot(rel);
  const Vec3 vn = rel - vt * e;
  EXPECT_NEAR(F.dot(e), 153.75, 153.75 * 1e-12);
  const Vec3 Fn = F - F.dot(e) * e;
  EXPECT_NEAR(Fn.norm(), 615.0, 615.0 * 1e-12);
  EXPECT_NEAR(Fn.normalized().dot(vn.normalized()), -1.0, 1e-12);
  // The same cylinder in the planar engine's plane (x, z -> x, y) gives the same force.
  const Vec2 F2 = physics::morisonDrag<2>(Vec2(rel.x(), rel.z()), Vec2(e.x(), e.z()), kRho, kD, kL, kCt, kCn);
  EXPECT_NEAR(F2.x(), F.x(), 1e-12 * F.norm());
  EXPECT_NEAR(F2.y(), F.z(), 1e-12 * F.norm());
  // Along the axis only: no normal force; across only: no tangential.
  EXPECT_NEAR((physics::morisonDrag<3>(Vec3(e * 1.5), e, kRho, kD, kL, kCt, kCn)).dot(e),
              -0.5 * kRho * kCt * kD * kL * 2.25, 1e-9);
  EXPECT_NEAR(physics::morisonDrag<3>(Vec3(0.0, 1.0, 0.0), e, kRho, kD, kL, kCt, kCn).dot(e), 0.0, 1e-12);
}

template <int D>
void checkDragDamping(const VecD<D>& rel, const VecD<D>& e) {
  const auto C = physics::morisonDragDamping<D>(rel, e, kRho, kD, kL, kCt, kCn);
  const double h = 1e-6;
  for (int k = 0; k < D; ++k) {
    VecD<D> dp = rel, dm = rel;
    dp[k] += h, dm[k] -= h;
    const VecD<D> col = -(physics::morisonDrag<D>(dp, e, kRho, kD, kL, kCt, kCn) -
                          physics::morisonDrag<D>(dm, e, kRho, kD, kL, kCt, kCn)) /
                        (2.0 * h);
    EXPECT_LE((C.col(k) - col).norm(), 1e-6 * C.norm()) << "D " << D << " column " << k;
  }
}

TEST(PhysicsKernels, MorisonDragDampingIsTheSlopeOfTheForce) {
  checkDragDamping<2>(Vec2(0.7, -1.3), Vec2(std::cos(0.4), std::sin(0.4)));
  checkDragDamping<3>(Vec3(0.7, -1.3, 0.4), Vec3(0.3, -0.2, 0.9).normalized());
}

TEST(PhysicsKernels, BuoyancyIsArchimedes) {
  const double g = 9.81, A = M_PI / 4.0 * kD * kD;
  // ρ g V of the displaced water, V = π/4 D² l = 0.3926990817 m^3: 1025·9.81·0.3926990817 = 3948.6874 N.
  const double f = physics::liftPerLength(kRho, A, g);
  const Vec3 F = physics::buoyancyForce<3>(f, kL, Vec3(0.0, 0.0, 1.0));
  EXPECT_NEAR(F.z(), 3948.6874, 1e-4);
  EXPECT_EQ(F.x(), 0.0);
  EXPECT_EQ(physics::buoyancyForce<2>(f, kL, Vec2(0.0, 1.0)).y(), F.z());
  // The lift is the potential's slope: -dV/dh = ρ g A l (V linear in h: exact up to rounding).
  const double h0 = -3.0, dh = 0.5;
  const double slope =
      (physics::buoyancyPotential(f, kL, h0 + dh) - physics::buoyancyPotential(f, kL, h0 - dh)) / (2.0 * dh);
  EXPECT_NEAR(-slope, F.z(), 1e-9 * F.z());
}

TEST(PhysicsKernels, FroudeKrylovAcrossAndAlongTheAxis) {
  const double rhoA = kRho * M_PI / 4.0 * kD * kD, cm = 2.0, cmt = 1.3, a = 0.4;
  const Vec3 e(std::cos(0.3), 0.0, std::sin(0.3)), n(-std::sin(0.3), 0.0, std::cos(0.3));
  // Across: C_M ρ A l a; along: C_m,t ρ A l a (Morison's inertia term on a fixed cylinder).
  EXPECT_LE((physics::froudeKrylov<3>(rhoA, kL, Vec3(a * n), e, cm, cmt) - cm * rhoA * kL * a * n).norm(), 1e-9);
  EXPECT_LE((physics::froudeKrylov<3>(rhoA, kL, Vec3(a * e), e, cm, cmt) - cmt * rhoA * kL * a * e).norm(), 1e-9);
  const Vec3 aw(0.3, 0.0, -0.2);
  const Vec3 F3 = physics::froudeKrylov<3>(rhoA, kL, aw, e, cm, cmt);
  const Vec2 F2 = physics::froudeKrylov<2>(rhoA, kL, Vec2(aw.x(), aw.z()), Vec2(e.x(), e.z()), cm, cmt);
  EXPECT_NEAR(F2.x(), F3.x(), 1e-12 * F3.norm());
  EXPECT_NEAR(F2.y(), F3.z(), 1e-12 * F3.norm());
}

TEST(PhysicsKernels, SeabedNormalForceNeverPulls) {
  // C_n δ - c_n v_n = 1e5·0.1 - 2e3·1.5 = 7000 N; moving up fast enough the damper would pull: 0.
  EXPECT_DOUBLE_EQ(physics::contactNormalForce(1e5, 0.1, 2e3 * 1.5), 7000.0);
  EXPECT_EQ(physics::contactNormalForce(1e5, 0.1, 2e3 * 6.0), 0.0);
  EXPECT_DOUBLE_EQ(physics::contactSpringEnergy(1e5, 0.1), 500.0);  // ½ 1e5 0.1²
}

TEST(PhysicsKernels, SeabedFrictionSaturatesAtMuN) {
  const Vec3 n(0.0, 0.0, 1.0);
  Vec3 a, l;
  physics::frictionAxes(Vec3(Vec3(1.0, 0.0, -0.5).normalized()), n, a, l);
  EXPECT_NEAR(a.dot(Vec3(1.0, 0.0, 0.0)), 1.0, 1e-15);  // the line's direction on the plane
  EXPECT_NEAR(l.dot(Vec3(0.0, 1.0, 0.0)), 1.0, 1e-15);
  const double fn = 7000.0, mu_a = 0.3, mu_l = 0.8, vs = 0.01;
  // Sliding at 10 m/s >> v_s: |F| = μ F_n / sqrt(1 + (v_s/v)²) = μ F_n (1 - 5e-7), against the motion.
  const Vec3 Fa = physics::smoothedFriction<3>(fn, Vec3(10.0 * a), a, l, mu_a, mu_l, vs);
  EXPECT_NEAR(Fa.dot(a), -mu_a * fn, mu_a * fn * 1e-6);
  EXPECT_NEAR(Fa.dot(l), 0.0, 1e-9);
  const Vec3 Fl = physics::smoothedFriction<3>(fn, Vec3(-10.0 * l), a, l, mu_a, mu_l, vs);
  EXPECT_NEAR(Fl.dot(l), mu_l * fn, mu_l * fn * 1e-6);
  // Never above μ F_n, whatever the speed.
  for (double v : {1e-4, 1e-2, 1.0, 1e3})
    EXPECT_LE(physics::smoothedFriction<3>(fn, Vec3(v * a), a, l, mu_a, mu_l, vs).norm(), mu_a * fn);
  // Far below v_s a viscous stick: F ≈ -μ F_n v / v_s (relative error (v/v_s)²/2 = 5e-9 at v = 1e-6).
  const double v = 1e-6;
  EXPECT_NEAR(physics::smoothedFriction<3>(fn, Vec3(v * a), a, l, mu_a, mu_l, vs).dot(a), -mu_a * fn * v / vs,
              mu_a * fn * v / vs * 1e-8);
  EXPECT_EQ(physics::smoothedFriction<3>(fn, Vec3::Zero(), a, l, mu_a, mu_l, vs).norm(), 0.0);
}

TEST(PhysicsKernels, PointBodyLiftDragAndContact) {
  AttachmentSpec s;
  s.volume = 2.0, s.drag_area = 1.5, s.cd = 0.8, s.added_mass = 0.0;
  s.seabed_contact = true;
  AttachmentWater w;
  w.enabled = true, w.density = kRho, w.gravity = 9.81;
  SeabedSpec bed;
  bed.enabled = true, bed.stiffness_normal = 1e5, bed.damping_normal = 0.0, bed.damping_tangential = 0.0;
  const Vec3 up(0.0, 0.0, 1.0), zero = Vec3::Zero(), uw(1.2, 0.0, 0.0);
  // 100 m under water, held still in a 1.2 m/s current, 0.05 m into the seabed:
  // lift ρ g V = 1025·9.81·2 = 20110.5 N; drag ½ ρ C_d A u² = ½·1025·0.8·1.5·1.44 = 885.6 N; bed 1e5·0.05 = 5000 N.
  const AttachmentLoad<Vec3> L =
      attachmentLoad<Vec3>(s, sphereRadius(s.volume), w, -100.0, up, zero, uw, zero, &bed, 0.05, up);
  EXPECT_NEAR(L.total.z(), 20110.5 + 5000.0, 1e-9 * 25110.5);
  EXPECT_NEAR(L.total.x(), 885.6, 1e-9 * 885.6);
  EXPECT_NEAR(L.conservative.z(), 20110.5 + 5000.0, 1e-9 * 25110.5);
  EXPECT_NEAR(L.k_normal, 1e5, 0.0);
}

}  // namespace
}  // namespace riser_sim
