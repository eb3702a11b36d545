#include "riser_sim/planar/forces/bending_spring.h"

namespace riser_sim {

// Spring i between rfes i-1 and i: c_i = 1 / ∫ ds/EI over segment i-1 (Model::bendingStiffness(i)).
void BendingSpring::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  for (int i = 1; i < model.bodies(); ++i) {
    const double m = model.bendingStiffness(i) * (kin[i].phi - kin[i - 1].phi) +
                     model.bendingDamping(i) * (kin[i].phi_dot - kin[i - 1].phi_dot);
    Q[4 * i + kPhi] -= m;
    Q[4 * (i - 1) + kPhi] += m;
  }
}

double BendingSpring::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double dphi = kin[i].phi - kin[i - 1].phi;
    v += 0.5 * model.bendingStiffness(i) * dphi * dphi;
  }
  return v;
}

double BendingSpring::power(const Model& model, const TermData*, const Kinematics& kin, double) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double w = kin[i].phi_dot - kin[i - 1].phi_dot;
    p -= model.bendingDamping(i) * w * w;
  }
  return p;
}

}  // namespace riser_sim

namespace riser_sim {

// ½ k_i (φ_i - φ_{i-1})²: +k_i on both diagonals, -k_i between the neighbours (same for the damping).
bool BendingSpring::addStiffness(const Model& model, const TermData*, const Kinematics&, double,
                                 StiffnessBlocks& S) const {
  for (int i = 1; i < model.bodies(); ++i) {
    const double k = model.bendingStiffness(i), c = model.bendingDamping(i);
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
