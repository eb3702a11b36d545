// Weight of every rigid part and of the end mass, in air: F = (0, -m g) at each centre of mass
// (paper eq. 5.3). Potential energy V = Σ m g y_c.
#pragma once
#include "riser_sim/planar/force_term.h"

namespace riser_sim {

class Gravity : public ForceTerm {
 public:
  std::string name() const override { return "gravity"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model&, const TermData*, const Kinematics&, double) const override { return 0.0; }  // conservative
};

}  // namespace riser_sim
