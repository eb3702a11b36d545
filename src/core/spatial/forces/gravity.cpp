#include "riser_sim/spatial/forces/gravity.h"

namespace riser_sim {
namespace spatial {

// Σ over parts of [m_p g; κ_p e·m_p g; s_p m_p g] = [m g; m_k e·g; S(Δ) g].
void Gravity::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  const Vec3& g = model.gravity();
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics3& b = kin[i];
    double* q = Q.data() + kDofPerBody3 * i;
    const double S = r.firstMoment(b.delta);
    for (int k = 0; k < 3; ++k) q[kA + k] += r.mass * g[k], q[kE + k] += S * g[k];
    q[kDelta3] += r.mass_k * b.e.dot(g);
  }
}

double Gravity::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    for (int p = 0; p < r.num_parts; ++p)
      v -= r.part[p].mass * model.gravity().dot(kin[i].point(r.part[p].s0, r.part[p].kappa));
  }
  return v;
}

// Geometric part: Q_Δ = m_k e·g and Q_e = S(Δ) g, dS/dΔ = m_k (Δ only moves with axial flexibility).
void Gravity::addStiffness(const Model3& model, const Kinematics3&, double, Stiffness3& S) const {
  if (!model.options().axial_flexibility) return;
  const Vec3& g = model.gravity();
  for (int i = 0; i < model.bodies(); ++i) {
    const double mk = model.rfe(i).mass_k;
    S.K_diag[i].block<1, 3>(kDelta3, kE) -= mk * g.transpose();
    S.K_diag[i].block<3, 1>(kE, kDelta3) -= mk * g;
  }
}

}  // namespace spatial
}  // namespace riser_sim
