// The stepping of a CLI run, planar or spatial: whole steps to total_steps, a sample (and a CSV row) every
// `every` steps; only the stepping is timed (sampling and writing are excluded from wall_s / cpu_s).
#pragma once
#include <algorithm>
#include <chrono>
#include <string>

#include "output_file.h"
#include "run_output.h"

namespace riser_sim {
namespace cli {

struct SteppingTime {
  double wall_s = 0.0;  // [s] of wall time in step()
  double cpu_s = 0.0;   // [s] of this thread's CPU time in step()
};

// Run: step() -> bool, steps(), divergenceReason(). sample() -> Sample, finite(Sample) -> bool,
// write(FILE*, Sample). last: the initial sample, then the last one taken. Returns why the run stopped
// early ("" when it reached total_steps or the CSV stopped accepting rows: csv.ok() says which).
template <class Run, class Sample, class SampleFn, class FiniteFn, class WriteFn>
std::string stepRun(Run& run, long total_steps, long every, OutputFile& csv, SampleFn sample, FiniteFn finite,
                    WriteFn write, Sample& last, SteppingTime& time) {
  last = sample();
  if (!finite(last)) return "initial state has non-finite outputs";
  if (csv.isOpen()) write(csv.get(), last);
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
    Sample s = sample();
    if (!finite(s)) {
      stopped = "outputs are not finite";
      break;
    }
    last = std::move(s);
    if (csv.isOpen()) write(csv.get(), last);
  }
  time.wall_s = std::chrono::duration<double>(wall).count();
  return stopped;
}

}  // namespace cli
}  // namespace riser_sim
