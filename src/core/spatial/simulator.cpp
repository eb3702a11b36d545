#include "riser_sim/spatial/simulator.h"

#include "riser_sim/spatial/force_term.h"

#include <stdexcept>

namespace riser_sim {
namespace spatial {

SpatialSimulator::SpatialSimulator(std::shared_ptr<const SpatialModel> model, std::unique_ptr<TopMotion3> top,
                                   IntegratorKind kind, const IntegratorOptions& options, double stabilization)
    : model_(std::move(model)), top_(std::move(top)), formulation_(*model_, stabilization),
      data_(formulation_.makeData()), shifted_(formulation_.makeShifted()), integrator_(makeIntegrator(kind, options)),
      kin_(model_->bodies()) {
  const int n = 2 * formulation_.positionSize() + 1;  // [q; v; W]
  y_.setZero(n);
  dy_.setZero(n);
  integrator_->reset(StateLayout{n, formulation_.positionSize()});
}

void SpatialSimulator::reset(const Kinematics3& kin, double t0) {
  t_ = t0;
  y_.setZero();
  formulation_.packState(kin, y_);
  formulation_.project(y_);
  formulation_.initTwist(y_, *data_);
  integrator_->restart();
}

void SpatialSimulator::setTwist(const VecX& theta, const VecX& omega) {
  const int nt = formulation_.twistDofs(), nq = model_->dofs(), p = formulation_.positionSize();
  if (nt == 0 || theta.size() != nt || omega.size() != nt)
    throw std::invalid_argument("SpatialSimulator::setTwist: torsion off, or not one angle and rate per rfe");
  y_.segment(nq, nt) = theta;
  y_.segment(p + nq, nt) = omega;
  y_[nq] = y_[p + nq] = 0.0;  // rfe 0 is held by the hang-off
  integrator_->restart();
}

void SpatialSimulator::rhs(double t, const VecX& y, VecX& dy) {
  const PointMotion3 top = top_->at(t);
  formulation_.derivative(t, y, top, dy, *data_);
  // dW/dt: power of the top motion (force on rfe 0 at A_0 is -λ_0), of a moving bottom (force on rfe n at
  // E_n is λ_{n+1} = -reactions.bottom; 0 when fixed or free) and of the non-conservative terms.
  double p_bottom = 0.0;
  if (model_->bottomMoves()) p_bottom = -data_->reactions.bottom.dot(data_->bottom.v);
  dy[dy.size() - 1] = -data_->reactions.top.dot(top.v) + p_bottom + data_->term_power;
}

void SpatialSimulator::linearize(double t, const VecX& y) {
  formulation_.linearize(t, y, top_->at(t), *data_, *shifted_);
}

bool SpatialSimulator::step(double h) {
  const bool ok = integrator_->step(*this, t_, y_, h);
  t_ += h;
  // Back onto |e| = 1, e·e' = 0 (the Baumgarte terms hold the drift within the step).
  if (projection_tol_ <= 0.0 || formulation_.manifoldError(y_, h) > projection_tol_) {
    formulation_.project(y_);
    formulation_.rechartTwist(y_, *data_);
    integrator_->stateProjected(y_);
  } else if (model_->hasTorsion()) {  // the twist charts move every step (the state does not)
    formulation_.rechartTwist(y_, *data_);
    integrator_->stateProjected(y_);
  }
  return ok && y_.allFinite();
}

void SpatialSimulator::positions(AlignedVector<Vec3>& p) const {
  const int nb = model_->bodies();
  for (int i = 0; i < nb; ++i) p[i] = formulation_.body(y_, i).A;
  p[nb] = formulation_.body(y_, nb - 1).end();
}

double SpatialSimulator::potentialEnergy() {
  formulation_.kinematics(y_, kin_);
  double v = 0.0;
  for (const auto& term : model_->terms()) v += term->potentialEnergy(*model_, kin_);
  return v + formulation_.twistEnergy(y_, *data_);
}

const NaturalData& SpatialSimulator::evaluate() {
  rhs(t_, y_, dy_);
  return *data_;
}

}  // namespace spatial
}  // namespace riser_sim
