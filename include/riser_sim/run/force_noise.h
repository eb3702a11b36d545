// Step-to-step noise in the forces a run reports (top tension, largest axial force), as an estimate
// of the force error that the step does not resolve. Modes far beyond 1/h that a scheme does not damp
// (the implicit midpoint rule at h ≫ the axial periods) map to frequencies near the step's Nyquist
// frequency and stay in the forces at full amplitude: T_k flips from step to step. The second
// difference d_k = T_{k+1} - 2 T_k + T_{k-1} sees them (white noise of RMS σ gives rms(d) = √6 σ, a
// Nyquist tone of amplitude a gives 4 a), while resolved content gives d ≈ h² T'' (1 % of a 1 s
// tone's amplitude at h = 0.016 s). The estimate rms(d)/√6 / rms(T) is a lower bound on the force error
// (it misses slow errors), set to the level of the noise. Cumulative over the run and over a recent
// window (exponential, kWindow of simulated time) for a running node.
#pragma once
#include <cmath>
#include <string>

#include "riser_sim/scene/choices.h"

namespace riser_sim {

// Noise estimate [relative] above which a run says its forces are not resolved (the CLI's summary,
// the node's diagnostics): 5 % of the force's RMS.
constexpr double kForceNoiseWarning = 0.05;

struct ForceNoise {
  double top = 0.0;        // top tension: noise RMS / tension RMS
  double max_axial = 0.0;  // largest axial force along the line: noise RMS / its RMS
  double worst() const { return std::max(top, max_axial); }
};

// Empty, or why forces with noise e are not resolved at solver.dt dt [s] with this integrator (and
// solver.rho_inf, for generalized_alpha) and what setting resolves them: the planar and the 3D runs' warning.
std::string forceNoiseWarning(const ForceNoise& e, double dt, IntegratorKind integrator, double rho_inf);

class ForceNoiseMonitor {
 public:
  static constexpr double kWindow = 10.0;  // [s] of simulated time: the recent estimate's memory
  void reset() { *this = ForceNoiseMonitor(); }
  // Forces at the end of a step of dt [s].
  void add(double top_tension, double max_axial, double dt);
  ForceNoise total() const { return estimate(sum_); }
  ForceNoise recent() const { return estimate(recent_); }
  long samples() const { return n_; }

 private:
  struct Sums {
    double d2_top = 0.0, t2_top = 0.0, d2_ax = 0.0, t2_ax = 0.0;  // Σ d², Σ T² (or weighted)
  };
  static ForceNoise estimate(const Sums& s);
  Sums sum_, recent_;
  double top_[2] = {0.0, 0.0}, ax_[2] = {0.0, 0.0};  // the two previous values
  long n_ = 0;                                       // values seen
};

}  // namespace riser_sim
