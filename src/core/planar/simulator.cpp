#include "riser_sim/planar/simulator.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "riser_sim/planar/absolute_formulation.h"
#include "riser_sim/planar/independent_formulation.h"
#include "riser_sim/planar/recursive_formulation.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/scene/solver_setup.h"
#include "riser_sim/run/stability_estimate.h"

namespace riser_sim {

namespace {
// Divergence by unresolved motion (checkDivergence): an rfe turning by more than 0.5 rad (29 deg) or
// stretching by more than 10 % in one step: far beyond anything a resolved run does (every sound case of
// test_extremes, the snap load included, stays below).
constexpr double kMaxTurnPerStep = 0.5;
constexpr double kMaxStretchPerStep = 0.1;
// Shares of the explicit stability estimate kept when joints are held by Baumgarte and when the line is
// inextensible (see stableStepEstimate).
constexpr double kBaumgarteStabilityFactor = 0.75;
constexpr double kTensionStabilityFactor = 0.85;

std::unique_ptr<Formulation> makeFormulation(const Model& model, const SolverSettings& s) {
  switch (s.formulation) {
    case FormulationKind::kAbsolute: return std::make_unique<AbsoluteFormulation>(model, s.stabilization);
    case FormulationKind::kIndependent: return std::make_unique<IndependentFormulation>(model, s.stabilization);
    case FormulationKind::kRecursive: return std::make_unique<RecursiveFormulation>(model, s.stabilization);
  }
  throw std::invalid_argument("solver.formulation: unknown formulation (accepted: " + choiceNames<FormulationKind>() +
                              ")");
}
}  // namespace

Simulator::Simulator(std::shared_ptr<const Model> model, std::unique_ptr<TopMotion> top, const SolverSettings& settings)
    : model_(std::move(model)), top_(std::move(top)), settings_(settings) {
  if (const auto error = checkSolverSetup(settings_, model_->segments(), model_->options().axial_flexibility))
    throw std::invalid_argument(error->what());
  formulation_ = makeFormulation(*model_, settings_);
  term_data_ = TermDataSet(*model_);
  data_ = formulation_->makeData();
  data_->term_data = &term_data_;
  IntegratorOptions io;
  io.tolerance = settings_.tolerance;
  io.jacobian_interval = settings_.jacobian_interval;
  io.jacobian = resolvedJacobian(settings_);
  io.rho_inf = settings_.rho_inf;
  io.newton_tolerance = settings_.newton_tolerance;
  integrator_ = makeIntegrator(settings_.integrator, io);
  const int n = 2 * formulation_->positionSize() + 1;
  y_.setZero(n);
  dy_.setZero(n);
  probe_y_.setZero(n);
  probe_a_.setZero(n);
  probe_x_.setZero(formulation_->positionSize());
  integrator_->reset(StateLayout{n, formulation_->positionSize()});
  kin_.resize(model_->bodies());
  const int nb = model_->bodies();
  out_.points.resize(nb + 1);
  out_.angles.resize(nb);
  out_.elongations.resize(nb);
  out_.axial_force.resize(nb);
  out_.arc_length.resize(nb);
  out_.bending_moment.resize(nb - 1);
  energy_scale_ = std::max(model_->totalMass() * model_->gravity() * model_->length(), 1e-12);
}

Simulator::~Simulator() = default;

void Simulator::setInitialState(const Kinematics& kin, double t0) {
  t_ = t0;
  steps_ = 0;
  reason_.clear();
  y_.setZero();
  formulation_->packState(kin, y_);
  formulation_->kinematics(y_, PointMotion{kin[0].A, kin[0].A_dot, Vec2::Zero()}, kin_);
  term_data_.startRun(*model_, kin_);
  integrator_->restart();
  noise_.reset();
  estimateHighestFrequency();
  e0_ = totalEnergy();
  max_constraint_error_ = constraintError();
}

// Power iteration on A = ∂a/∂q (accelerations per position change, v held), by forward differences:
// |λ_max(A)| = ω_max² for the undamped linearised line. The start vector alternates in sign along the
// line (the shape of a chain's highest mode) with a deterministic spread so that no mode is missed.
void Simulator::estimateHighestFrequency() {
  const int p = formulation_->positionSize();
  for (int i = 0; i < p; ++i) probe_x_[i] = ((i / 2) % 2 ? -1.0 : 1.0) * (1.0 + 0.37 * std::sin(1.7 * i));
  rhs(t_, y_, dy_);
  const double qscale = 1.0 + y_.head(p).cwiseAbs().maxCoeff();
  double lambda = 0.0;
  constexpr int kIterations = 80;  // Rayleigh-type ratio settles to < 1 % (checked against the calibration)
  for (int k = 0; k < kIterations; ++k) {
    probe_x_ /= probe_x_.norm();
    const double eps = 1e-7 * qscale;
    probe_y_ = y_;
    probe_y_.head(p) += eps * probe_x_;
    rhs(t_, probe_y_, probe_a_);
    probe_x_ = (probe_a_.segment(p, p) - dy_.segment(p, p)) / eps;
    const double norm = probe_x_.norm();
    if (!std::isfinite(norm) || norm == 0.0) break;
    lambda = norm;
  }
  omega_max_ = std::sqrt(lambda);
  // Damping: the Ritz values of the whole first-order Jacobian (real negative ones for damped modes),
  // each against the explicit scheme's stability region in its direction.
  rhs(t_, y_, dy_);
  const int m = 2 * p;
  const double vscale = 1.0 + y_.segment(p, p).cwiseAbs().maxCoeff();
  const auto jv = [&](const VecX& x, VecX& out) {
    const double eps = 1e-7 * std::max(qscale, vscale);
    probe_y_ = y_;
    probe_y_.head(m) += eps * x;
    rhs(t_, probe_y_, probe_a_);
    out = (probe_a_.head(m) - dy_.head(m)) / eps;
  };
  constexpr int kKrylov = 60;  // the outermost Ritz values settle well before (test_extremes, damping x n)
  const std::vector<Complex> ritz = ritzValues(m, kKrylov, jv);
  const Rk4 rk4;  // the reference scheme for implicit ones (stableStepEstimate)
  const Integrator& scheme = integrator_->explicitFixedStep() ? *integrator_ : static_cast<const Integrator&>(rk4);
  damped_step_ = largestStableStep(ritz, [&](Complex z) { return scheme.stabilityFunction(z); });
  rhs(t_, y_, dy_);  // leave data_'s evaluation at the state
}

double Simulator::stableStepEstimate() const {
  const double bound = integrator_->explicitFixedStep() ? integrator_->stabilityBound() : Rk4().stabilityBound();
  // Joints held by Baumgarte (absolute formulation, pinned bottom): the constraint dynamics c'' + 2ω_c c'
  // + ω_c² c, a critically damped real pair, couple with the line's modes and are not seen by the power
  // iteration on ∂a/∂q. Measured on the inextensible Table 1 line (absolute, rk4, 60 s): the largest
  // stable h is 0.83, 0.79, 0.86, 0.85x the raw estimate at n = 10, 20, 40, 100 (docs/integrators.md).
  const bool baumgarte =
      settings_.formulation == FormulationKind::kAbsolute || model_->bottom() == BottomBoundary::kPinned;
  // An inextensible line's highest frequencies are set by its tension, which the motion changes (the
  // swing of Table 1 raises it): measured (recursive, 20 s) 0.8x the raw estimate stable, 0.9x diverging
  // at n = 20, 40, 100.
  const bool tension_governed = !model_->options().axial_flexibility;
  // (The Baumgarte measurements were on the inextensible line over 60 s: they include the swing.)
  const double factor = baumgarte ? kBaumgarteStabilityFactor : tension_governed ? kTensionStabilityFactor : 1.0;
  const double undamped = omega_max_ > 0.0 ? bound / omega_max_ : std::numeric_limits<double>::infinity();
  return factor * std::min(undamped, damped_step_);
}

void Simulator::rhs(double t, const VecX& y, VecX& dy) {
  const PointMotion top = top_->at(t);
  formulation_->derivative(t, y, top, dy, *data_);
  // dW/dt: power of the top motion (force on rfe 0 at A_0 is -λ_0) and of the non-conservative terms
  // (summed by the formulation with the forces, at the same state).
  dy[dy.size() - 1] = -data_->reactions.top.dot(top.v) + data_->term_power;
}

bool Simulator::step() {
  if (diverged()) return false;
  const bool stepped = integrator_->step(*this, t_, y_, settings_.dt);
  ++steps_;
  t_ += settings_.dt;
  if (term_data_.any()) {
    kinematics(kin_);
    if (term_data_.endStep(*model_, kin_)) integrator_->forcesChanged();
  }
  checkDivergence(stepped);
  if (!diverged()) sampleForces();
  return !diverged();
}

double Simulator::axialForce(int i, const BodyKinematics& b, const Reactions& re) const {
  const Rfe& r = model_->rfe(i);
  return model_->options().axial_flexibility ? r.axial_stiffness * b.delta + r.axial_damping * b.delta_dot
                                             : re.joint[i].dot(b.e());  // tension at A_i from the joint reaction
}

// The forces of the step's last evaluation when it was made at the step's end time (every scheme's
// last stage is: rk4's k4, the implicit schemes' end evaluation, dopri5's FSAL stage), O(n), no extra
// evaluation.
void Simulator::sampleForces() {
  if (data_->t != t_) return;
  const Kinematics& kin = data_->kin;
  double tmax = 0.0;
  for (int i = 0; i < model_->bodies(); ++i) tmax = std::max(tmax, axialForce(i, kin[i], data_->reactions));
  noise_.add(data_->reactions.top.norm(), tmax, settings_.dt);
}

bool Simulator::advanceTo(double t_end) {
  while (t_ < t_end - 0.5 * settings_.dt)
    if (!step()) return false;
  return true;
}

void Simulator::checkDivergence(bool stepped) {
  // Nothing is built unless something is wrong: the healthy path allocates nothing.
  const bool finite = y_.allFinite();
  double err = 0.0;
  if (finite) {
    err = data_->constraint_error;  // monitored at the last stage, free
    max_constraint_error_ = std::max(max_constraint_error_, err);
  }
  const double limit = settings_.max_constraint_error * model_->segmentLength();
  // Unresolved motion: the chain formulations have no joint gap to watch, so an unstable run would
  // otherwise grow for many steps until it overflows. An rfe that turns by more than kMaxTurnPerStep or
  // stretches by more than kMaxStretchPerStep of its length in one step (rates of the last evaluation,
  // O(n) comparisons) is not being integrated any more.
  int fast = -1;
  double turn = 0.0, stretch = 0.0;
  if (finite) {
    const Kinematics& kin = data_->kin;
    for (int i = 0; i < model_->bodies() && fast < 0; ++i) {
      turn = std::abs(kin[i].phi_dot) * settings_.dt;
      stretch = std::abs(kin[i].delta_dot) * settings_.dt / model_->rfe(i).length;
      if (!(turn <= kMaxTurnPerStep && stretch <= kMaxStretchPerStep)) fast = i;
    }
  }
  if (stepped && finite && err <= limit && fast < 0) return;
  std::ostringstream why;
  if (!stepped)
    why << integrator_->failure();
  else if (finite && fast >= 0)
    why << "rfe " << fast << " turns by " << turn << " rad and stretches by " << stretch
        << " of its length in one step at t = " << t_ << " s (limits " << kMaxTurnPerStep << " rad, "
        << kMaxStretchPerStep << "): the motion is not resolved (unstable)";
  else if (!finite)
    why << "state is not finite (NaN/Inf) at t = " << t_ << " s";
  else
    why << "joint constraint error " << err << " m exceeds " << limit << " m (" << settings_.max_constraint_error
        << " d) at t = " << t_ << " s";
  // dopri5's step size underflow is a tolerance problem: its own advice, no smaller output step.
  if (integrator_->failure().find("loosen solver.tolerance") == std::string::npos)
    why << "; reduce solver.dt (now " << settings_.dt << " s)";
  if (integrator_->explicitFixedStep() && omega_max_ > 0.0)
    why << divergenceStabilityNote(integrator_->name(), settings_.dt, stableStepEstimate(), omega_max_);
  reason_ = why.str();
}

std::string Simulator::stepAboveLimit() const {
  if (!integrator_->explicitFixedStep()) return "";
  return stepAboveLimitMessage(integrator_->name(), settings_.dt, stableStepEstimate(), omega_max_);
}

std::string Simulator::forceWarning(const ForceNoise& e) const {
  return forceNoiseWarning(e, settings_.dt, settings_.integrator, settings_.rho_inf);
}

double Simulator::constraintError() const { return formulation_->constraintError(y_, top_->at(t_)); }

double Simulator::potentialEnergy(const Kinematics& kin) const {
  return termPotentialEnergy(*model_, &term_data_, kin, t_);
}

double Simulator::totalEnergy() {
  const PointMotion top = top_->at(t_);
  formulation_->kinematics(y_, top, kin_);
  return formulation_->kineticEnergy(t_, y_, top, *data_) + potentialEnergy(kin_);
}

double Simulator::energyDrift() { return (totalEnergy() - e0_ - work()) / std::max(std::abs(e0_), energy_scale_); }

const LineOutputs& Simulator::outputs() {
  const int nb = model_->bodies();
  const PointMotion top = top_->at(t_);
  formulation_->derivative(t_, y_, top, dy_, *data_);
  const Kinematics& kin = data_->kin;
  const Reactions& re = data_->reactions;
  out_.t = t_;
  double tmax = 0.0;
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics& b = kin[i];
    const Rfe& r = model_->rfe(i);
    out_.points[i] = b.A;
    out_.angles[i] = b.phi;
    out_.elongations[i] = b.delta;
    out_.arc_length[i] = r.s_begin + 0.5 * r.length;
    out_.axial_force[i] = axialForce(i, b, re);
    tmax = std::max(tmax, out_.axial_force[i]);
  }
  out_.points[nb] = kin[nb - 1].end();
  for (int i = 1; i < nb; ++i)
    out_.bending_moment[i - 1] = model_->bendingStiffness(i) * (kin[i].phi - kin[i - 1].phi) +
                                 model_->bendingDamping(i) * (kin[i].phi_dot - kin[i - 1].phi_dot);
  out_.top_force = re.top;
  out_.bottom_force = re.bottom;
  out_.top_tension = re.top.norm();
  out_.bottom_tension = out_.axial_force[nb - 1];
  out_.max_tension = tmax;
  out_.kinetic_energy = formulation_->kineticEnergy(t_, y_, top, *data_);
  out_.potential_energy = potentialEnergy(kin);
  out_.work_in = work();
  out_.constraint_error = constraintError();
  return out_;
}

}  // namespace riser_sim
