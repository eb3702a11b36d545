#include "riser_sim/spatial/forces/added_mass.h"

namespace riser_sim {
namespace spatial {

void AddedMassTerm::addInertia(const SpatialModel& model, const Kinematics3& kin, std::vector<AddedMass3>& per_rfe) const {
  const double rhoA = water_.spec().density * model.line().line().externalArea();
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const double mw = rhoA * w.length, c = w.s0 + w.kappa * b.delta;
      per_rfe[i].normal.add(ca_n_ * mw, c, w.kappa);
      per_rfe[i].axial.add(ca_t_ * mw, c, w.kappa);
    }
}

// energy: Σ ½ m_w v_cᵀ T v_c; else the power ½ v_cᵀ T' v_c = (C_a,t - C_a,n) m_w (n'·v_c)(n·v_c).
double AddedMassTerm::sweep(const SpatialModel& model, const Kinematics3& kin, bool energy) const {
  const double rhoA = water_.spec().density * model.line().line().externalArea();
  double sum = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const double mw = rhoA * w.length, rho = b.e.norm();
      const Vec3 n = b.e / rho, v = b.velocity(w.s0, w.kappa);
      const double vn = n.dot(v);
      if (energy) {
        sum += 0.5 * mw * (ca_n_ * (v.squaredNorm() - vn * vn) + ca_t_ * vn * vn);
      } else {
        const Vec3 n_dot = (b.e_dot - n.dot(b.e_dot) * n) / rho;
        sum += (ca_t_ - ca_n_) * mw * n_dot.dot(v) * vn;
      }
    }
  return sum;
}

double AddedMassTerm::power(const SpatialModel& model, const Kinematics3& kin, double) const {
  return sweep(model, kin, false);
}

double AddedMassTerm::kineticEnergy(const SpatialModel& model, const Kinematics3& kin) const {
  return sweep(model, kin, true);
}

}  // namespace spatial
}  // namespace riser_sim
