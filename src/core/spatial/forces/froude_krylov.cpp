#include "riser_sim/spatial/forces/froude_krylov.h"

#include "riser_sim/physics/buoyancy.h"

namespace riser_sim {
namespace spatial {

double FroudeKrylov::sweep(const Model3& model, const Kinematics3& kin, double t, VecX* Q) const {
  if (!water_.moving()) return 0.0;
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      Vec3 vw, aw;
      water_.at(b.point(w.s0, w.kappa), t, vw, aw);
      const LineSection& sec = model.line().partSection(i, p);
      const double rhoA = water_.spec().density * sec.props.externalArea();
      const double cm_n = orLine(sec.hydro.inertia_coefficient, cm_n_);
      const double cm_t = 1.0 + orLine(sec.hydro.axial_added_mass, cm_t_ - 1.0);
      const Vec3 F = physics::froudeKrylov<3>(rhoA, w.length, aw, b.e, cm_n, cm_t);
      if (Q) addPointForce(b, w.s0, w.kappa, F, Q->data() + kDofPerBody3 * i);
      pw += F.dot(b.velocity(w.s0, w.kappa));
    }
  return pw;
}

void FroudeKrylov::addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  sweep(model, kin, t, &Q);
}

double FroudeKrylov::addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  return sweep(model, kin, t, &Q);
}

double FroudeKrylov::power(const Model3& model, const Kinematics3& kin, double t) const {
  return sweep(model, kin, t, nullptr);
}

}  // namespace spatial
}  // namespace riser_sim
