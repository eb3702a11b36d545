// Runs the spatial line with the existing integrators (integrator.h's OdeSystem, state y = [q; v; W],
// W [J] the work of the top motion, of a moving bottom and of the non-conservative terms integrated alongside). After
// every integrator step the state is projected back onto |e_i| = 1, e_i·e'_i = 0 (NaturalFormulation:: project); within
// a step the Baumgarte terms hold the drift. The joint gaps are not projected (the planar absolute formulation does not
// either). The implicit schemes (rosenbrock2, midpoint, generalized_alpha) use options.jacobian: "structured" (the
// default) solves with the formulation's O(n) block-tridiagonal KKT factorisation (shifted_solver.h),
// relinearised every step (at its first solve: the Newton predictor, simulator.cpp); "dense" uses their
// finite-difference Jacobian (O(p²) per solve, O(p³) per refresh).
#pragma once
#include <cmath>
#include <memory>

#include "riser_sim/scene/choices.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/shifted_solver.h"

namespace riser_sim {
class OneStageImplicit;  // implicit_integrators.h
namespace spatial {

class Simulator3 : private OdeSystem {
 public:
  Simulator3(std::shared_ptr<const Model3> model, std::shared_ptr<const TopMotion3> top, IntegratorKind kind,
             const IntegratorOptions& options = {}, double stabilization = 50.0);
  // Starts from the given rfe kinematics at time t0 [s] (projected; W = 0). Torsion on: hang_off_ref is the
  // hang-off's reference at kin's top rfe (zero: made from the model's bending axis, else any).
  void reset(const Kinematics3& kin, double t0, const HangOff& hang_off = HangOff());
  // Torsion on: spin angles θ and rates ω [rad, rad/s] per rfe (torsion.h; entry 0 is held at 0). After
  // reset(), which starts them at 0.
  void setTwist(const VecX& theta, const VecX& omega);
  // The same from each rfe's material axis 1 (torsion.h, frame-free; e.g. InitialState3::material_axes), at rest.
  void setMaterialAxes(const AlignedVector<Vec3>& m1);
  // One integrator step of h [s], then the projection (and, torsion on, the twist charts moved). False when the
  // integrator failed or the state is not finite.
  bool step(double h);
  // Project only when max_i max(| |e_i| - 1 |, |e_i·e'_i| h) exceeds tol (default 0: after every step).
  // The integrator is told (Integrator::stateProjected), so generalized_alpha keeps its ẏ history and its
  // second order with a projection after every step (test_spatial_integrators).
  void setProjectionTolerance(double tol) { projection_tol_ = tol; }

  double time() const { return t_; }
  const VecX& state() const { return y_; }  // [q; θ; v; ω; W] (θ, ω with torsion on)
  const Model3& model() const { return *model_; }
  const NaturalFormulation& formulation() const { return formulation_; }
  Integrator& integrator() { return *integrator_; }
  OdeSystem& system() { return *this; }
  StateLayout layout() const { return StateLayout{int(y_.size()), formulation_.positionSize()}; }

  void kinematics(Kinematics3& kin) const { formulation_.kinematics(y_, kin); }
  // A_0..A_n and the end E_n [m] (n + 2 points; resized by the caller once).
  void positions(AlignedVector<Vec3>& p) const;
  double kineticEnergy();  // [J], the added mass's included
  double potentialEnergy();
  double energy() { return kineticEnergy() + potentialEnergy(); }  // T + V [J]
  double work() const { return y_[y_.size() - 1]; }                // W [J]
  double constraintError() const {                                 // [m]
    return formulation_.constraintError(y_, top_->at(t_), model_->bottomAt(t_));
  }
  PointMotion3 topAt(double t) const { return top_->at(t); }
  double directorError() const { return formulation_.directorError(y_); }
  // One evaluation at the current state: its data (reactions.top, reactions.bottom, joint forces).
  const NaturalData& evaluate();
  // The last evaluation made (of the last step's last stage, or of evaluate()). stepEndEvaluated(): the
  // last step's last evaluation was at its end time (rk4's k4, the implicit schemes' end evaluation,
  // dopri5's FSAL stage), so its reactions and kin are the step's end forces and state (before the
  // projection's round-off-sized move, or after it when the twist charts moved).
  const NaturalData& lastEvaluation() const { return *data_; }
  bool stepEndEvaluated() const { return end_evaluated_; }

  // Stability of explicit schemes (docs/spatial.md, "Stability"), as the planar Simulator: at the current
  // state, the highest natural frequency ω_max [rad/s] of the linearised line (Ritz values of ∂v'/∂q by
  // forward differences: every term, the twist with torsion on, the flex joints, the end mass and the
  // Baumgarte-held joints count) and the largest stable step of the explicit scheme (rk4 for the others)
  // from the Ritz values of the whole Jacobian, damping included. O(n) per probe, ~140 evaluations:
  // Run3 calls it once at the initial state. stableStepEstimate(): that step times
  // kStabilityFactor3 (a share kept for the motion raising the tension during the run, measured).
  void estimateStability();
  double highestFrequency() const { return omega_max_; }
  double stableStepEstimate() const;

 private:
  void rhs(double t, const VecX& y, VecX& dy) override;
  bool hasShiftedSolve() const override { return true; }
  void linearize(double t, const VecX& y) override;
  void factorShifted(double c) override;
  void solveShifted(const VecX& b, VecX& x) override;
  bool staleNext() const;

  std::shared_ptr<const Model3> model_;
  std::shared_ptr<const TopMotion3> top_;
  NaturalFormulation formulation_;
  std::unique_ptr<NaturalData> data_;
  std::unique_ptr<ShiftedSolver3> shifted_;
  std::unique_ptr<Integrator> integrator_;
  VecX y_, dy_;
  // The structured solves' linearisation, deferred to the first solve after linearize() or kept from the
  // last steps (simulator.cpp).
  static constexpr int kReuseSolves = 3, kReuseSteps = 8;
  VecX y_lin_;
  double t_lin_ = 0.0, c_pending_ = 0.0;
  long evaluations_ = 0, evaluations_at_lin_ = 0, evaluations_at_solve_ = 0;
  int solves_ = 0, age_ = 0, backoff_ = 0, wait_ = 0;
  bool lin_pending_ = false, reused_ = false, force_lin_ = true;
  const OneStageImplicit* newton_ = nullptr;  // the integrator when it is a Newton scheme (its reports)
  Kinematics3 kin_;
  double t_ = 0.0;
  double projection_tol_ = 0.0;
  bool end_evaluated_ = false;
  double omega_max_ = 0.0;
  double stable_step_ = INFINITY;  // raw: min(bound / ω_max, the damped step)
};

}  // namespace spatial
}  // namespace riser_sim
