// What riser_sim_cli writes: one sample of the run (a CSV row) and the JSON summary line.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "output_file.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"
#include "riser_sim/run/section_extremes.h"

namespace riser_sim {
namespace cli {

// CPU time of this thread [s] (the stepping's cost on a loaded machine, beside its wall time).
double threadCpuSeconds();
// Prints "riser_sim_cli: error: MESSAGE" on stderr and returns code.
int fail(int code, const std::string& message);

// The CSV columns of every scene (planar or 3D, one schema): t, x/y/z of the top and the end, the forces and
// moments on the hang-off and on the anchor, tension_top, tension_max, energy, work, energy_drift,
// constraint_error; x/y/z_bottom when the bottom moves, top_twist with line.torsion; then per probed rfe K
// x/y/z_rfeK (its axial spring's point) and tension_rfeK.
std::string csvHeader(const std::vector<int>& probe_rfes = {}, bool bottom_moves = false, bool torsion = false);
// Writes one row (%.9g) in csvHeader()'s order. The caller checks allFinite(RunOutputs) (line_run.h) first: no
// NaN reaches the file.
void writeCsvRow(std::FILE* f, const RunOutputs& o, const std::vector<int>& probe_rfes, bool bottom_moves,
                 bool torsion);

// The range graph's CSV (--range-graph): rangeGraphHeader(), then one row per rfe (%.9g); the joint columns
// hold the joint at the rfe's far end, empty on the last row; clearance columns only with a seabed.
std::string rangeGraphHeader(bool seabed);
void writeRangeGraph(std::FILE* f, const RangeGraph& g);

// Steps between CSV rows: output_dt / dt rounded, at least 1, at most total_steps (an output_dt beyond
// the run gives its first and last rows only; the ratio can exceed a long).
long outputStride(double output_dt, double dt, long total_steps);

// The warning of a finished run whose energy balance is off by more than kEnergyDriftWarning (what it
// means and what to do), "" when it is within it.
std::string energyWarning(double drift);

// The "stability: ..." line of a run, planar or spatial: the highest frequency [rad/s] and the estimated
// limit [s] of the explicit fixed-step scheme (with a note when solver.dt is above it), or rk4's for
// reference when the scheme has no such limit.
std::string stabilityMessage(bool explicit_fixed_step, const std::string& scheme, double omega_max, double stable_dt,
                             double dt);

class JsonLine;

// How a CLI run (planar or spatial) ended, for its summary status, its exit code and its messages.
struct RunEnd {
  std::string diverged, write_error, warning;  // "" when none
  bool written = true;                         // the CSV (if any) was written completely
  bool csv = false;                            // a CSV was asked for
  double sim_s = 0.0;
  long steps = 0, total_steps = 0;
};
// The end of a run after its stepping (LineRun: time(), steps(), forceNoise(), forceWarning()). Closes (flushes) the
// CSV and reads whether it was written completely; a run that did not diverge warns when its energy balance is off by
// energy_drift (energyWarning) or its forces are noisy (Run::forceWarning), both joined by "; ".
template <class Run>
RunEnd runEnd(const Run& run, long total_steps, const std::string& diverged, double energy_drift, OutputFile& csv,
              bool csv_asked) {
  RunEnd e;
  e.written = csv.close();  // flush and close before reporting
  e.write_error = csv.error();
  e.diverged = diverged;
  if (diverged.empty()) {
    e.warning = energyWarning(energy_drift);
    const std::string forces = run.forceWarning(run.forceNoise().total());
    if (!forces.empty()) e.warning += (e.warning.empty() ? "" : "; ") + forces;
  }
  e.csv = csv_asked;
  e.sim_s = run.time();
  e.steps = run.steps();
  e.total_steps = total_steps;
  return e;
}
// "diverged", "write_failed", "warning" or "ok".
const char* runStatus(const RunEnd& e);
// Prints the summary j (when given) with the end's keys, the failure or warning messages, and returns the
// exit code; kExitOk: the caller prints its "done" line.
int finishRun(const RunEnd& e, JsonLine* summary);

// Builds one line of JSON; non-finite numbers are written as null.
class JsonLine {
 public:
  JsonLine& add(const std::string& key, double v);
  JsonLine& add(const std::string& key, long v);
  JsonLine& add(const std::string& key, int v) { return add(key, static_cast<long>(v)); }
  JsonLine& add(const std::string& key, bool v);
  JsonLine& add(const std::string& key, const std::string& v);
  JsonLine& add(const std::string& key, const char* v) { return add(key, std::string(v)); }
  std::string str() const { return "{" + body_ + "}"; }

 private:
  void addRaw(const std::string& key, const std::string& json);
  std::string body_;
};

std::string jsonString(const std::string& s);

// The summary's keys of a sectioned line (over the run): per section k sectionK_tension_max, sectionK_tension_max_s,
// sectionK_curvature_max, sectionK_curvature_max_s; a wave configuration's sag_z, sag_s, hog_z, hog_s.
void addSectionKeys(JsonLine& j, const SectionExtremes& sections, const RangeGraph& range);

}  // namespace cli
}  // namespace riser_sim
