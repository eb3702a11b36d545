// Command line of riser_sim_cli.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace riser_sim {
namespace cli {

struct CliOptions {
  std::string scene;                   // --scene FILE (required)
  std::vector<std::string> overrides;  // --set key.path=value, in order
  double duration = -1.0;              // --duration S [s]; < 0: run.duration; 0: the statics alone
  std::string csv;                     // --csv FILE; empty: no time series
  double output_dt = 0.1;              // --output-dt S [s]: CSV row interval
  bool summary = false;                // --summary: one JSON line on stdout at the end
  bool quiet = false;                  // --quiet: no progress text on stderr
  bool help = false;                   // --help
  int modes = 0;                       // --modes K: statics + lowest K natural modes (0: off)
  std::string modes_csv;               // --modes-csv FILE: mode shapes (needs --modes)
  std::vector<int> probe_rfes;         // --probe-rfe K: CSV columns of rfe K (checked against n later)
  std::string range_graph;             // --range-graph FILE: min/max envelopes along the line (range_graph.h)
};

// Exit codes (usage() and docs/overview.md list them).
constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;     // bad option, scene or value; an output file that cannot be opened
constexpr int kExitDiverged = 3;     // the run diverged, or the initial statics failed
constexpr int kExitWriteFailed = 4;  // an output (file or stdout) could not be written completely

// Bad command line (exit code 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Accepts "--opt VALUE" and "--opt=VALUE". Throws UsageError.
CliOptions parseOptions(int argc, char** argv);
std::string usage();

}  // namespace cli
}  // namespace riser_sim
