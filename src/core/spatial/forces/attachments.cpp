#include "riser_sim/spatial/forces/attachments.h"

namespace riser_sim {
namespace spatial {

Attachments::Attachments(const Model3& model, const std::vector<AttachmentSpec>& specs, const WaterSpec& water,
                         const SeabedSpec& seabed)
    : sea_(water.enabled ? water : WaterSpec(), model.gravity()), seabed_(seabed), plane_(seabed, model.gravity()) {
  const double g = model.gravity().norm();
  water_.enabled = water.enabled && g != 0.0;
  water_.density = water.density;
  water_.gravity = g;
  for (size_t k = 0; k < specs.size(); ++k) {
    Body b;
    b.spec = specs[k];
    b.at = locateAttachment(model.line(), b.spec.arc_length, "attachments[" + std::to_string(k) + "].arc_length");
    b.radius = sphereRadius(b.spec.volume);
    has_added_mass_ = has_added_mass_ || b.spec.added_mass > 0.0;
    bodies_.push_back(b);
  }
}

AttachmentLoad<Vec3> Attachments::load(const Body& a, const Kinematics3& kin, double t) const {
  const BodyKinematics3& b = kin[a.at.rfe];
  const Vec3 p = b.point(a.at.s0, a.at.kappa), v = b.velocity(a.at.s0, a.at.kappa);
  Vec3 uw = Vec3::Zero(), aw = Vec3::Zero();
  if (water_.enabled && sea_.moving()) sea_.at(p, t, uw, aw);
  const bool contact = seabed_.enabled && a.spec.seabed_contact;
  return attachmentLoad<Vec3>(a.spec, a.radius, water_, sea_.height(p), sea_.up(), v, uw, aw,
                              contact ? &seabed_ : nullptr, plane_.penetration(p), plane_.normal());
}

double Attachments::sweep(const Kinematics3& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (const Body& a : bodies_) {
    const AttachmentLoad<Vec3> L = load(a, kin, t);
    const BodyKinematics3& b = kin[a.at.rfe];
    if (Q) addPointForce(b, a.at.s0, a.at.kappa, L.total, Q->data() + kDofPerBody3 * a.at.rfe);
    pw += (L.total - L.conservative).dot(b.velocity(a.at.s0, a.at.kappa));
  }
  return pw;
}

void Attachments::addForces(const Model3&, const Kinematics3& kin, double t, VecX& Q) const { sweep(kin, t, &Q); }

double Attachments::addForcesAndPower(const Model3&, const Kinematics3& kin, double t, VecX& Q) const {
  return sweep(kin, t, &Q);
}

double Attachments::power(const Model3&, const Kinematics3& kin, double t) const { return sweep(kin, t, nullptr); }

double Attachments::potentialEnergy(const Model3&, const Kinematics3& kin, double t) const {
  double e = 0.0;
  for (const Body& a : bodies_) e += load(a, kin, t).energy;
  return e;
}

// Q = Jᵀ F, J = [I, κ e, s I]: K = Jᵀ Kp J - ∂Jᵀ/∂q F (the geometric part: Q_Δ = κ e·F, Q_e = s F).
void Attachments::addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const {
  for (const Body& a : bodies_) {
    const AttachmentLoad<Vec3> L = load(a, kin, t);
    const BodyKinematics3& b = kin[a.at.rfe];
    const Vec3 up = sea_.up(), n = plane_.normal();
    Mat3 Kp = L.k_up * up * up.transpose() + L.k_normal * n * n.transpose();
    Mat3 Cp = L.c_normal * n * n.transpose() + L.c_tangential * (Mat3::Identity() - n * n.transpose());
    if (L.drag > 0.0) {
      Vec3 uw = Vec3::Zero(), aw = Vec3::Zero();
      if (sea_.moving()) sea_.at(b.point(a.at.s0, a.at.kappa), t, uw, aw);
      const Vec3 u = uw - b.velocity(a.at.s0, a.at.kappa);
      const double un = u.norm();
      if (un > 0.0) Cp += L.drag * (un * Mat3::Identity() + u * u.transpose() / un);
    }
    const auto J = pointJacobian(b, a.at.s0, a.at.kappa);
    S.K_diag[a.at.rfe].noalias() += J.transpose() * Kp * J;
    S.C_diag[a.at.rfe].noalias() += J.transpose() * Cp * J;
    if (model.options().axial_flexibility && a.at.kappa != 0.0) {
      S.K_diag[a.at.rfe].block<1, 3>(kDelta3, kE) -= a.at.kappa * L.total.transpose();
      S.K_diag[a.at.rfe].block<3, 1>(kE, kDelta3) -= a.at.kappa * L.total;
    }
  }
}

void Attachments::addInertia(const Model3&, const Kinematics3& kin, std::vector<AddedMass3>& per_rfe) const {
  for (const Body& a : bodies_) {
    if (!(a.spec.added_mass > 0.0)) continue;
    const double c = a.at.s0 + a.at.kappa * kin[a.at.rfe].delta;
    per_rfe[a.at.rfe].normal.add(a.spec.added_mass, c, a.at.kappa);  // isotropic: across and along alike
    per_rfe[a.at.rfe].axial.add(a.spec.added_mass, c, a.at.kappa);
  }
}

double Attachments::kineticEnergy(const Model3&, const Kinematics3& kin) const {
  double T = 0.0;
  for (const Body& a : bodies_)
    if (a.spec.added_mass > 0.0)
      T += 0.5 * a.spec.added_mass * kin[a.at.rfe].velocity(a.at.s0, a.at.kappa).squaredNorm();
  return T;
}

Vec3 Attachments::position(const Kinematics3& kin, int k) const {
  const Body& a = bodies_[k];
  return kin[a.at.rfe].point(a.at.s0, a.at.kappa);
}

Vec3 Attachments::force(const Model3& model, const Kinematics3& kin, double t, int k) const {
  return load(bodies_[k], kin, t).total + bodies_[k].spec.mass * model.gravity();
}

}  // namespace spatial
}  // namespace riser_sim
