#include "riser_sim/planar/forces/end_load.h"

namespace riser_sim {

void EndLoad::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  const int n = model.bodies() - 1;
  Q.segment<4>(4 * n) += pointForce(kin[n], model.rfe(n).length, 1.0, force_);
}

// A dead load: only the geometric part (its lever arm turns with φ_n and stretches with Δ_n).
bool EndLoad::addStiffness(const Model& model, const TermData*, const Kinematics& kin, double,
                           StiffnessBlocks& S) const {
  const int n = model.bodies() - 1;
  addPointStiffness(kin[n], model.rfe(n).length, 1.0, force_, Mat2::Zero(), Mat2::Zero(), S.K_diag[n], S.C_diag[n]);
  return true;
}

double EndLoad::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  const int n = model.bodies() - 1;
  return -force_.dot(kin[n].end());
}

}  // namespace riser_sim
