// A flex joint: a rotational spring and damper between one end rfe's direction and the axis d of what holds
// it (the hang-off's axis on the vessel, an anchor's axis), V = ½ k θ², θ = angle(d, e) (the bending spring's
// law, bending_spring.h, with d in place of the neighbour), and a damping torque -c (ω - w) on the rfe
// (ω = e × e', w the holder's angular velocity across the line). Without it an end is pinned (free rotation).
// The axis turns with its holder: d(t) = R(t) d_h, R(t) the holder's orientation (PointMotion3::R); fixed in
// the world without one. power() is the damper's τ_d·ω and the turning holder's work on the spring, τ_s·w
// (= ∂V/∂t), so E - E0 - W still closes. Riser engineers
// size flex joints by the moment it carries: moment() is the moment the line exerts on the holder [N m].
#pragma once
#include <memory>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {

class FlexJoint : public ForceTerm3 {
 public:
  enum class End { kTop, kBottom };  // rfe 0 at A_0, or rfe n at its end E_n
  // direction: the unloaded axis of the joint at time t0 in the world frame, pointing along the line from the
  // holder (normalised); stiffness k [N m/rad] > 0, damping c [N m s/rad] >= 0; holder: the motion of what
  // holds the joint (its R and w turn the axis; nullptr: the axis is fixed in the world).
  FlexJoint(End end, const Vec3& direction, double stiffness, double damping,
            std::shared_ptr<const TopMotion3> holder = nullptr, double t0 = 0.0);
  std::string name() const override { return end_ == End::kTop ? "flex_joint_top" : "flex_joint_bottom"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  // The exact linearisation (spring Hessian, damper in the rate and through e) for the structured solves.
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
  // The moment the line exerts on the holder through the joint at time t [N m] (world frame): spring and damper.
  Vec3 moment(const Model3& model, const Kinematics3& kin, double t) const;
  // Rotation of the joint from its unloaded axis at time t [rad].
  double angle(const Model3& model, const Kinematics3& kin, double t) const;
  // The unloaded axis at time t (world frame) and the holder's angular velocity [rad/s].
  struct Axis {
    Vec3 d, w;
  };
  Axis axis(double t) const;
  bool turnsWithHolder() const { return holder_ != nullptr; }

 private:
  int rfe(const Model3& model) const { return end_ == End::kTop ? 0 : model.bodies() - 1; }
  // The line's direction at the joint, pointing away from the holder (e_0 at the top, -e_n at the bottom).
  Vec3 away(const Model3& model, const Kinematics3& kin) const;
  // Torques [N m] the joint's spring and damper apply to its rfe.
  Vec3 springTorque(const Model3& model, const Kinematics3& kin, const Vec3& d) const;
  Vec3 damperTorque(const Model3& model, const Kinematics3& kin, const Vec3& w) const;
  End end_;
  Vec3 d_;  // the axis in the holder's frame (in the world's without a holder)
  double k_, c_;
  std::shared_ptr<const TopMotion3> holder_;
};

}  // namespace spatial
}  // namespace riser_sim
