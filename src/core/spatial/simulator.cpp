#include "riser_sim/spatial/simulator.h"

#include "riser_sim/integrators/implicit_integrators.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/run/stability_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace riser_sim {
namespace spatial {

namespace {
// Share of the raw explicit limit kept (stableStepEstimate). rk4's largest stable step measured by
// bisection (to 0.4 %) against the raw estimate: 0.99x on spatial_swing (20 s, inextensible, the swing
// raises the tension), 1.07x on spatial_tether (20 s, pinned, flex joints), 0.99x on a 10-rfe extensible
// steel line and on a torsion line with a flex joint (3 s each) (docs/spatial.md, "Stability"). 0.9 leaves
// 10 % for tensions that grow beyond those runs' (the planar inextensible line needed 15 %).
constexpr double kStabilityFactor3 = 0.9;
}  // namespace

Simulator3::Simulator3(std::shared_ptr<const Model3> model, std::shared_ptr<const TopMotion3> top, IntegratorKind kind,
                       const IntegratorOptions& options, double stabilization)
    : model_(std::move(model)),
      top_(std::move(top)),
      formulation_(*model_, stabilization),
      data_(formulation_.makeData()),
      shifted_(formulation_.makeShifted()),
      integrator_(makeIntegrator(kind, options)),
      kin_(model_->bodies()) {
  const int n = 2 * formulation_.positionSize() + 1;  // [q; v; W]
  y_.setZero(n);
  dy_.setZero(n);
  y_lin_.setZero(n);
  newton_ = dynamic_cast<const OneStageImplicit*>(integrator_.get());  // midpoint, generalized_alpha
  integrator_->reset(StateLayout{n, formulation_.positionSize()});
}

void Simulator3::reset(const Kinematics3& kin, double t0, const HangOff& hang_off) {
  t_ = t0;
  y_.setZero();
  formulation_.packState(kin, y_);
  formulation_.project(y_);
  formulation_.initTwist(y_, *data_, top_->at(t0).R, hang_off);
  integrator_->restart();
  force_lin_ = true;
}

void Simulator3::setTwist(const VecX& theta, const VecX& omega) {
  const int nt = formulation_.twistDofs(), nq = model_->dofs(), p = formulation_.positionSize();
  if (nt == 0 || theta.size() != nt || omega.size() != nt)
    throw std::invalid_argument("Simulator3::setTwist: torsion off, or not one angle and rate per rfe");
  y_.segment(nq, nt) = theta;
  y_.segment(p + nq, nt) = omega;
  if (firstSpin(*model_) > 0) y_[nq] = y_[p + nq] = 0.0;  // rfe 0 is held by the hang-off
  integrator_->restart();
  force_lin_ = true;
}

void Simulator3::setMaterialAxes(const AlignedVector<Vec3>& m1) {
  const int nb = model_->bodies();
  Kinematics3 kin(nb);
  kinematics(kin);
  VecX theta(nb);
  spinsFromAxes(kin, data_->twist.frames, m1, theta.data());
  setTwist(theta, VecX::Zero(nb));
}

void Simulator3::rhs(double t, const VecX& y, VecX& dy) {
  const PointMotion3 top = top_->at(t);
  formulation_.derivative(t, y, top, dy, *data_);
  ++evaluations_;
  // dW/dt: power of the top motion (force on rfe 0 at A_0 is -λ_0), of a moving bottom (force on rfe n at
  // E_n is λ_{n+1} = -reactions.bottom; 0 when fixed or free) and of the non-conservative terms.
  double p_bottom = 0.0;
  if (model_->bottomMoves()) p_bottom = -data_->reactions.bottom.dot(data_->bottom.v);
  dy[dy.size() - 1] = -data_->reactions.top.dot(top.v) + p_bottom + data_->term_power;
}

// Deferred to the first solve: linearised there at the last evaluation when one was made since (the
// implicit schemes' Newton predictor z0, where the stage is solved: fewer iterations than at (t, y)),
// else at (t, y) (Rosenbrock2: its step's first solve follows the linearisation directly).
// Newton schemes keep the last factor instead while the steps converge in kReuseSolves (3) solves, for at most
// kReuseSteps steps (simplified Newton across steps: the same solution to Newton's tolerance); a step
// that needs more is relinearised at its current iterate, and reuse waits 1, 3, 7, ... 63 steps after it.
void Simulator3::linearize(double t, const VecX& y) {
  if (reused_) backoff_ = 0;  // the last step converged on the kept factor
  if (wait_ > 0) --wait_;
  bool reuse =
      newton_ && !force_lin_ && shifted_->factored() && solves_ <= kReuseSolves && age_ < kReuseSteps && wait_ == 0;
  if (reuse && reused_ && age_ > 0 && solves_ == kReuseSolves && staleNext()) reuse = false;
  solves_ = 0;
  reused_ = reuse;
  force_lin_ = false;
  if (reuse) {
    ++age_;
    return;
  }
  age_ = 0;
  t_lin_ = t;
  y_lin_ = y;
  evaluations_at_lin_ = evaluations_;
  lin_pending_ = true;
}

// Whether the next step on the kept factor is predicted to need more than kReuseSolves solves (it would be
// relinearised in the middle of its Newton iteration, after solves that the old factor wasted). The last
// step, age_ steps after its linearisation, converged in kReuseSolves solves with its stopping test at
// `margin` of its bound. The factor's error, and with it Newton's contraction rate, grows about in
// proportion to the steps since the linearisation, so the next step's error after as many solves is
// about margin ((age_ + 1) / age_)^solves (measured on the step-cost bench line: the rate after the
// second solve 6e-5, 1.3e-4, 2e-4, 3e-4, 4e-4 one to five steps after it at n = 1000).
bool Simulator3::staleNext() const {
  if (!newton_ || newton_->lastNewton().solves != solves_) return false;  // a retry in substeps: no estimate
  const double growth = double(age_ + 1) / double(age_);
  return newton_->lastNewton().margin * std::pow(growth, solves_) > 1.0;
}

void Simulator3::factorShifted(double c) {
  c_pending_ = c;
  if (!lin_pending_ && !(shifted_->factored() && shifted_->c() == c)) formulation_.factorShifted(c, *shifted_);
}

void Simulator3::solveShifted(const VecX& b, VecX& x) {
  if (reused_ && ++solves_ > kReuseSolves && evaluations_ != evaluations_at_solve_) {  // converging slowly
    shifted_->setLinearization(*data_, data_->acc);
    formulation_.factorShifted(c_pending_, *shifted_);
    reused_ = false;
    age_ = 0;
    backoff_ = std::min(2 * backoff_ + 1, 63);
    wait_ = backoff_;
  } else if (!reused_) {
    ++solves_;
  }
  evaluations_at_solve_ = evaluations_;
  if (lin_pending_) {
    if (evaluations_ != evaluations_at_lin_)
      shifted_->setLinearization(*data_, data_->acc);
    else
      formulation_.linearize(t_lin_, y_lin_, top_->at(t_lin_), *data_, *shifted_);
    formulation_.factorShifted(c_pending_, *shifted_);
    lin_pending_ = false;
  }
  if (reused_ && solves_ == 1) shifted_->followDirectors(*data_);  // at the step's predictor (its last evaluation)
  formulation_.solveShifted(b, x, *shifted_);
}

bool Simulator3::step(double h) {
  const bool ok = integrator_->step(*this, t_, y_, h);
  t_ += h;
  end_evaluated_ = data_->t == t_;  // before the charts move (rechartTwist marks the evaluation stale)
  // Back onto |e| = 1, e·e' = 0 (the Baumgarte terms hold the drift within the step).
  if (projection_tol_ <= 0.0 || formulation_.manifoldError(y_, h) > projection_tol_) {
    formulation_.project(y_);
    if (model_->hasTorsion()) formulation_.rechartTwist(y_, top_->at(t_), *data_);
    integrator_->stateProjected(y_);
  } else if (model_->hasTorsion()) {  // the twist charts move every step (the state does not)
    formulation_.rechartTwist(y_, top_->at(t_), *data_);
    integrator_->stateProjected(y_);
  }
  return ok && y_.allFinite();
}

void Simulator3::positions(AlignedVector<Vec3>& p) const {
  const int nb = model_->bodies();
  for (int i = 0; i < nb; ++i) p[i] = formulation_.body(y_, i).A;
  p[nb] = formulation_.body(y_, nb - 1).end();
}

double Simulator3::kineticEnergy() {
  double T = formulation_.kineticEnergy(y_);
  if (data_->added.empty()) return T;
  formulation_.kinematics(y_, kin_);
  for (const auto& term : model_->terms()) T += term->kineticEnergy(*model_, kin_);
  return T;
}

double Simulator3::potentialEnergy() {
  formulation_.kinematics(y_, kin_);
  double v = 0.0;
  for (const auto& term : model_->terms()) v += term->potentialEnergy(*model_, kin_, t_);
  return v + formulation_.twistEnergy(y_, top_->at(t_), *data_);
}

const NaturalData& Simulator3::evaluate() {
  rhs(t_, y_, dy_);
  return *data_;
}

void Simulator3::estimateStability() {
  const Rk4 rk4;  // the reference scheme for the implicit and adaptive ones
  const Integrator& scheme = integrator_->explicitFixedStep() ? *integrator_ : static_cast<const Integrator&>(rk4);
  const LinearisedSpectrum s = linearisedSpectrum(
      formulation_.positionSize(), y_, [&](const VecX& y, VecX& dy) { rhs(t_, y, dy); },
      [&](Complex z) { return scheme.stabilityFunction(z); });
  omega_max_ = s.omega_max;
  const double undamped =
      omega_max_ > 0.0 ? scheme.stabilityBound() / omega_max_ : std::numeric_limits<double>::infinity();
  stable_step_ = std::min(undamped, s.damped_step);
  rhs(t_, y_, dy_);  // leave data_'s evaluation at the state
}

double Simulator3::stableStepEstimate() const { return kStabilityFactor3 * stable_step_; }

}  // namespace spatial
}  // namespace riser_sim
