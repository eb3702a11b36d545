#include "riser_sim/forces/bending_spring.h"

namespace riser_sim {

void BendingSpring::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  const double k = model.bendingStiffness(), c = model.bendingDamping();
  for (int i = 1; i < model.bodies(); ++i) {
    const double m = k * (kin[i].phi - kin[i - 1].phi) + c * (kin[i].phi_dot - kin[i - 1].phi_dot);
    Q[4 * i + kPhi] -= m;
    Q[4 * (i - 1) + kPhi] += m;
  }
}

double BendingSpring::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double dphi = kin[i].phi - kin[i - 1].phi;
    v += 0.5 * model.bendingStiffness() * dphi * dphi;
  }
  return v;
}

double BendingSpring::power(const Model& model, const TermData*, const Kinematics& kin, double) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double w = kin[i].phi_dot - kin[i - 1].phi_dot;
    p -= model.bendingDamping() * w * w;
  }
  return p;
}

}  // namespace riser_sim

namespace riser_sim {

// ½ k (φ_i - φ_{i-1})²: +k on both diagonals, -k between the neighbours (same for the damping).
bool BendingSpring::addStiffness(const Model& model, const TermData*, const Kinematics&, double, StiffnessBlocks& S) const {
  const double k = model.bendingStiffness(), c = model.bendingDamping();
  for (int i = 1; i < model.bodies(); ++i) {
    S.K_diag[i](kPhi, kPhi) += k;
    S.K_diag[i - 1](kPhi, kPhi) += k;
    S.K_sub[i](kPhi, kPhi) -= k;
    S.C_diag[i](kPhi, kPhi) += c;
    S.C_diag[i - 1](kPhi, kPhi) += c;
    S.C_sub[i](kPhi, kPhi) -= c;
  }
  return true;
}

}  // namespace riser_sim
