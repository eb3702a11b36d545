#include "riser_sim/spatial/forces/flex_joint.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/spatial/forces/bending_spring.h"

namespace riser_sim {
namespace spatial {

FlexJoint::FlexJoint(End end, const Vec3& direction, double stiffness, double damping,
                     std::shared_ptr<const TopMotion3> holder, double t0)
    : end_(end), d_(direction.normalized()), k_(stiffness), c_(damping), holder_(std::move(holder)) {
  if (!(direction.norm() > 0.0) || !direction.allFinite())
    throw std::invalid_argument("flex joint: the direction must be a non-zero finite vector");
  if (!(stiffness > 0.0) || !std::isfinite(stiffness))
    throw std::invalid_argument("flex joint: the stiffness must be positive and finite [N m/rad]");
  if (!(damping >= 0.0) || !std::isfinite(damping))
    throw std::invalid_argument("flex joint: the damping must be >= 0 and finite [N m s/rad]");
  if (holder_) d_ = holder_->at(t0).R.transpose() * d_;
}

FlexJoint::Axis FlexJoint::axis(double t) const {
  if (!holder_) return Axis{d_, Vec3::Zero()};
  const PointMotion3 m = holder_->at(t);
  return Axis{m.R * d_, m.w};
}

Vec3 FlexJoint::away(const Model3& model, const Kinematics3& kin) const {
  const Vec3& e = kin[rfe(model)].e;
  return end_ == End::kTop ? e : Vec3(-e);
}

double FlexJoint::angle(const Model3& model, const Kinematics3& kin, double t) const {
  return BendingSpring::angle(axis(t).d, away(model, kin));
}

// Spring: V = ½ k θ² turns the line's direction b toward d: torque k (θ/sinθ) (b × d)/|b| on the rfe (its
// e part, τ × e, is the bending spring's Q with d for the neighbour; the sign of b drops out of it).
Vec3 FlexJoint::springTorque(const Model3& model, const Kinematics3& kin, const Vec3& d) const {
  const Vec3 u = away(model, kin);
  const double theta = BendingSpring::angle(d, u);
  if (theta >= M_PI - BendingSpring::kFoldedTol) return Vec3::Zero();
  return k_ * BendingSpring::thetaOverSin(theta) / u.norm() * u.cross(d);
}

// Damper: -c (ω - w⊥), w⊥ the holder's angular velocity across the line (its spin about the line is no
// degree of freedom of the rfe here).
Vec3 FlexJoint::damperTorque(const Model3& model, const Kinematics3& kin, const Vec3& w) const {
  const BodyKinematics3& b = kin[rfe(model)];
  if (c_ == 0.0) return Vec3::Zero();
  const Vec3 e = b.e / b.e.norm();
  return -c_ * (b.omega() - (w - w.dot(e) * e));
}

void FlexJoint::addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  const int i = rfe(model);
  const Axis a = axis(t);
  addTorque(kin[i], springTorque(model, kin, a.d) + damperTorque(model, kin, a.w), Q.data() + kDofPerBody3 * i);
}

double FlexJoint::potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const {
  const double theta = angle(model, kin, t);
  return 0.5 * k_ * theta * theta;
}

double FlexJoint::power(const Model3& model, const Kinematics3& kin, double t) const {
  const Axis a = axis(t);
  const Vec3 omega = kin[rfe(model)].omega();
  double p = damperTorque(model, kin, a.w).dot(omega);
  if (holder_) p += springTorque(model, kin, a.d).dot(a.w);
  return p;
}

double FlexJoint::addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  const int i = rfe(model);
  const Axis a = axis(t);
  const Vec3 ts = springTorque(model, kin, a.d), td = damperTorque(model, kin, a.w);
  addTorque(kin[i], ts + td, Q.data() + kDofPerBody3 * i);
  return td.dot(kin[i].omega()) + ts.dot(a.w);
}

namespace {
Mat3 crossMatrix(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}
}  // namespace

// Spring: springTorque() gives Q_e = ±k φ |b|² g with b = away = ±e, w = b/|b|, c = d·w, g = (d - c w)/|b|
// (= ∂c/∂b), φ = θ/sinθ; the sign drops out of ∂Q_e/∂e = ∂(k φ |b|² g)/∂b = k (-ψ |b|² g gᵀ + 2φ g bᵀ +
// φ |b|² ∂g/∂b), ψ = φ'(θ)/sinθ, ∂g/∂b as the bending spring's (bending_spring.cpp).
// Damping: Q_e = τ × e gives K = -[τ]× + [e]× ∂τ/∂e; τ = -c e × e' + c (w - (w·e) e): C_ee = c (|e|² I - e eᵀ),
// K_ee = c [e]×[e']× - [τ]× - c (w·e) [e]× (the holder's part through its projection across e).
void FlexJoint::addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const {
  const int i = rfe(model);
  const Mat3 I3 = Mat3::Identity();
  const Axis a = axis(t);
  const Vec3& d = a.d;
  const Vec3 b = away(model, kin);
  const double theta = BendingSpring::angle(d, b);
  if (theta < M_PI - BendingSpring::kFoldedTol) {
    const double lb = b.norm();
    const Vec3 w = b / lb;
    const double cs = d.dot(w), sn = std::sin(theta), phi = BendingSpring::thetaOverSin(theta);
    const double psi =
        theta < 1e-4 ? 1.0 / 3.0 + 2.0 * theta * theta / 15.0 : (sn - theta * std::cos(theta)) / (sn * sn * sn);
    const Vec3 g = (d - cs * w) / lb;
    const Mat3 dg = -(w * g.transpose() + g * w.transpose()) / lb - cs * (I3 - w * w.transpose()) / (lb * lb);
    const double bb = lb * lb;
    S.K_diag[i].block<3, 3>(kE, kE) -=
        k_ * (-psi * bb * g * g.transpose() + 2.0 * phi * g * b.transpose() + phi * bb * dg);
  }
  if (c_ != 0.0) {
    const BodyKinematics3& r = kin[i];
    const Mat3 X = crossMatrix(r.e);
    const Vec3 e = r.e / r.e.norm();
    const Vec3 tau = -c_ * (r.omega() - (a.w - a.w.dot(e) * e));
    S.C_diag[i].block<3, 3>(kE, kE) -= c_ * X * X;
    S.K_diag[i].block<3, 3>(kE, kE) += c_ * X * crossMatrix(r.e_dot) - crossMatrix(tau) - c_ * a.w.dot(r.e) * X;
  }
}

Vec3 FlexJoint::moment(const Model3& model, const Kinematics3& kin, double t) const {
  const Axis a = axis(t);
  return -(springTorque(model, kin, a.d) + damperTorque(model, kin, a.w));
}

}  // namespace spatial
}  // namespace riser_sim
