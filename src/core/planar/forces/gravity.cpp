#include "riser_sim/planar/forces/gravity.h"

namespace riser_sim {

void Gravity::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  // Σ over parts of B_p^T (0, -m_p g): [0, -m g, -mk g sinφ, -S(Δ) g cosφ].
  const double g = model.gravity();
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics& b = kin[i];
    double* q = Q.data() + 4 * i;
    q[kY] -= r.mass * g;
    q[kDelta] -= r.mass_k * g * b.s;
    q[kPhi] -= r.firstMoment(b.delta) * g * b.c;
  }
}

double Gravity::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    for (int p = 0; p < r.num_parts; ++p)
      v += r.part[p].mass * model.gravity() * kin[i].point(r.part[p].s0, r.part[p].kappa).y();
  }
  return v;
}

}  // namespace riser_sim

namespace riser_sim {

// Only the geometric part: the weights are constant, their lever arms turn with φ and stretch with Δ.
bool Gravity::addStiffness(const Model& model, const TermData*, const Kinematics& kin, double,
                           StiffnessBlocks& S) const {
  const double g = model.gravity();
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics& b = kin[i];
    Mat4& K = S.K_diag[i];
    K(kDelta, kPhi) += r.mass_k * g * b.c;
    K(kPhi, kDelta) += r.mass_k * g * b.c;
    K(kPhi, kPhi) -= r.firstMoment(b.delta) * g * b.s;
  }
  return true;
}

}  // namespace riser_sim
