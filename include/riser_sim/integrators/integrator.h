// Time integrators behind one small interface (Drake-style). Workspaces are sized once in reset();
// step() allocates nothing.
#pragma once
#include <complex>
#include <memory>
#include <string>

#include "riser_sim/scene/choices.h"
#include "riser_sim/types.h"

namespace riser_sim {

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual void rhs(double t, const VecX& y, VecX& dy) = 0;
  // Optional structured (O(n)) linear solves for the implicit schemes on y = [q; v; rest]:
  // linearize at (t, y), factor for c, then x = (I - c J)^-1 b on the first 2p entries.
  virtual bool hasShiftedSolve() const { return false; }
  virtual void linearize(double /*t*/, const VecX& /*y*/) {}
  virtual void factorShifted(double /*c*/) {}
  virtual void solveShifted(const VecX& /*b*/, VecX& /*x*/) {}
};

// Layout of the state y = [q; v; rest]: q and v have `positions` entries each, the rest (the work W)
// is integrated alongside but takes no part in error control or linear solves.
struct StateLayout {
  int size = 0;
  int positions = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Sizes the workspaces for the system's state (the only allocation).
  virtual void reset(const StateLayout& layout) = 0;
  // Advances y from t by h [s]. False when the step could not meet its contract (failure() says why;
  // y then holds the last good state and the caller must stop).
  virtual bool step(OdeSystem& sys, double t, VecX& y, double h) = 0;
  // Number of rhs evaluations per step (for cost reports).
  virtual int stages() const = 0;

  // --- Additions for adaptive / implicit schemes (defaults fit a fixed-step explicit scheme). ---
  // The system changed outside the integrator (new initial state, a term's history moved): cached
  // derivatives (FSAL, Jacobians) must not be reused.
  virtual void restart() {}
  // A term's run state moved between steps (seabed anchors): derivative values cached at the old state
  // (FSAL, f(t, y)) must not be reused; an approximate Jacobian may (the implicit schemes keep their dense
  // one until its refresh interval instead of an O(p³) refresh every step).
  virtual void forcesChanged() { restart(); }
  // The caller moved y by a projection onto the constraint manifold (a small move, not a new start): the
  // scheme keeps its history (generalized_alpha's ẏ) and takes y as where its last step ended; values
  // evaluated at the unprojected state (f(t, y), FSAL) are not reused. Default: nothing to keep.
  virtual void stateProjected(const VecX& /*y*/) {}
  // Why the last step() returned false (Newton failed, step size underflow). Cleared by
  // reset()/restart(). A reference: no allocation on the hot path.
  virtual const std::string& failure() const {
    static const std::string none;
    return none;
  }
  // Explicit fixed-step scheme: the step is limited by stability (|λ| h below stabilityBound()).
  virtual bool explicitFixedStep() const { return false; }
  // Largest |λ h| on the imaginary axis inside the stability region (0: unconditionally stable).
  virtual double stabilityBound() const { return 0.0; }
  // Explicit fixed-step scheme: its stability function R(z), y1 = R(h λ) y0 on y' = λ y.
  virtual std::complex<double> stabilityFunction(std::complex<double> /*z*/) const { return 0.0; }
  // Cumulative work counters (for cost reports).
  struct Stats {
    long substeps = 0, rejected = 0, rhs = 0, jacobians = 0, factorizations = 0, newton = 0;
  };
  virtual Stats stats() const { return Stats(); }
};

// Loosest Newton tolerance accepted (IntegratorOptions::newton_tolerance; measured in docs/benchmarks.md).
constexpr double kMaxNewtonTolerance = 1e-3;

// Settings of the integrators beyond h (solver.tolerance etc.).
struct IntegratorOptions {
  double tolerance = 1e-6;         // dopri5: atol = rtol on positions and velocities
  double jacobian_interval = 0.1;  // implicit schemes: dense Jacobian refresh period [s of simulated time]
  // Implicit schemes: kStructured (the system's O(n) solves, relinearised every step) or kDense
  // (finite-difference Jacobian, O(p²) per solve).
  JacobianKind jacobian = JacobianKind::kStructured;
  // generalized_alpha: high-frequency spectral radius ρ∞ in [0, 1] (1: no numerical damping, the midpoint
  // rule; 0: the unresolved modes are annihilated in one step). Default: solver.rho_inf's (SolverSettings).
  double rho_inf = 0.5;
  // midpoint, generalized_alpha: Newton's stopping bound, relative to 1 + |z_i| (implicit_integrators.cpp).
  // Default: solver.newton_tolerance's (SolverSettings).
  double newton_tolerance = 1e-11;
};

// Classical fixed-step fourth-order Runge-Kutta (the paper's scheme).
class Rk4 : public Integrator {
 public:
  std::string name() const override { return "rk4"; }
  void reset(const StateLayout& layout) override;
  bool step(OdeSystem& sys, double t, VecX& y, double h) override;
  int stages() const override { return 4; }
  bool explicitFixedStep() const override { return true; }
  double stabilityBound() const override { return 2.8284; }  // RK4 on the imaginary axis: 2 sqrt(2)
  std::complex<double> stabilityFunction(std::complex<double> z) const override {
    return 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
  }
  Stats stats() const override { return stats_; }

 private:
  VecX k1_, k2_, k3_, k4_, tmp_;
  Stats stats_;
};

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind, const IntegratorOptions& options = {});
// rosenbrock2, midpoint and generalized_alpha: the schemes with linear solves (and the dense-Jacobian size limits).
bool isImplicitIntegrator(IntegratorKind kind);

}  // namespace riser_sim
