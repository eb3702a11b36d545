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

Vec3 FlexJoint::moment(const SpatialModel& model, const Kinematics3& kin) const { return -torque(model, kin); }

}  // namespace spatial
}  // namespace riser_sim
