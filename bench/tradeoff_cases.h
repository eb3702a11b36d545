// Cases of the speed/accuracy sweep (riser_sim_bench_tradeoff): each is a scene family in n, a duration,
// a probe point and a reference. References: the Table 1 line's end uses fixed converged values (elastic:
// rk4 at n = 320; inextensible: docs/validation.md's Richardson value), its force histories rk4 runs; the
// paper's riser scenes are referenced to runs of our own at two fine discretisations and two steps
// (Case::ref_runs), whose differences to the finest are reported as the reference's convergence. The
// elastic Table 1 line and the J-lay have variants with light axial damping (and, the J-lay, seabed
// springs per metre) whose force references converge in h and n (tradeoff_cases.cpp).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "riser_sim/scene/scene.h"
#include "tradeoff_history.h"

namespace tradeoff {

using riser_sim::Scene;
using riser_sim::Vec2;

// What a run is measured by.
struct Measures {
  Vec2 probe = Vec2::Zero();  // probe point at the end of the run [m]
  // Force histories on the grid t_k = k kHistoryDt (tradeoff_history.h) [N]:
  std::vector<double> top_tension;  // LineOutputs::top_tension, |force on the hang-off point|
  std::vector<double> max_axial;    // LineOutputs::max_tension: the largest axial force along the line
                                    // (max over rfes of axial_force, floored at 0)
  double peak() const;              // largest top tension on the grid
  double rms() const;               // RMS top tension on the grid
};

struct Case {
  std::string name;   // e.g. "jlay_elastic"
  std::string title;  // for plots
  std::function<Scene(int n)> scene;
  double duration = 20.0;       // simulated [s]
  double probe_s = 0.0;         // probe at this unstretched arc length from the top [m]
  bool probe_relative = false;  // probe relative to the top point (Table 1: x_s, y_s)
  std::vector<int> ns;          // n of the sweep
  // Reference runs (recursive formulation): the last one is the reference, its largest difference to
  // the others (a coarser n, a larger h) its spread. h <= 0 means -h times rk4's estimated stability limit.
  struct RefRun {
    int n;
    std::string integrator;
    double h;
  };
  std::vector<RefRun> ref_runs;
  std::string note;  // what differs from the shipped scene (e.g. the damped variants), for the tables
  // Table 1: the end position is docs/validation.md's converged value, not the reference run's.
  bool fixed_probe = false;
  Vec2 probe_ref = Vec2::Zero();
  double probe_spread = 0.0;  // [m]
  std::string probe_source;
};

// Every case; scenes from config/scenes (paper_jlay_170m.yaml, paper_riser_500m.yaml) under `root`.
std::vector<Case> allCases(const std::string& root);

// Point at unstretched arc length s [m] along the line (A_0 at 0, A_i at (i - 1/2) d, end at L),
// linear between the joints.
Vec2 probeAt(const riser_sim::LineOutputs& o, double length, int n, double s);

}  // namespace tradeoff
