// Implicit schemes for stiff lines, on y = [q; v; rest] with q' = v (every formulation's layout; the
// trailing entries, the work W, are integrated by the same rule but take no part in the solve).
//
// Linear solves (IntegratorOptions::jacobian):
// - "structured": the system's own O(n) solves (OdeSystem::linearize / factorShifted / solveShifted; the
//   chain formulations, see chain_shifted_solver.h), relinearised at every step. A Rosenbrock-W method
//   keeps its order with any such approximate J; Newton (midpoint, generalized_alpha) converges linearly at its
//   accuracy.
// - "dense": A_q = ∂a/∂q, A_v = ∂a/∂v by forward differences (2p evaluations, p = size of q), dense,
// refreshed every IntegratorOptions::jacobian_interval of simulated time, when h changes, or when
// Newton stalls. The linear systems (I - c J) x = b reduce to the p x p matrix
//   S = I - c A_v - c² A_q,   u = S^-1 (b_v + c A_q b_q),   x_q = b_q + c u,   x_v = u,
// factored by partial-pivot LU (O(p³) per refresh, O(p²) per solve). This is not O(n) per step: the
// cost is stated (measured) in docs/benchmarks.md. Workspaces are sized in reset(); step() does not
// allocate.
#pragma once
#include <Eigen/LU>

#include "riser_sim/integrators/integrator.h"

namespace riser_sim {

class ImplicitIntegrator : public Integrator {
 public:
  explicit ImplicitIntegrator(const IntegratorOptions& options) : options_(options) {}
  void reset(const StateLayout& layout) override;
  void restart() override {
    jac_valid_ = f0_valid_ = f0_projected_ = false;
    failure_.clear();
  }
  void forcesChanged() override { f0_valid_ = f0_projected_ = false; }
  void stateProjected(const VecX& y) override {
    y_end_ = y;
    f0_projected_ = f0_valid_ || f0_projected_;
    f0_valid_ = false;
  }
  const std::string& failure() const override { return failure_; }
  Stats stats() const override { return stats_; }

 protected:
  // Jacobian at (t, y) with f0 = f(t, y); factors for coefficient c.
  void jacobian(OdeSystem& sys, double t, const VecX& y, const VecX& f0);
  void factor(OdeSystem& sys, double c);
  // x = (I - c J)^-1 b on the first 2p entries (c of the last factor()).
  void solve(OdeSystem& sys, const VecX& b, VecX& x);
  // Structured: relinearised at every new t. Dense: older than the refresh interval (or none).
  bool jacobianStale(double t) const {
    return !jac_valid_ || (structured_ ? t != jac_t_ : std::abs(t - jac_t_) >= options_.jacobian_interval);
  }
  // f(t, y) into f0_, reusing the last end-of-step evaluation when y and t are unchanged.
  void startValue(OdeSystem& sys, double t, const VecX& y);
  void fail(const char* what, double t, VecX& y);

  IntegratorOptions options_;
  int n_ = 0, p_ = 0, m_ = 0;  // state size, positions, implicit part (2p)
  MatX Aq_, Av_, S_;
  Eigen::PartialPivLU<MatX> lu_;
  VecX f0_, fp_, yp_, bu_, u_, y_end_;
  double jac_t_ = 0.0, c_ = -1.0, t_end_ = 0.0;
  bool jac_valid_ = false, f0_valid_ = false;
  bool f0_projected_ = false;  // f0_ stale only by stateProjected() (the forces did not change)
  bool structured_ = false;    // options_.jacobian == "structured": the system's O(n) solves
  std::string failure_;
  Stats stats_;
};

// Schemes with one implicit stage z = b + c f(t + θh, z) (c = κh; b from y0 and the scheme's history;
// z = y0 + θ (y1 - y0) on q, v), solved by modified Newton with (I - cJ). The predictor extrapolates the
// last equal steps' increments d1, d2, d3 (newest first): z0 = y0 + a d1 + b d2 + c d3, exact for a
// smooth solution to second order in its increments and for a component the scheme carries as r∞^k (its
// root at hλ -> -∞: midpoint -1, generalized_alpha -ρ∞), the unresolved stiff modes a linear
// extrapolation mispredicts by twice their size every step. After one or two equal steps, or when the
// last step's stage lay nearer it, the last increment is carried on instead (z0 = y0 + θ d1). A stale
// Jacobian is refreshed once, and when Newton still fails the step is retried as 2, 4, 8 equal substeps
// before giving up. The scheme supplies b and the end of the step.
class OneStageImplicit : public ImplicitIntegrator {
 public:
  // stiff_root: r∞, in [-1, 0].
  OneStageImplicit(const IntegratorOptions& options, double theta, double kappa, double stiff_root);
  void reset(const StateLayout& layout) override;
  void restart() override {
    ImplicitIntegrator::restart();
    equal_steps_ = 0;
  }
  bool step(OdeSystem& sys, double t, VecX& y, double h) override;
  // The predictor's weights (a, b, c) on the last three increments (for its test).
  const Eigen::Vector3d& predictorWeights() const { return weights_; }
  int stages() const override { return 3; }  // typical: 2 Newton iterations + the end evaluation
  // The last converged Newton solve: its solves, and its stopping test's measure over that test's bound
  // (<= 1: the smaller of |Δz| / tol and, from the second solve on, η/(1-η) |Δz| / (tol / 10)). A system
  // that keeps its factor across steps reads it to see the factor going stale (Simulator3).
  struct NewtonReport {
    int solves = 0;
    double margin = 0.0;
  };
  const NewtonReport& lastNewton() const { return last_newton_; }

 protected:
  // b of the stage equation for a step h from y0 (f0_ = f(t, y0) is current); may return y0 itself.
  virtual const VecX& stageBase(const VecX& y0, double h) = 0;
  // y0 -> y1 from the converged stage (z_, fz_ = f(t + θh, z_)), on every entry (W too).
  virtual void advance(VecX& y, double h) = 0;
  // State beyond y (generalized-α's ẏ): taken up at the start of a step (f0_ current), saved before the
  // first try and put back before a retry in substeps.
  virtual void beginStep(double /*t*/, const VecX& /*y*/) {}
  // Whether beginStep() reads f0_ at this start (else step() may leave f(t, y) out: see step()).
  virtual bool historyNeedsF0(double /*t*/, const VecX& /*y*/) const { return false; }
  virtual void saveHistory() {}
  virtual void restoreHistory() {}

  const double theta_, kappa_;
  VecX z_, fz_;

 private:
  static constexpr int kMaxPieces = 8;  // substeps tried when Newton fails on the whole step
  bool newton(OdeSystem& sys, double t, const VecX& y0, const VecX& base, double h);
  bool single(OdeSystem& sys, double t, VecX& y, double h);
  VecX g_, dz_, y_save_, f_save_;
  VecX d_[3];  // the last increments y1 - y0 of equal steps h_prev_, newest first
  Eigen::Vector3d weights_;
  NewtonReport last_newton_;
  int equal_steps_ = 0;   // how many of d_ hold such increments (0: no predictor)
  bool weighted_ = true;  // the weighted start (else the last increment's): the one nearer the last stage
  double h_prev_ = 0.0;
};

// Implicit midpoint rule: y1 = y0 + h f(t + h/2, z), z = y0 + (h/2) f(t + h/2, z) = (y0 + y1)/2.
// Second order, A-stable, symmetric (time-reversible), no numerical damping; conserves quadratic
// invariants exactly. For long conservative runs.
class ImplicitMidpoint : public OneStageImplicit {
 public:
  explicit ImplicitMidpoint(const IntegratorOptions& options) : OneStageImplicit(options, 0.5, 0.5, -1.0) {}
  std::string name() const override { return "midpoint"; }

 protected:
  const VecX& stageBase(const VecX& y0, double /*h*/) override { return y0; }
  void advance(VecX& y, double h) override { y += h * fz_; }
};

// Generalized-α in first-order form (Jansen, Whiting & Hulbert 2000; Chung & Hulbert 1993 for the
// second-order one) with the user's high-frequency spectral radius ρ∞ = IntegratorOptions::rho_inf:
//   y1 = y0 + h ẏ0 + γ h (ẏ1 - ẏ0),   ẏ0 + αm (ẏ1 - ẏ0) = f(t + αf h, y0 + αf (y1 - y0)),
//   αm = (3 - ρ∞) / (2 (1 + ρ∞)),  αf = 1 / (1 + ρ∞),  γ = 1/2 + αm - αf (= αf).
// The stage z = y0 + αf (y1 - y0) solves z = y0 + d ẏ0 + c f(t + αf h, z), c = αf γ h / αm,
// d = αf h (αm - γ) / αm: the existing (I - cJ) solve. ẏ is the scheme's own variable (not f(y)), carried
// from step to step; it starts as f(t, y) and again after restart() or when y was changed from outside,
// but not on forcesChanged() (a reset to f(y) at every step turns it into another, first-order scheme).
// On y' = λy: second order; the resolved modes lose 1 - |R| = (1 - ρ∞)³ / (4 (1 + ρ∞)³) (ωh)⁴ per step,
// the unresolved ones are damped to |R| → ρ∞ as ωh → ∞ (as ρ∞ ± (1 + ρ∞) √(1 - ρ∞²) / (2 √(ωh)) on the
// imaginary axis: the limit is a double root). ρ∞ = 1 is the implicit midpoint rule (same iterates),
// ρ∞ = 0 annihilates the highest modes in one step.
class GeneralizedAlpha : public OneStageImplicit {
 public:
  explicit GeneralizedAlpha(const IntegratorOptions& options);
  std::string name() const override { return "generalized_alpha"; }
  void reset(const StateLayout& layout) override;
  void restart() override {
    OneStageImplicit::restart();
    ydot_valid_ = false;
  }
  double rhoInf() const { return rho_inf_; }

 protected:
  const VecX& stageBase(const VecX& y0, double h) override;
  void advance(VecX& y, double h) override;
  void beginStep(double t, const VecX& y) override;
  bool historyNeedsF0(double t, const VecX& y) const override;
  void saveHistory() override { ydot_save_ = ydot_; }
  void restoreHistory() override { ydot_ = ydot_save_; }

 private:
  double rho_inf_, alpha_m_, alpha_f_, gamma_;
  VecX ydot_, ydot_save_, b_;
  bool ydot_valid_ = false;
};

// Linearly implicit Rosenbrock-W method ROS2 (Verwer, Spee, Blom & Hundsdorfer 1999), γ = 1 + 1/√2:
//   (I - γhJ) k1 = f(t, y),  (I - γhJ) k2 = f(t + h, y + h k1) - 2 k1,  y1 = y + h (3 k1 + k2) / 2.
// Second order for any J (a W-method, so a reused Jacobian keeps the order), L-stable: the unresolved
// axial mode is damped, not amplified. Two evaluations and two solves per step, no iteration.
class Rosenbrock2 : public ImplicitIntegrator {
 public:
  using ImplicitIntegrator::ImplicitIntegrator;
  std::string name() const override { return "rosenbrock2"; }
  void reset(const StateLayout& layout) override;
  bool step(OdeSystem& sys, double t, VecX& y, double h) override;
  int stages() const override { return 2; }

 private:
  VecX k1_, k2_, f2_;
};

}  // namespace riser_sim
