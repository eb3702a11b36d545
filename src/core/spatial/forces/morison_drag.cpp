#include "riser_sim/spatial/forces/morison_drag.h"

#include <cmath>

#include "riser_sim/physics/morison_drag.h"

namespace riser_sim {
namespace spatial {

Vec3 MorisonDrag::relativeVelocity(const BodyKinematics3& b, const WetPart3& w, double t) const {
  Vec3 rel = at_rest_ ? Vec3(Vec3::Zero()) : b.velocity(w.s0, w.kappa);
  if (water_.moving()) {
    Vec3 vw, aw;
    water_.at(b.point(w.s0, w.kappa), t, vw, aw);
    rel -= vw;
  }
  return rel;
}

double MorisonDrag::sweep(const Model3& model, const Kinematics3& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
      const Vec3 v = b.velocity(w.s0, w.kappa), rel = relativeVelocity(b, w, t);
      const Vec3 F = physics::morisonDrag<3>(rel, b.e, water_.spec().density, sec.dragDiameter(), w.length, cd_t, cd_n);
      if (Q) addPointForce(b, w.s0, w.kappa, F, Q->data() + kDofPerBody3 * i);
      pw += F.dot(v);
    }
  return pw;
}

void MorisonDrag::addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  sweep(model, kin, t, &Q);
}

double MorisonDrag::addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  return sweep(model, kin, t, &Q);
}

double MorisonDrag::power(const Model3& model, const Kinematics3& kin, double t) const {
  return sweep(model, kin, t, nullptr);
}

// -∂F/∂V' of each centroid (physics::morisonDragDamping), mapped by the point's Jacobian.
void MorisonDrag::addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const {
  if (at_rest_) return;  // no dependence on the rates
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
      const Mat3 Cp = physics::morisonDragDamping<3>(relativeVelocity(b, w, t), b.e, water_.spec().density,
                                                     sec.dragDiameter(), w.length, cd_t, cd_n);
      const Eigen::Matrix<double, 3, 7> J = pointJacobian(b, w.s0, w.kappa);
      S.C_diag[i] += J.transpose() * Cp * J;
    }
}

}  // namespace spatial
}  // namespace riser_sim
