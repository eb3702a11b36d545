#include "riser_sim/spatial/forces/seabed.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/physics/seabed_contact.h"

namespace riser_sim {
namespace spatial {

namespace {

Vec3 upOf(const Vec3& gravity) { return gravity.norm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3::UnitZ(); }

}  // namespace

Seabed::Seabed(const SeabedSpec& spec, const Vec3& gravity) : spec_(spec), n_(upOf(gravity)), offset_(spec.level) {
  if (spec.slope == 0.0) return;  // level: n = up, the arithmetic of the level plane
  const Vec3 up = n_;
  // The heading's horizontal direction (normal to up; with gravity along -z, (cos, sin, 0)).
  Vec3 h = Vec3(std::cos(spec.slope_heading), std::sin(spec.slope_heading), 0.0);
  h -= up.dot(h) * up;
  h = h.norm() > 1e-12 ? Vec3(h.normalized()) : Vec3(up.unitOrthogonal());
  n_ = std::cos(spec.slope) * up - std::sin(spec.slope) * h;
  offset_ = spec.level * n_.dot(up);
}

Seabed::Contact Seabed::contact(const Model3& model, const Kinematics3& kin, int j) const {
  const int n1 = model.bodies();
  Contact c;
  c.body = j < n1 ? j : n1 - 1;
  c.s0 = j < n1 ? 0.0 : model.rfe(c.body).length;
  c.kappa = j < n1 ? 0.0 : 1.0;
  c.p = kin[c.body].point(c.s0, c.kappa);
  c.v = kin[c.body].velocity(c.s0, c.kappa);
  return c;
}

Vec3 Seabed::force(const Contact& c, const Vec3& e, bool conservative) const {
  const double pen = penetration(c.p);
  if (conservative) return (spec_.stiffness_normal * pen) * n_;
  const double vn = n_.dot(c.v);
  const double fn = physics::contactNormalForce(spec_.stiffness_normal, pen, spec_.damping_normal * vn);
  const Vec3 vh = c.v - vn * n_;
  Vec3 F = fn * n_ - spec_.damping_tangential * vh;
  if (fn > 0.0 && (spec_.friction_axial > 0.0 || spec_.friction_lateral > 0.0)) {
    Vec3 a, l;
    physics::frictionAxes(e, n_, a, l);
    F += physics::smoothedFriction<3>(fn, vh, a, l, spec_.friction_axial, spec_.friction_lateral,
                                      spec_.friction_velocity);
  }
  return F;
}

double Seabed::sweep(const Model3& model, const Kinematics3& kin, VecX* Q) const {
  double pw = 0.0;
  for (int j = 0; j <= model.bodies(); ++j) {
    const Contact c = contact(model, kin, j);
    if (!(penetration(c.p) > 0.0)) continue;
    const Vec3 F = force(c, kin[c.body].e, false);
    if (Q) addPointForce(kin[c.body], c.s0, c.kappa, F, Q->data() + kDofPerBody3 * c.body);
    pw += (F - force(c, kin[c.body].e, true)).dot(c.v);  // all but the spring: dampers, friction, the no-pull clamp
  }
  return pw;
}

void Seabed::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const { sweep(model, kin, &Q); }

double Seabed::addForcesAndPower(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  return sweep(model, kin, &Q);
}

double Seabed::power(const Model3& model, const Kinematics3& kin, double) const { return sweep(model, kin, nullptr); }

double Seabed::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int j = 0; j <= model.bodies(); ++j) {
    const double pen = penetration(contact(model, kin, j).p);
    if (pen > 0.0) v += physics::contactSpringEnergy(spec_.stiffness_normal, pen);
  }
  return v;
}

int Seabed::contacts(const Model3& model, const Kinematics3& kin) const {
  int n = 0;
  for (int j = 0; j <= model.bodies(); ++j) n += penetration(contact(model, kin, j).p) > 0.0;
  return n;
}

// The normal spring and damper, the tangential damper and the friction's exact rate dependence: with
// g = (μ_a v_a a + μ_l v_l l)/s, s = sqrt(v_a² + v_l² + v_s²), F_f = -F_n g gives -∂F_f/∂v_h =
// F_n (D - D v_p v_pᵀ / s²)/s on the plane (D = μ_a a aᵀ + μ_l l lᵀ, v_p = v_h), and through F_n = C_n p - c_n v_n
// the terms -c_n g nᵀ (rates) and -C_n g nᵀ (position). The turning of a with e is left out.
void Seabed::addStiffness(const Model3& model, const Kinematics3& kin, double, Stiffness3& S) const {
  const Mat3 UU = n_ * n_.transpose(), P = Mat3::Identity() - UU;
  const bool friction = spec_.friction_axial > 0.0 || spec_.friction_lateral > 0.0;
  for (int j = 0; j <= model.bodies(); ++j) {
    const Contact c = contact(model, kin, j);
    const double pen = penetration(c.p);
    if (!(pen > 0.0)) continue;
    const double vn = n_.dot(c.v);
    const double fn = physics::contactNormalForce(spec_.stiffness_normal, pen, spec_.damping_normal * vn);
    Mat3 K = spec_.stiffness_normal * UU;
    Mat3 C = spec_.damping_normal * UU + spec_.damping_tangential * P;
    if (friction && fn > 0.0) {
      const Vec3& e = kin[c.body].e;
      Vec3 a, l;
      physics::frictionAxes(e, n_, a, l);
      const Vec3 vh = c.v - vn * n_;
      const double vs = spec_.friction_velocity, s2 = vh.squaredNorm() + vs * vs, s = std::sqrt(s2);
      const Mat3 D = spec_.friction_axial * a * a.transpose() + spec_.friction_lateral * l * l.transpose();
      const Vec3 Dv = D * vh, g = Dv / s;
      C += (fn / s) * (D - Dv * vh.transpose() / s2);
      C -= spec_.damping_normal * g * n_.transpose();
      K -= spec_.stiffness_normal * g * n_.transpose();
    }
    const Eigen::Matrix<double, 3, 7> J = pointJacobian(kin[c.body], c.s0, c.kappa);
    S.K_diag[c.body] += J.transpose() * K * J;
    S.C_diag[c.body] += J.transpose() * C * J;
  }
}

}  // namespace spatial
}  // namespace riser_sim
