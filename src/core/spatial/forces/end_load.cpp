#include "riser_sim/spatial/forces/end_load.h"

namespace riser_sim {
namespace spatial {

// The end E_n = A_n + (l_n + Δ_n) e_n: s0 = l_n, κ = 1.
void EndLoad::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  const int n = model.bodies() - 1;
  addPointForce(kin[n], model.rfe(n).length, 1.0, force_, Q.data() + kDofPerBody3 * n);
}

double EndLoad::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  return -force_.dot(kin[model.bodies() - 1].end());
}

}  // namespace spatial
}  // namespace riser_sim
