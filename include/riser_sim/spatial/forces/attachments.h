// The attachments' forces on the 3D line (attachment.h, the law in physics/point_body.h, as the planar
// Attachments): buoyancy, drag, Froude-Krylov and seabed contact (the scene's plane, level or sloped) at each
// attachment's point, and its isotropic added mass m_a as added-mass moments of its rfe (added_mass.h).
// Energy: U = Σ (ρ_w g W + ½ C_n δ²), kinetic ½ m_a |v|²; power() = Σ (F - F_conservative)·v.
#pragma once
#include <vector>

#include "riser_sim/physics/point_body.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class Attachments : public ForceTerm3 {
 public:
  // Throws std::invalid_argument naming attachments[k] when one is off the line.
  Attachments(const Model3& model, const std::vector<AttachmentSpec>& specs, const WaterSpec& water,
              const SeabedSpec& seabed);
  std::string name() const override { return "attachments"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
  bool hasInertia() const override { return has_added_mass_; }
  void addInertia(const Model3& model, const Kinematics3& kin, std::vector<AddedMass3>& per_rfe) const override;
  double kineticEnergy(const Model3& model, const Kinematics3& kin) const override;

  int count() const { return int(bodies_.size()); }
  const AttachmentSpec& spec(int k) const { return bodies_[k].spec; }
  const AttachmentPoint& point(int k) const { return bodies_[k].at; }
  Vec3 position(const Kinematics3& kin, int k) const;
  // This term's force on attachment k and its weight [N].
  Vec3 force(const Model3& model, const Kinematics3& kin, double t, int k) const;

 private:
  struct Body {
    AttachmentSpec spec;
    AttachmentPoint at;
    double radius = 0.0;
  };
  AttachmentLoad<Vec3> load(const Body& a, const Kinematics3& kin, double t) const;
  double sweep(const Kinematics3& kin, double t, VecX* Q) const;
  std::vector<Body> bodies_;
  AttachmentWater water_;
  Water3 sea_;
  SeabedSpec seabed_;
  Seabed plane_;
  bool has_added_mass_ = false;
};

}  // namespace spatial
}  // namespace riser_sim
