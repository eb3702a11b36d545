#include "riser_sim/spatial/forces/flex_joint.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/spatial/forces/bending_spring.h"

namespace riser_sim {
namespace spatial {

FlexJoint::FlexJoint(End end, const Vec3& direction, double stiffness, double damping)
    : end_(end), d_(direction.normalized()), k_(stiffness), c_(damping) {
  if (!(direction.norm() > 0.0) || !direction.allFinite())
    throw std::invalid_argument("flex joint: the direction must be a non-zero finite vector");
  if (!(stiffness > 0.0) || !std::isfinite(stiffness))
    throw std::invalid_argument("flex joint: the stiffness must be positive and finite [N m/rad]");
  if (!(damping >= 0.0) || !std::isfinite(damping))
    throw std::invalid_argument("flex joint: the damping must be >= 0 and finite [N m s/rad]");
}

Vec3 FlexJoint::away(const SpatialModel& model, const Kinematics3& kin) const {
  const Vec3& e = kin[rfe(model)].e;
  return end_ == End::kTop ? e : Vec3(-e);
}

double FlexJoint::angle(const SpatialModel& model, const Kinematics3& kin) const {
  return BendingSpring::angle(d_, away(model, kin));
}

// Spring: V = ½ k θ² turns the line's direction b toward d: torque k (θ/sinθ) (b × d)/|b| on the rfe (its
// e part, τ × e, is the bending spring's Q with d for the neighbour; the sign of b drops out of it).
// Damper: -c ω of the rfe.
Vec3 FlexJoint::torque(const SpatialModel& model, const Kinematics3& kin) const {
  const BodyKinematics3& b = kin[rfe(model)];
  const Vec3 u = away(model, kin);
  const double theta = BendingSpring::angle(d_, u);
  Vec3 tau = -c_ * b.omega();
  if (theta < M_PI - BendingSpring::kFoldedTol)
    tau += k_ * BendingSpring::thetaOverSin(theta) / u.norm() * u.cross(d_);
  return tau;
}

void FlexJoint::addForces(const SpatialModel& model, const Kinematics3& kin, double, VecX& Q) const {
  const int i = rfe(model);
  addTorque(kin[i], torque(model, kin), Q.data() + kDofPerBody3 * i);
}

double FlexJoint::potentialEnergy(const SpatialModel& model, const Kinematics3& kin) const {
  const double theta = angle(model, kin);
  return 0.5 * k_ * theta * theta;
}

double FlexJoint::power(const SpatialModel& model, const Kinematics3& kin, double) const {
  return -c_ * kin[rfe(model)].omega().squaredNorm();
}

namespace {
Mat3 crossMatrix(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}
}  // namespace

// Spring: torque() gives Q_e = ±k φ |b|² g with b = away = ±e, w = b/|b|, c = d·w, g = (d - c w)/|b| (= ∂c/∂b),
// φ = θ/sinθ; the sign drops out of ∂Q_e/∂e = ∂(k φ |b|² g)/∂b = k (-ψ |b|² g gᵀ + 2φ g bᵀ + φ |b|² ∂g/∂b),
// ψ = φ'(θ)/sinθ, ∂g/∂b as the bending spring's (bending_spring.cpp).
// Damping: Q_e = τ × e, τ = -c e × e': C_ee = c (|e|² I - e eᵀ), K_ee = -c [e]×[e']× + [τ]× (the bending
// damping's with the neighbour at rest).
void FlexJoint::addStiffness(const SpatialModel& model, const Kinematics3& kin, double, SpatialStiffness& S) const {
  const int i = rfe(model);
  const Mat3 I3 = Mat3::Identity();
  const Vec3 b = away(model, kin);
  const double theta = BendingSpring::angle(d_, b);
  if (theta < M_PI - BendingSpring::kFoldedTol) {
    const double lb = b.norm();
    const Vec3 w = b / lb;
    const double cs = d_.dot(w), sn = std::sin(theta), phi = BendingSpring::thetaOverSin(theta);
    const double psi = theta < 1e-4 ? 1.0 / 3.0 + 2.0 * theta * theta / 15.0
                                    : (sn - theta * std::cos(theta)) / (sn * sn * sn);
    const Vec3 g = (d_ - cs * w) / lb;
    const Mat3 dg = -(w * g.transpose() + g * w.transpose()) / lb - cs * (I3 - w * w.transpose()) / (lb * lb);
    const double bb = lb * lb;
    S.K_diag[i].block<3, 3>(kE, kE) -= k_ * (-psi * bb * g * g.transpose() + 2.0 * phi * g * b.transpose() + phi * bb * dg);
  }
  if (c_ != 0.0) {
    const BodyKinematics3& r = kin[i];
    const Mat3 X = crossMatrix(r.e);
    S.C_diag[i].block<3, 3>(kE, kE) -= c_ * X * X;
    S.K_diag[i].block<3, 3>(kE, kE) += c_ * X * crossMatrix(r.e_dot) - crossMatrix(-c_ * r.omega());
  }
}

Vec3 FlexJoint::moment(const SpatialModel& model, const Kinematics3& kin) const { return -torque(model, kin); }

}  // namespace spatial
}  // namespace riser_sim
