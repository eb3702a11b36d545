// Ties model, formulation, integrator and top motion together. The state is y = [q; v; W], where
// W [J] is the work fed in by the top motion and the non-conservative terms, integrated alongside
// the motion so that energy balance E(t) - E(0) - W(t) = 0 is checkable at any step.
#pragma once
#include <cmath>
#include <memory>
#include <string>

#include "riser_sim/scene/choices.h"
#include "riser_sim/run/force_noise.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/formulation.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/planar/model.h"
#include "riser_sim/run/outputs.h"
#include "riser_sim/motion/top_motion.h"

namespace riser_sim {

// |E - E0 - W| / (m g L) above which a run warns that its step does not resolve the motion (the CLI's
// summary and the node's diagnostics): a resolved run closes its balance to round-off or ~1e-7.
constexpr double kEnergyDriftWarning = 1e-3;

struct SolverSettings {
  double dt = 1e-3;  // solver.dt [s]
  IntegratorKind integrator = IntegratorKind::kRk4;
  FormulationKind formulation = FormulationKind::kAbsolute;
  double stabilization = 50.0;         // Baumgarte frequency ω_c [rad/s] (c'' + 2ω_c c' + ω_c² c = 0)
  double max_constraint_error = 0.05;  // divergence when the joint gap exceeds this × d
  double tolerance = 1e-6;             // solver.tolerance: dopri5 error control (atol = rtol)
  // solver.jacobian_interval [s]: refresh period of the implicit schemes' dense Jacobian (the structured
  // solves relinearise every step). 0.1 s: on the absolute formulation rosenbrock2 needs a Jacobian that
  // follows the line's rotation (Table 1, n = 10, h = 0.01 s: 1 s lets the joints drift apart, 0.1 s holds
  // them to 5e-5 m; docs/integrators.md).
  double jacobian_interval = 0.1;
  // solver.jacobian: implicit schemes' linear solves. "auto": structured (O(n)) when the formulation has
  // them (independent, recursive), else dense; "structured"; "dense" (finite differences, O(p²)).
  JacobianKind jacobian = JacobianKind::kAuto;
  // solver.rho_inf: generalized_alpha's high-frequency spectral radius ρ∞ in [0, 1]. 0.5: see
  // docs/integrators.md ("generalized_alpha") for the measurements behind it.
  double rho_inf = 0.5;
  // solver.newton_tolerance: midpoint's and generalized_alpha's Newton stopping bound, relative to 1 + |z_i|,
  // in (0, 1e-3]. 1e-11: far below any step's own error (docs/integrators.md, "Newton tolerance").
  double newton_tolerance = 1e-11;
};

class Simulator : private OdeSystem {
 public:
  Simulator(std::shared_ptr<const Model> model, std::unique_ptr<TopMotion> top, const SolverSettings& settings);
  ~Simulator() override;

  // Starts from the given rfe kinematics at time t0 [s] (usually a static equilibrium).
  void setInitialState(const Kinematics& kin, double t0);
  void setTopMotion(std::unique_ptr<TopMotion> top) { top_ = std::move(top); }
  TopMotion& topMotion() { return *top_; }

  // One step of solver.dt. Returns false once the run has diverged (see divergenceReason()).
  bool step();
  // Steps until time() >= t_end - dt/2.
  bool advanceTo(double t_end);

  double time() const { return t_; }
  long steps() const { return steps_; }
  double dt() const { return settings_.dt; }
  bool diverged() const { return !reason_.empty(); }
  const std::string& divergenceReason() const { return reason_; }

  const Model& model() const { return *model_; }
  const SolverSettings& settings() const { return settings_; }
  const Formulation& formulation() const { return *formulation_; }
  // The formulation's last evaluation: of the last step's last stage, or of outputs() when called since.
  const FormulationData& formulationData() const { return *data_; }
  const VecX& state() const { return y_; }
  // Kinematics of every rfe at the current state and time.
  void kinematics(Kinematics& kin) const { formulation_->kinematics(y_, top_->at(t_), kin); }

  // Every output at the current state (one extra evaluation for the reactions).
  const LineOutputs& outputs();
  double totalEnergy();  // T + V [J]
  double initialEnergy() const { return e0_; }
  double work() const { return y_[y_.size() - 1]; }
  // (E - E0 - W) / max(|E0|, m g L): relative energy-balance error.
  double energyDrift();
  double constraintError() const;
  double maxConstraintError() const { return max_constraint_error_; }

  // Stability of explicit schemes, estimated at the initial state (setInitialState): the highest
  // natural frequency ω_max [rad/s] of the linearised line (power iteration on ∂a/∂q, so every term and
  // the stiffest element - usually the short end rfes' axial springs - count), and the largest stable
  // step of the fixed-step explicit scheme, stabilityBound / ω_max (rk4: 2√2 / ω_max), times 0.75 when
  // joints are held by Baumgarte stabilisation (absolute formulation or a pinned bottom: their constraint
  // dynamics are not in the estimate and lower the limit by up to 21 %, measured), else times 0.85 for an
  // inextensible line (tension-governed frequencies rise with the tension during the run). Implicit and
  // adaptive schemes have no such limit; stableStepEstimate() still gives rk4's for reference.
  double highestFrequency() const { return omega_max_; }
  double energyScale() const { return energy_scale_; }  // m g L [J], the floor of energyDrift()'s scale
  double stableStepEstimate() const;
  // Empty, or why solver.dt is above the explicit scheme's estimated limit, with a safe step (the node
  // refuses to start on it: such a run diverges within milliseconds).
  std::string stepAboveLimit() const;
  const Integrator& integrator() const { return *integrator_; }

  // Step-to-step noise in the top tension and the largest axial force, relative to their RMS, over the
  // run and over the last ~10 s (force_noise.h): above kForceNoiseWarning the step does not resolve the
  // forces it reports.
  const ForceNoiseMonitor& forceNoise() const { return noise_; }
  // Empty, or why forces with noise e (forceNoise().total() or .recent()) are not resolved and what
  // setting resolves them.
  std::string forceWarning(const ForceNoise& e) const;

 private:
  void rhs(double t, const VecX& y, VecX& dy) override;
  bool hasShiftedSolve() const override { return formulation_->hasShiftedSolve(); }
  void linearize(double t, const VecX& y) override { formulation_->linearize(t, y, top_->at(t), *data_); }
  void factorShifted(double c) override { formulation_->factorShifted(c, *data_); }
  void solveShifted(const VecX& b, VecX& x) override { formulation_->solveShifted(b, x, *data_); }
  double potentialEnergy(const Kinematics& kin) const;
  void checkDivergence(bool stepped);
  void sampleForces();
  double axialForce(int i, const BodyKinematics& b, const Reactions& re) const;  // [N]
  void estimateHighestFrequency();

  std::shared_ptr<const Model> model_;
  std::unique_ptr<TopMotion> top_;
  SolverSettings settings_;
  std::unique_ptr<Formulation> formulation_;
  std::unique_ptr<FormulationData> data_;  // every evaluation of this run (rhs, linearize, outputs)
  std::unique_ptr<Integrator> integrator_;
  VecX y_, dy_, probe_y_, probe_a_, probe_x_;
  double omega_max_ = 0.0;
  double damped_step_ = INFINITY;  // largest stable explicit step from the Ritz values (damping included)
  double t_ = 0.0, e0_ = 0.0, energy_scale_ = 1.0, max_constraint_error_ = 0.0;
  long steps_ = 0;
  TermDataSet term_data_;  // the terms' history in this run (seabed anchors); the model stays immutable
  std::string reason_;
  ForceNoiseMonitor noise_;
  LineOutputs out_;
  Kinematics kin_;
};

}  // namespace riser_sim
