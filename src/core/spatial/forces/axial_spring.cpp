#include "riser_sim/spatial/forces/axial_spring.h"

namespace riser_sim {
namespace spatial {

void AxialSpring::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  if (!model.options().axial_flexibility) return;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    Q[kDofPerBody3 * i + kDelta3] -= r.axial_stiffness * kin[i].delta + r.axial_damping * kin[i].delta_dot;
  }
}

double AxialSpring::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i) v += 0.5 * model.rfe(i).axial_stiffness * kin[i].delta * kin[i].delta;
  return v;
}

double AxialSpring::power(const Model3& model, const Kinematics3& kin, double) const {
  double p = 0.0;
  for (int i = 0; i < model.bodies(); ++i) p -= model.rfe(i).axial_damping * kin[i].delta_dot * kin[i].delta_dot;
  return p;
}

void AxialSpring::addStiffness(const Model3& model, const Kinematics3&, double, Stiffness3& S) const {
  if (!model.options().axial_flexibility) return;
  for (int i = 0; i < model.bodies(); ++i) {
    S.K_diag[i](kDelta3, kDelta3) += model.rfe(i).axial_stiffness;
    S.C_diag[i](kDelta3, kDelta3) += model.rfe(i).axial_damping;
  }
}

}  // namespace spatial
}  // namespace riser_sim
