// Mass-proportional damping Q = -α ∂T/∂q' = -α M q' [1/s]: per part, the force -α m_p v_p at its centre and the
// couple -α J_p e' on e. Not a physical load: the dynamic relaxation's (spatial/relaxation.h), where it decays every
// mode at least at α/2 whatever the masses.
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class MassDamping : public ForceTerm3 {
 public:
  explicit MassDamping(double alpha) : alpha_(alpha) {}
  std::string name() const override { return "relaxation_damping"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3&, const Kinematics3&, double) const override { return 0.0; }
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;

 private:
  double sweep(const Model3& model, const Kinematics3& kin, VecX* Q) const;
  double alpha_;
};

}  // namespace spatial
}  // namespace riser_sim
