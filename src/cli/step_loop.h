// The stepping of a CLI run: whole steps to total_steps, a CSV row every `every` steps, the range graph (if
// any) and the section extremes fed every step; only the stepping is timed (the outputs and the writing are excluded
// from wall_s / cpu_s).
#pragma once
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "output_file.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"
#include "riser_sim/run/section_extremes.h"
#include "run_output.h"

namespace riser_sim {
namespace cli {

struct SteppingTime {
  double wall_s = 0.0;  // [s] of wall time in step()
  double cpu_s = 0.0;   // [s] of this thread's CPU time in step()
};

// last: the initial outputs, then the last ones taken (copied into its storage: no allocation per row).
// Returns why the run stopped early ("" when it reached total_steps or the CSV stopped accepting rows:
// csv.ok() says which). total_steps 0: the initial row alone. range: built from the initial outputs here and
// fed every step (nullptr: no range graph); sections (made from the initial outputs by the caller): fed with it.
inline std::string stepRun(LineRun& run, long total_steps, long every, OutputFile& csv,
                           const std::vector<int>& probe_rfes, RunOutputs& last, SteppingTime& time,
                           std::unique_ptr<RangeGraph>* range = nullptr, const SeabedPlane& seabed = {},
                           SectionExtremes* sections = nullptr) {
  const bool bottom = run.bottomMoves(), torsion = run.hasTorsion();
  last = run.outputs();
  if (!allFinite(last)) return "initial state has non-finite outputs";
  if (csv.isOpen()) writeCsvRow(csv.get(), last, probe_rfes, bottom, torsion);
  if (range) *range = std::make_unique<RangeGraph>(last, seabed);
  RangeGraph* graph = range ? range->get() : nullptr;
  std::chrono::steady_clock::duration wall{0};
  std::string stopped;
  while (csv.ok() && run.steps() < total_steps) {
    const long chunk = std::min(every, total_steps - run.steps());
    bool ok = true;
    for (long k = 0; k < chunk && ok; k += graph ? 1 : chunk) {  // with a range graph, one step at a time
      const long steps = graph ? 1 : chunk;
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = threadCpuSeconds();
      for (long m = 0; m < steps && ok; ++m) ok = run.step();
      wall += std::chrono::steady_clock::now() - start;
      time.cpu_s += threadCpuSeconds() - cpu_start;
      if (ok && graph && k + 1 < chunk) {  // the chunk's last step: fed below with the row
        const RunOutputs& o = run.outputs();
        if (!allFinite(o)) {
          stopped = "outputs are not finite";
          break;
        }
        graph->add(o);
        if (sections) sections->add(o);
      }
    }
    if (!stopped.empty()) break;
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
    if (graph) graph->add(o);
    if (graph && sections) sections->add(o);
    if (csv.isOpen()) writeCsvRow(csv.get(), last, probe_rfes, bottom, torsion);
  }
  time.wall_s = std::chrono::duration<double>(wall).count();
  return stopped;
}

}  // namespace cli
}  // namespace riser_sim
