// Weight of every rigid part and of the end mass along the model's gravity vector g:
// F_p = m_p g at each centre, V = -Σ m_p g·x_p.
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class Gravity : public ForceTerm3 {
 public:
  std::string name() const override { return "gravity"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3&, const Kinematics3&, double) const override { return 0.0; }  // conservative
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
};

}  // namespace spatial
}  // namespace riser_sim
