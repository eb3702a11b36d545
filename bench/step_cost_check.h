// Is the step cost of the shipped scenes (config/scenes/*.yaml, as the CLI runs them) unchanged? A saved
// baseline (--save-baseline) against the build at hand (--compare), within a tolerance (3 %).
//
// Per scene: its run (buildLineRun), warm-up steps (3, then 20 ms of CPU whose cost sizes the blocks for
// `target`), then `rounds` rounds; each round times, for every
// scene in turn, a fixed arithmetic kernel (no riser_sim code, the same in every build) and right after it
// a block of the scene's steps (thread CPU time). The scenes are interleaved round by round, so a drift of
// the machine's speed falls on every scene alike, and each block is normalised by its kernel block:
// q = (CPU per step) / (CPU per kernel pass). Medians over the rounds. The comparison replays the
// baseline's warm-up and blocks (the same steps of the same trajectories), so both time the same work.
//
// Verdict per scene on r = q_now / q_baseline with its standard error s (of each median: 1.2533 σ / √rounds,
// σ = IQR / 1.349, the two combined): unchanged when |r - 1| + 2 s <= tolerance; slower / faster when
// |r - 1| - 2 s > tolerance; inconclusive otherwise (the noise is too large to say); a scene whose n,
// integrator, dt or space differ from the baseline's is "scene changed", not compared.
#pragma once
#include <string>
#include <vector>

namespace riser_sim {
namespace bench {

struct StepCheckOptions {
  std::string root = ".";                                     // the package (config/scenes)
  std::string baseline = "out/bench/step_cost_baseline.csv";  // written by --save-baseline
  std::vector<std::string> scenes;  // scene names (config/scenes/<name>.yaml); empty: every shipped scene
                                    // (--compare: the baseline's)
  double target = 0.5;              // [s] of thread CPU per scene over all rounds (--save-baseline)
  int rounds = 15;
  double tolerance = 0.03;
  bool fail_on_change = false;  // --compare exits 3 unless every scene is unchanged
  std::string command;          // for the table's provenance line
};

// Writes opts.baseline; 0 on success.
int saveStepCostBaseline(const StepCheckOptions& opts);
// Prints (and writes as the table step_cost_check) the comparison; 0 on success, 1 on an error, 3 with
// fail_on_change and a scene not unchanged.
int compareStepCost(const StepCheckOptions& opts);

}  // namespace bench
}  // namespace riser_sim
