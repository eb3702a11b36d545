// Rotational spring-damper between rfe i-1 and rfe i, i = 1..n (paper eq. 2, 5.1 with ½ restored):
// V = ½ c^b (φ_i - φ_{i-1})², moment M = c^b (φ_i - φ_{i-1}) + c_d (φ'_i - φ'_{i-1}).
#pragma once
#include "riser_sim/planar/force_term.h"

namespace riser_sim {

class BendingSpring : public ForceTerm {
 public:
  std::string name() const override { return "bending_spring"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
};

}  // namespace riser_sim
