#include "riser_sim/planar/forces/hydro_inertia.h"

#include "riser_sim/planar/forces/buoyancy.h"
#include "riser_sim/physics/buoyancy.h"

namespace riser_sim {

void HydroInertia::addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  if (water_.moving()) sweep(model, kin, t, &Q);
}

void HydroInertia::addInertia(const Model& model, const Kinematics& kin, double, AlignedVector<Mat4>& M,
                              VecX& h) const {
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics& b = kin[i];
      const WetPart w = wetPart(model, b, i, p, water_.spec().surface);
      if (w.length <= 0.0) continue;
      const LineSection& sec = model.partSection(i, p);
      const double rhoA = water_.spec().density * sec.props.externalArea();
      const double cm = orLine(sec.hydro.inertia_coefficient, cm_), ca_t = orLine(sec.hydro.axial_added_mass, ca_t_);
      const double mw = rhoA * w.length, s = w.s0 + w.kappa * b.delta;
      if (cm != 1.0) {
        const double ma = (cm - 1.0) * water_.spec().density * sec.props.externalArea() * w.length;
        const Vec4 row(-b.s, b.c, 0.0, s);  // n^T B: normal velocity of the point per q'
        M[i] += ma * row * row.transpose();
        h.segment<4>(4 * i) += ma * (2.0 * w.kappa * b.delta_dot * b.phi_dot) * row;
      }
      if (ca_t != 0.0) {  // e·a = e^T B q'' - s φ'²
        const double ma = ca_t * mw;
        const Vec4 row(b.c, b.s, w.kappa, 0.0);  // e^T B: axial velocity of the point per q'
        M[i] += ma * row * row.transpose();
        h.segment<4>(4 * i) -= ma * (s * b.phi_dot * b.phi_dot) * row;
      }
    }
}

double HydroInertia::addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                                       VecX& Q) const {
  return sweep(model, kin, t, &Q);
}

double HydroInertia::power(const Model& model, const TermData*, const Kinematics& kin, double t) const {
  return sweep(model, kin, t, nullptr);
}

// With the added-mass energy ½ m_w ((C_M - 1)(n·v)² + C_a,t (e·v)²) in the kinetic energy, the balance needs
// (C_a,t - (C_M - 1)) m_w φ' (n·v)(e·v) (n and e turn) plus the Froude-Krylov power.
double HydroInertia::sweep(const Model& model, const Kinematics& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics& b = kin[i];
      const WetPart w = wetPart(model, b, i, p, water_.spec().surface);
      if (w.length <= 0.0) continue;
      const LineSection& sec = model.partSection(i, p);
      const double rhoA = water_.spec().density * sec.props.externalArea();
      const double cm = orLine(sec.hydro.inertia_coefficient, cm_), ca_t = orLine(sec.hydro.axial_added_mass, ca_t_);
      const Vec2 v = b.velocity(w.s0, w.kappa);
      pw += (ca_t - (cm - 1.0)) * rhoA * w.length * b.phi_dot * b.nrm().dot(v) * b.e().dot(v);
      if (water_.moving()) {
        Vec2 vw, aw;
        water_.at(b.point(w.s0, w.kappa), t, vw, aw);
        const Vec2 F = physics::froudeKrylov<2>(rhoA, w.length, aw, b.e(), cm, 1.0 + ca_t);
        if (Q) Q->segment<4>(4 * i) += pointForce(b, w.s0, w.kappa, F);
        pw += F.dot(v);
      }
    }
  return pw;
}

}  // namespace riser_sim
