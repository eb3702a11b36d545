#include "riser_sim/spatial/forces/morison_drag.h"

#include <cmath>

namespace riser_sim {
namespace spatial {

Vec3 MorisonDrag3::relativeVelocity(const BodyKinematics3& b, const WetPart3& w, double t) const {
  Vec3 rel = at_rest_ ? Vec3(Vec3::Zero()) : b.velocity(w.s0, w.kappa);
  if (water_.moving()) {
    Vec3 vw, aw;
    water_.at(b.point(w.s0, w.kappa), t, vw, aw);
    rel -= vw;
  }
  return rel;
}

double MorisonDrag3::sweep(const SpatialModel& model, const Kinematics3& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double k = 0.5 * water_.spec().density * sec.dragDiameter();
      const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
      const Vec3 v = b.velocity(w.s0, w.kappa), rel = relativeVelocity(b, w, t);
      const double vt = b.e.dot(rel);
      const Vec3 vn = rel - vt * b.e;
      const Vec3 F = -(k * w.length) * (cd_t * std::abs(vt) * vt * b.e + cd_n * vn.norm() * vn);
      if (Q) addPointForce(b, w.s0, w.kappa, F, Q->data() + kDofPerBody3 * i);
      pw += F.dot(v);
    }
  return pw;
}

void MorisonDrag3::addForces(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const {
  sweep(model, kin, t, &Q);
}

double MorisonDrag3::addForcesAndPower(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const {
  return sweep(model, kin, t, &Q);
}

double MorisonDrag3::power(const SpatialModel& model, const Kinematics3& kin, double t) const {
  return sweep(model, kin, t, nullptr);
}

// -∂F/∂V' = k l [2 D_ξ |V'_ξ| e eᵀ + D_η (|V'_η| (I - e eᵀ) + V'_η V'_ηᵀ / |V'_η|)], mapped by the point's Jacobian.
void MorisonDrag3::addStiffness(const SpatialModel& model, const Kinematics3& kin, double t,
                                SpatialStiffness& S) const {
  if (at_rest_) return;  // no dependence on the rates
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics3& b = kin[i];
      const WetPart3 w = wetPart3(model.line(), b, i, p, water_);
      if (!(w.length > 0.0)) continue;
      const LineSection& sec = model.line().partSection(i, p);
      const double k = 0.5 * water_.spec().density * sec.dragDiameter();
      const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
      const Vec3 rel = relativeVelocity(b, w, t);
      const double vt = b.e.dot(rel);
      const Vec3 vn = rel - vt * b.e;
      const double un = vn.norm();
      const Mat3 P = Mat3::Identity() - b.e * b.e.transpose();
      Mat3 Cp = (2.0 * cd_t * std::abs(vt)) * b.e * b.e.transpose() + (cd_n * un) * P;
      if (un > 0.0) Cp += (cd_n / un) * vn * vn.transpose();
      Cp *= k * w.length;
      const Eigen::Matrix<double, 3, 7> J = pointJacobian(b, w.s0, w.kappa);
      S.C_diag[i] += J.transpose() * Cp * J;
    }
}

}  // namespace spatial
}  // namespace riser_sim
