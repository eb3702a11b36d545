#include "statics_residual.h"

#include <cmath>

#include "riser_sim/planar/chain_kinematics.h"
#include "riser_sim/planar/forces/attachments.h"
#include "riser_sim/planar/forces/buoyancy.h"
#include "riser_sim/planar/forces/morison_drag.h"
#include "riser_sim/planar/forces/seabed.h"

namespace riser_sim {
namespace statics_detail {

StaticTerms::StaticTerms(const Model& model, double t) : model_(model), t_(t) {
  for (const auto& term : model.terms()) {
    std::unique_ptr<ForceTerm> steady = term->steadyTerm(t);
    original_.push_back(steady ? steady.get() : term.get());
    if (steady) owned_.push_back(std::move(steady));
  }
  terms_ = original_;
  for (size_t k = 0; k < original_.size(); ++k)
    if (dynamic_cast<const Attachments*>(original_[k])) attachments_ = int(k);
  for (size_t k = 0; k < original_.size(); ++k)
    if (dynamic_cast<const Buoyancy*>(original_[k])) buoyancy_ = int(k);
  const WaterSpec* w = nullptr;
  for (const auto& term : model.terms())
    if (const auto* d = dynamic_cast<const MorisonDrag*>(term.get())) w = &d->water().spec();
  if (w && w->enabled) {
    has_current_ = inPlane(w->current.velocity).norm() > 0.0 || inPlane(w->current.acceleration).norm() > 0.0;
    for (const CurrentSpec::Point& p : w->current.profile) has_current_ |= p.vx != 0.0 || p.vy != 0.0;
  }
}

void StaticTerms::scaleCurrent(double factor) {
  current_factor_ = factor;
  for (size_t k = 0; k < original_.size(); ++k) {
    if (int(k) == attachments_) continue;
    std::unique_ptr<ForceTerm> scaled = model_.terms()[k]->steadyTerm(t_, factor);
    if (!scaled) continue;
    if (factor == 1.0) {
      terms_[k] = original_[k];
      continue;
    }
    owned_.push_back(std::move(scaled));
    terms_[k] = owned_.back().get();
  }
  composeAttachments();
}

void StaticTerms::scaleAttachments(double factor) {
  attachments_factor_ = factor;
  composeAttachments();
}

// The attachments in the current x current_factor_, their loads x attachments_factor_ (the two continuations
// compose: a still-water start ramps the attachments with the current off).
void StaticTerms::composeAttachments() {
  if (attachments_ < 0) return;
  const ForceTerm* in_current = original_[attachments_];
  if (current_factor_ != 1.0) {
    owned_.push_back(model_.terms()[attachments_]->steadyTerm(t_, current_factor_));
    in_current = owned_.back().get();
  }
  if (attachments_factor_ != 1.0) {
    owned_.push_back(static_cast<const Attachments*>(in_current)->scaled(attachments_factor_));
    in_current = owned_.back().get();
  }
  terms_[attachments_] = in_current;
}

void StaticTerms::scaleBuoyancy(double factor) {
  if (buoyancy_ < 0) return;
  if (factor == 1.0) {
    terms_[buoyancy_] = original_[buoyancy_];
    return;
  }
  WaterSpec w = static_cast<const Buoyancy*>(original_[buoyancy_])->water();
  w.density *= factor;
  owned_.push_back(std::make_unique<Buoyancy>(w));
  terms_[buoyancy_] = owned_.back().get();
}

bool StaticTerms::hasBuoyantSection() const {
  if (buoyancy_ < 0) return false;
  const double rho = static_cast<const Buoyancy*>(original_[buoyancy_])->water().density;
  for (int k = 0; k < model_.sectionCount(); ++k) {
    const LineProperties& p = model_.section(k).props;
    if (rho * p.externalArea() > p.mass_per_length + p.content_mass_per_length) return true;
  }
  return false;
}

double StaticTerms::seabedLevel() const {
  double level = -INFINITY;
  for (const ForceTerm* term : original_) level = std::max(level, term->seabedLevel());
  return level;
}

double StaticTerms::seabedStiffness() const {
  double k = 0.0;
  for (const ForceTerm* term : original_)
    if (const auto* s = dynamic_cast<const Seabed*>(term)) k = std::max(k, s->spec().stiffness_normal);
  return k;
}

void StaticTerms::softenSeabed(double base) {
  seabed_base_ = base;
  scaleSeabed(1.0);
}

void StaticTerms::scaleSeabed(double factor) {
  factor *= seabed_base_;
  for (size_t k = 0; k < original_.size(); ++k) {
    const auto* s = dynamic_cast<const Seabed*>(original_[k]);
    if (!s) continue;
    if (factor == 1.0) {
      terms_[k] = original_[k];
      continue;
    }
    SeabedSpec spec = s->spec();
    spec.stiffness_normal *= factor;
    owned_.push_back(std::make_unique<Seabed>(spec));
    terms_[k] = owned_.back().get();
  }
}

StaticResidual::StaticResidual(const Model& m, const StaticsProblem& p, const StaticTerms& terms, double t)
    : model_(m), prob_(p), terms_(terms), t_(t) {
  axial_ = m.options().axial_flexibility;
  per_ = axial_ ? 2 : 1;
  extra_ = p.kind == StaticsProblem::Kind::kHanging ? 0 : (p.kind == StaticsProblem::Kind::kEndDisplaced ? 1 : 2);
  kin_.resize(m.bodies());
  joint_.resize(m.bodies());
  Q_.setZero(m.dofs());
  weight_ = std::max(m.totalMass() * std::abs(m.gravity()), 1e-9);
}

void StaticResidual::toKinematics(const VecX& x, Kinematics& kin) const {
  chainKinematics(model_, prob_.top, Vec2::Zero(), x.data(), nullptr, kin);  // the first per_ (n+1) entries
}

void StaticResidual::fromKinematics(const Kinematics& kin, VecX& x) const {
  for (int i = 0; i < model_.bodies(); ++i) {
    if (axial_) x[per_ * i] = kin[i].delta;
    x[per_ * i + per_ - 1] = kin[i].phi;
  }
}

Vec2 StaticResidual::endForce(const VecX& x) const {
  const int o = coordinates();
  if (extra_ == 1) return Vec2(x[o], 0.0);
  if (extra_ == 2) return Vec2(x[o], x[o + 1]);
  return Vec2::Zero();
}

void StaticResidual::setEndForce(const Vec2& f, VecX& x) const {
  const int o = coordinates();
  if (extra_ >= 1) x[o] = f.x();
  if (extra_ == 2) x[o + 1] = f.y();
}

void StaticResidual::operator()(const VecX& x, VecX& r) {
  toKinematics(x, kin_);
  Q_.setZero();
  for (const ForceTerm* term : terms_.terms())  // no history: the seabed's tangential springs are free
    term->addForces(model_, nullptr, kin_, t_, Q_);
  const int nb = model_.bodies();
  Q_.segment<4>(4 * (nb - 1)) += pointForce(kin_[nb - 1], model_.rfe(nb - 1).length, 1.0, endForce(x));
  Vec2 below = Vec2::Zero();  // net force on the rfes beyond rfe i
  const double L = model_.length();
  for (int i = nb - 1; i >= 0; --i) {
    const BodyKinematics& b = kin_[i];
    const Vec4 q = Q_.segment<4>(4 * i);
    if (axial_) r[per_ * i] = (q[kDelta] + b.e().dot(below)) / weight_;
    r[per_ * i + per_ - 1] = (q[kPhi] + b.len * b.nrm().dot(below)) / (weight_ * L);
    below += q.head<2>();
    joint_[i] = below;
  }
  const int o = coordinates();
  const Vec2 end = kin_[nb - 1].end();
  if (extra_ == 1) r[o] = (end.x() - prob_.top.x() - prob_.end_dx) / L;
  if (extra_ == 2) r.segment<2>(o) = (end - prob_.end_point) / L;
}

void StaticResidual::jacobian(const VecX& x, const VecX& r, MatX& J) {
  const int n = size();
  J.resize(n, n);
  VecX x1 = x, r1(n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-7 * std::max(std::abs(x[j]), typical(j));
    x1[j] = x[j] + h;
    (*this)(x1, r1);
    J.col(j) = (r1 - r) / h;
    x1[j] = x[j];
  }
}

void StaticResidual::centralJacobian(const VecX& x, MatX& J) {
  const int n = size(), nt = coordinates();
  J.resize(n, n);
  VecX x1 = x, rp(n), rm(n);
  for (int j = 0; j < n; ++j) {
    double h = 1e-6 * std::max(std::abs(x[j]), weight_);  // end force
    if (j < nt) h = axial_ && j % 2 == 0 ? 1e-8 * model_.rfe(j / per_).length : 1e-6;
    x1[j] = x[j] + h;
    (*this)(x1, rp);
    x1[j] = x[j] - h;
    (*this)(x1, rm);
    J.col(j) = (rp - rm) / (2.0 * h);
    x1[j] = x[j];
  }
}

}  // namespace statics_detail
}  // namespace riser_sim
