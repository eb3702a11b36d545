// The attachments' forces on the planar line (attachment.h, the law in physics/point_body.h): buoyancy, drag,
// Froude-Krylov, seabed contact at each attachment's point, and its added mass in the rfe's mass block
// (M_i += m_a Pᵀ P, P = ∂v/∂q'_i of the point; h_i += m_a Pᵀ (2κΔ'φ' n - s φ'² e)). The weight is Gravity's.
// Energy: U = Σ (ρ_w g W + ½ C_n δ²); power() = Σ (F - F_conservative)·v.
#pragma once
#include <vector>

#include "riser_sim/physics/point_body.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {

class Attachments : public ForceTerm {
 public:
  // water: the scene's sea (disabled: no buoyancy, drag or Froude-Krylov); seabed: contact for those that ask.
  // Throws std::invalid_argument naming attachments[k] when one is off the line.
  Attachments(const Model& model, const std::vector<AttachmentSpec>& specs, const WaterSpec& water,
              const SeabedSpec& seabed, double gravity);
  std::string name() const override { return "attachments"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  double addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                           VecX& Q) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  bool hasInertia() const override { return has_added_mass_; }
  void addInertia(const Model& model, const Kinematics& kin, double t, AlignedVector<Mat4>& M, VecX& h) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  std::unique_ptr<ForceTerm> steadyTerm(double t) const override { return steadyTerm(t, 1.0); }
  std::unique_ptr<ForceTerm> steadyTerm(double t, double current_factor) const override;

  // The statics' continuation in the attachments: every attachment's whole load (its weight included, which the
  // Gravity term applies through its part) x factor: this term's forces x factor + (1 - factor) m g up.
  std::unique_ptr<ForceTerm> scaled(double factor) const;
  double loadFactor() const { return factor_; }

  int count() const { return int(bodies_.size()); }
  const AttachmentSpec& spec(int k) const { return bodies_[k].spec; }
  const AttachmentPoint& point(int k) const { return bodies_[k].at; }
  // The attachment's centre [m] and the force on it [N]: this term's and its weight (what it puts on the line
  // beside its inertia).
  Vec2 position(const Kinematics& kin, int k) const;
  Vec2 force(const Model& model, const Kinematics& kin, double t, int k) const;

 private:
  struct Body {
    AttachmentSpec spec;
    AttachmentPoint at;
    double radius = 0.0;
  };
  Attachments(const Attachments& other, const WaterKinematics& water);
  AttachmentLoad<Vec2> load(const Body& a, const Kinematics& kin, double t) const;
  // Adds the forces to *Q (when given); returns the power [W].
  double sweep(const Kinematics& kin, double t, VecX* Q) const;
  std::vector<Body> bodies_;
  AttachmentWater water_;
  WaterKinematics kinematics_;
  SeabedSpec seabed_;
  bool has_added_mass_ = false;
  double gravity_ = 0.0, factor_ = 1.0;
};

}  // namespace riser_sim
