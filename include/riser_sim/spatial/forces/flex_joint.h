// A flex joint: a rotational spring and damper between one end rfe's direction and a fixed direction d of
// what holds it (the hang-off's axis on the vessel, an anchor's axis), V = ½ k θ², θ = angle(d, e) (the
// bending spring's law, bending_spring.h, with d in place of the neighbour), and a damping torque
// -c ω on the rfe (ω = e × e'). Without it an end is pinned (free rotation). Riser engineers size flex joints
// by the moment it carries: moment() is the moment the line exerts on the holder [N m].
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class FlexJoint : public SpatialForceTerm {
 public:
  enum class End { kTop, kBottom };  // rfe 0 at A_0, or rfe n at its end E_n
  // direction: the unloaded axis of the joint, pointing along the line from the holder (normalised);
  // stiffness k [N m/rad] > 0, damping c [N m s/rad] >= 0.
  FlexJoint(End end, const Vec3& direction, double stiffness, double damping);
  std::string name() const override { return end_ == End::kTop ? "flex_joint_top" : "flex_joint_bottom"; }
  void addForces(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const SpatialModel& model, const Kinematics3& kin) const override;
  double power(const SpatialModel& model, const Kinematics3& kin, double t) const override;
  // The exact linearisation (spring Hessian, damper in the rate and through e) for the structured solves.
  void addStiffness(const SpatialModel& model, const Kinematics3& kin, double t, SpatialStiffness& S) const override;
  // The moment the line exerts on the holder through the joint [N m] (world frame): spring and damper.
  Vec3 moment(const SpatialModel& model, const Kinematics3& kin) const;
  // Rotation of the joint from its unloaded axis [rad].
  double angle(const SpatialModel& model, const Kinematics3& kin) const;

 private:
  int rfe(const SpatialModel& model) const { return end_ == End::kTop ? 0 : model.bodies() - 1; }
  // The line's direction at the joint, pointing away from the holder (e_0 at the top, -e_n at the bottom).
  Vec3 away(const SpatialModel& model, const Kinematics3& kin) const;
  // Torque [N m] the joint applies to its rfe.
  Vec3 torque(const SpatialModel& model, const Kinematics3& kin) const;
  End end_;
  Vec3 d_;
  double k_, c_;
};

}  // namespace spatial
}  // namespace riser_sim
