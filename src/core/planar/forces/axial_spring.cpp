#include "riser_sim/planar/forces/axial_spring.h"

namespace riser_sim {

void AxialSpring::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    Q[4 * i + kDelta] -= r.axial_stiffness * kin[i].delta + r.axial_damping * kin[i].delta_dot;
  }
}

double AxialSpring::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i) v += 0.5 * model.rfe(i).axial_stiffness * kin[i].delta * kin[i].delta;
  return v;
}

double AxialSpring::power(const Model& model, const TermData*, const Kinematics& kin, double) const {
  double p = 0.0;
  for (int i = 0; i < model.bodies(); ++i) p -= model.rfe(i).axial_damping * kin[i].delta_dot * kin[i].delta_dot;
  return p;
}

}  // namespace riser_sim

namespace riser_sim {

bool AxialSpring::addStiffness(const Model& model, const TermData*, const Kinematics&, double,
                               StiffnessBlocks& S) const {
  for (int i = 0; i < model.bodies(); ++i) {
    S.K_diag[i](kDelta, kDelta) += model.rfe(i).axial_stiffness;
    S.C_diag[i](kDelta, kDelta) += model.rfe(i).axial_damping;
  }
  return true;
}

}  // namespace riser_sim
