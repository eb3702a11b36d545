// One timed run of the speed/accuracy sweep: a case at (formulation, integrator, n, h or tolerance),
// stepped to the case's duration with the force histories sampled on the grid of tradeoff_history.h.
// Timing covers the stepping only (not the statics nor the sampling); the thread's CPU time is recorded
// beside the wall time.
#pragma once
#include <cmath>
#include <string>

#include "tradeoff_cases.h"

namespace tradeoff {

struct Config {
  const Case* c = nullptr;
  std::string formulation, integrator;
  int n = 0;
  double h = 0.0;                 // solver.dt (dopri5: output step) [s]; <= 0: -h x rk4's estimated limit
  double tol = 0.0;               // dopri5 only
  std::string jacobian = "auto";  // implicit schemes: auto | structured | dense
  double rho_inf = NAN;           // solver.rho_inf of a scheme that has it (NaN: the scene's); see applyConfig
};

// The scene of a run: the case's scene at n with the Config's solver settings. The one place a Config
// reaches the Scene (a new solver setting of the sweep goes here).
riser_sim::Scene applyConfig(const Config& c);

struct Result {
  std::string status;  // ok | diverged | skipped
  std::string reason;
  double h = 0.0;                // the step actually used [s]
  double wall = 0.0, cpu = 0.0;  // medians [s]
  int runs = 0;
  long steps = 0;
  Measures m;
  double drift = 0.0, limit = 0.0;  // energy-balance error; rk4 stability estimate [s]
  riser_sim::Integrator::Stats stats;
};

// Runs c; repeats 3 times (median) when a run takes less than repeat_below seconds. A run predicted
// (from its first ~0.3 s of stepping) to take more than max_run seconds is skipped.
Result run(const Config& c, double max_run, double repeat_below = 2.0);

}  // namespace tradeoff
