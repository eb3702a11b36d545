// Cases of the speed/accuracy sweep (riser_sim_bench_tradeoff): each is a scene family in n, a duration,
// a probe point and a reference. References: the Table 1 line's end uses fixed converged values (elastic:
// rk4 at n = 320; inextensible: docs/validation.md's Richardson value), its tensions an rk4 run at
// n = 100; the paper's riser scenes are referenced to runs of our own at two fine discretisations and two
// steps (Case::ref_runs), whose largest difference is reported as the reference's spread.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "riser_sim/scene.h"

namespace tradeoff {

using riser_sim::Scene;
using riser_sim::Vec2;

// What a run is measured by.
struct Measures {
  Vec2 probe = Vec2::Zero();  // probe point at the end of the run [m]
  double peak = 0.0;          // peak top tension over the run [N]
  double rms = 0.0;           // RMS top tension over the run [N]
};

struct Case {
  std::string name;                  // e.g. "jlay_elastic"
  std::string title;                 // for plots
  std::function<Scene(int n)> scene;
  double duration = 20.0;            // simulated [s]
  double probe_s = 0.0;              // probe at this unstretched arc length from the top [m]
  bool probe_relative = false;       // probe relative to the top point (Table 1: x_s, y_s)
  std::vector<int> ns;               // n of the sweep
  // Reference runs (recursive formulation): the last one is the reference, its largest difference to
  // the others (a coarser n, a larger h) its spread. h <= 0 means -h times rk4's estimated stability limit.
  struct RefRun {
    int n;
    std::string integrator;
    double h;
  };
  std::vector<RefRun> ref_runs;
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
