// Longitudinal spring c_l = EA/l_i and damper c_EA/l_i on Δ_i of every rfe: V = ½ c_l Δ², P = -c Δ'².
// Without axial flexibility Δ is locked and the term does nothing.
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class AxialSpring : public ForceTerm3 {
 public:
  std::string name() const override { return "axial_spring"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
};

}  // namespace spatial
}  // namespace riser_sim
