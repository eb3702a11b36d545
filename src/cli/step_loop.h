// The stepping of a CLI run: whole steps to total_steps, a CSV row every `every` steps; only the stepping
// is timed (the outputs and the writing are excluded from wall_s / cpu_s).
#pragma once
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "output_file.h"
#include "riser_sim/line_run.h"
#include "run_output.h"

namespace riser_sim {
namespace cli {

struct SteppingTime {
  double wall_s = 0.0;  // [s] of wall time in step()
  double cpu_s = 0.0;   // [s] of this thread's CPU time in step()
};

// last: the initial outputs, then the last ones taken (copied into its storage: no allocation per row).
// Returns why the run stopped early ("" when it reached total_steps or the CSV stopped accepting rows:
// csv.ok() says which). total_steps 0: the initial row alone.
inline std::string stepRun(LineRun& run, long total_steps, long every, OutputFile& csv,
                           const std::vector<int>& probe_rfes, RunOutputs& last, SteppingTime& time) {
  const bool bottom = run.bottomMoves(), torsion = run.hasTorsion();
  last = run.outputs();
  if (!allFinite(last)) return "initial state has non-finite outputs";
  if (csv.isOpen()) writeCsvRow(csv.get(), last, probe_rfes, bottom, torsion);
  std::chrono::steady_clock::duration wall{0};
  std::string stopped;
  while (csv.ok() && run.steps() < total_steps) {
    const long chunk = std::min(every, total_steps - run.steps());
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = threadCpuSeconds();
    bool ok = true;
    for (long k = 0; k < chunk && ok; ++k) ok = run.step();
    wall += std::chrono::steady_clock::now() - start;
    time.cpu_s += threadCpuSeconds() - cpu_start;
    if (!ok) {
      stopped = run.divergenceReason();
      break;
    }
    const RunOutputs& o = run.outputs();
    if (!allFinite(o)) {
      stopped = "outputs are not finite";
      break;
    }
    last = o;
    if (csv.isOpen()) writeCsvRow(csv.get(), last, probe_rfes, bottom, torsion);
  }
  time.wall_s = std::chrono::duration<double>(wall).count();
  return stopped;
}

}  // namespace cli
}  // namespace riser_sim
