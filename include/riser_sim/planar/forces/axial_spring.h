// Longitudinal spring-damper inside each rfe (paper eq. 3, 5.2 with its missing ½ restored):
// V = ½ c^l Δ², force N = c^l Δ + c_d Δ' acting on Δ.
#pragma once
#include "riser_sim/planar/force_term.h"

namespace riser_sim {

class AxialSpring : public ForceTerm {
 public:
  std::string name() const override { return "axial_spring"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
};

}  // namespace riser_sim
