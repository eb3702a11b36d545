#include "riser_sim/spatial/forces/added_mass.h"

namespace riser_sim {
namespace spatial {

void AddedMass::addInertia(const Model3& model, const Kinematics3& kin, std::vector<AddedMass3>& per_rfe) const {
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double mw = water_.spec().density * sec.props.externalArea() * w.length, c = w.s0 + w.kappa * b.delta;
      per_rfe[i].normal.add(caN(sec) * mw, c, w.kappa);
      per_rfe[i].axial.add(caT(sec) * mw, c, w.kappa);
    }
}

// energy: Σ ½ m_w v_cᵀ T v_c; else the power ½ v_cᵀ T' v_c = (C_a,t - C_a,n) m_w (n'·v_c)(n·v_c).
double AddedMass::sweep(const Model3& model, const Kinematics3& kin, bool energy) const {
  double sum = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double mw = water_.spec().density * sec.props.externalArea() * w.length, rho = b.e.norm();
      const double ca_n = caN(sec), ca_t = caT(sec);
      const Vec3 n = b.e / rho, v = b.velocity(w.s0, w.kappa);
      const double vn = n.dot(v);
      if (energy) {
        sum += 0.5 * mw * (ca_n * (v.squaredNorm() - vn * vn) + ca_t * vn * vn);
      } else {
        const Vec3 n_dot = (b.e_dot - n.dot(b.e_dot) * n) / rho;
        sum += (ca_t - ca_n) * mw * n_dot.dot(v) * vn;
      }
    }
  return sum;
}

double AddedMass::power(const Model3& model, const Kinematics3& kin, double) const { return sweep(model, kin, false); }

double AddedMass::kineticEnergy(const Model3& model, const Kinematics3& kin) const { return sweep(model, kin, true); }

}  // namespace spatial
}  // namespace riser_sim
