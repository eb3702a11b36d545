#include "riser_sim/planar/forces/attachments.h"

namespace riser_sim {

namespace {
// ∂v/∂q' of the point (s0, κ) of b: [I, κ e, s n] (2x4), also ∂p/∂q.
Mat24 pointRows(const BodyKinematics& b, double s0, double kappa) {
  const double s = s0 + kappa * b.delta;
  Mat24 P;
  P << 1.0, 0.0, kappa * b.c, -s * b.s,  //
      0.0, 1.0, kappa * b.s, s * b.c;
  return P;
}
}  // namespace

Attachments::Attachments(const Model& model, const std::vector<AttachmentSpec>& specs, const WaterSpec& water,
                         const SeabedSpec& seabed, double gravity)
    : kinematics_(water.enabled ? water : WaterSpec(), gravity), seabed_(seabed), gravity_(gravity) {
  water_.enabled = water.enabled && gravity != 0.0;
  water_.density = water.density;
  water_.gravity = gravity;
  for (size_t k = 0; k < specs.size(); ++k) {
    Body b;
    b.spec = specs[k];
    b.at = locateAttachment(model, b.spec.arc_length, "attachments[" + std::to_string(k) + "].arc_length");
    b.radius = sphereRadius(b.spec.volume);
    has_added_mass_ = has_added_mass_ || b.spec.added_mass > 0.0;
    bodies_.push_back(b);
  }
}

Attachments::Attachments(const Attachments& other, const WaterKinematics& water)
    : bodies_(other.bodies_),
      water_(other.water_),
      kinematics_(water),
      seabed_(other.seabed_),
      has_added_mass_(other.has_added_mass_),
      gravity_(other.gravity_),
      factor_(other.factor_) {}

std::unique_ptr<ForceTerm> Attachments::scaled(double factor) const {
  auto t = std::unique_ptr<Attachments>(new Attachments(*this, kinematics_));
  t->factor_ = factor;
  return t;
}

std::unique_ptr<ForceTerm> Attachments::steadyTerm(double t, double current_factor) const {
  return std::unique_ptr<ForceTerm>(new Attachments(*this, kinematics_.steady(t, current_factor)));
}

AttachmentLoad<Vec2> Attachments::load(const Body& a, const Kinematics& kin, double t) const {
  const BodyKinematics& b = kin[a.at.rfe];
  const Vec2 p = b.point(a.at.s0, a.at.kappa), v = b.velocity(a.at.s0, a.at.kappa);
  Vec2 uw = Vec2::Zero(), aw = Vec2::Zero();
  if (water_.enabled && kinematics_.moving()) kinematics_.at(p, t, uw, aw);
  const bool contact = seabed_.enabled && a.spec.seabed_contact;
  AttachmentLoad<Vec2> L =
      attachmentLoad<Vec2>(a.spec, a.radius, water_, p.y() - kinematics_.spec().surface, Vec2::UnitY(), v, uw, aw,
                           contact ? &seabed_ : nullptr, seabed_.level - p.y(), Vec2::UnitY());
  if (factor_ != 1.0) {  // the statics' continuation (scaled())
    const double lift = (1.0 - factor_) * a.spec.mass * gravity_;
    L.total = factor_ * L.total + Vec2(0.0, lift);
    L.conservative = factor_ * L.conservative + Vec2(0.0, lift);
    L.energy = factor_ * L.energy - lift * p.y();
    L.k_up *= factor_, L.k_normal *= factor_, L.c_normal *= factor_, L.c_tangential *= factor_, L.drag *= factor_;
  }
  return L;
}

double Attachments::sweep(const Kinematics& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (const Body& a : bodies_) {
    const AttachmentLoad<Vec2> L = load(a, kin, t);
    const BodyKinematics& b = kin[a.at.rfe];
    if (Q) Q->segment<4>(4 * a.at.rfe) += pointForce(b, a.at.s0, a.at.kappa, L.total);
    pw += (L.total - L.conservative).dot(b.velocity(a.at.s0, a.at.kappa));
  }
  return pw;
}

void Attachments::addForces(const Model&, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  sweep(kin, t, &Q);
}

double Attachments::addForcesAndPower(const Model&, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  return sweep(kin, t, &Q);
}

double Attachments::power(const Model&, const TermData*, const Kinematics& kin, double t) const {
  return sweep(kin, t, nullptr);
}

double Attachments::potentialEnergy(const Model&, const TermData*, const Kinematics& kin) const {
  double e = 0.0;
  for (const Body& a : bodies_) e += load(a, kin, 0.0).energy;  // the energy does not depend on t
  return e;
}

void Attachments::addInertia(const Model&, const Kinematics& kin, double, AlignedVector<Mat4>& M, VecX& h) const {
  for (const Body& a : bodies_) {
    if (!(a.spec.added_mass > 0.0)) continue;
    const BodyKinematics& b = kin[a.at.rfe];
    const double s = a.at.s0 + a.at.kappa * b.delta;
    const Mat24 P = pointRows(b, a.at.s0, a.at.kappa);
    M[a.at.rfe].noalias() += a.spec.added_mass * P.transpose() * P;
    const Vec2 bias = (2.0 * a.at.kappa * b.delta_dot * b.phi_dot) * b.nrm() - (s * b.phi_dot * b.phi_dot) * b.e();
    h.segment<4>(4 * a.at.rfe).noalias() += a.spec.added_mass * P.transpose() * bias;
  }
}

bool Attachments::addStiffness(const Model&, const TermData*, const Kinematics& kin, double t,
                               StiffnessBlocks& S) const {
  for (const Body& a : bodies_) {
    const AttachmentLoad<Vec2> L = load(a, kin, t);
    const BodyKinematics& b = kin[a.at.rfe];
    Mat2 Kp = Mat2::Zero(), Cp = Mat2::Zero();
    Kp(1, 1) = L.k_up + L.k_normal;
    Cp(1, 1) = L.c_normal;
    Cp += L.c_tangential * Vec2(1.0, 0.0) * Vec2(1.0, 0.0).transpose();
    if (L.drag > 0.0) {
      Vec2 uw = Vec2::Zero(), aw = Vec2::Zero();
      const Vec2 p = b.point(a.at.s0, a.at.kappa);
      if (kinematics_.moving()) kinematics_.at(p, t, uw, aw);
      const Vec2 u = uw - b.velocity(a.at.s0, a.at.kappa);
      const double un = u.norm();
      if (un > 0.0) Cp += L.drag * (un * Mat2::Identity() + u * u.transpose() / un);
    }
    addPointStiffness(b, a.at.s0, a.at.kappa, L.total, Kp, Cp, S.K_diag[a.at.rfe], S.C_diag[a.at.rfe]);
  }
  return true;
}

Vec2 Attachments::position(const Kinematics& kin, int k) const {
  const Body& a = bodies_[k];
  return kin[a.at.rfe].point(a.at.s0, a.at.kappa);
}

Vec2 Attachments::force(const Model& model, const Kinematics& kin, double t, int k) const {
  return load(bodies_[k], kin, t).total + Vec2(0.0, -bodies_[k].spec.mass * model.gravity());
}

}  // namespace riser_sim
