#include "cli_options.h"

#include <cmath>
#include <cstdlib>

namespace riser_sim {
namespace cli {

namespace {

double seconds(const std::string& option, const std::string& text, bool zero_ok) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || !(zero_ok ? v >= 0.0 : v > 0.0))
    throw UsageError(option + ": expected a number of seconds " + (zero_ok ? ">= 0" : "> 0") + ", got '" + text + "'");
  return v;
}

}  // namespace

std::string usage() {
  return "usage: riser_sim_cli --scene FILE [options]\n"
         "Runs a scene offline (no roscore) and reports the motion of the line.\n"
         "\n"
         "  --scene FILE        scene file (YAML, keys in docs/scene_keys.md)      [required]\n"
         "  --set KEY=VALUE     override a scene key, VALUE parsed as YAML, e.g.\n"
         "                      --set line.elements=40 --set top.position=[1,2]   [repeatable]\n"
         "                      --set KEY=null removes the key (it must be in the scene)\n"
         "  --duration S        simulated time [s] (default: run.duration); 0: the statics alone\n"
         "  --csv FILE          time series every --output-dt seconds, 3D (z up) for every scene (a\n"
         "                      planar scene in x-z): t,x_top,y_top,z_top,x_end,y_end,z_end,top_fx,\n"
         "                      top_fy,top_fz,bottom_fx,bottom_fy,bottom_fz,top_mx,...,bottom_mz,\n"
         "                      tension_top,tension_max,energy,work,energy_drift,constraint_error\n"
         "  --output-dt S       CSV row interval [s] (default 0.1)\n"
         "  --probe-rfe K       adds CSV columns x/y/z_rfeK (middle of rfe K, at the arc length\n"
         "                      of its axial spring) and tension_rfeK (axial force in rfe K) [N];\n"
         "                      K = 0..line.elements                               [repeatable]\n"
         "  --range-graph FILE  range graph: per station along the line, the least and largest value\n"
         "                      over every step of the run (the initial state included):\n"
         "                      s,tension_min,tension_max,clearance_min,clearance_max,s_joint,\n"
         "                      moment_min,moment_max,curvature_min,curvature_max; one row per rfe\n"
         "                      (n + 1): s its middle's unstretched arc length from the top [m],\n"
         "                      tension its axial force [N], clearance of its middle above the\n"
         "                      seabed [m] (columns only with a seabed); s_joint [m], the bending\n"
         "                      moment [N m] (planar signed, 3D its size) and curvature [1/m] of the\n"
         "                      joint at the rfe's far end (empty on the last row)\n"
         "  --summary           print one JSON line with the results at the end (stdout)\n"
         "  --quiet             no progress text on stderr\n"
         "  --modes K           statics + the K lowest natural modes about it (table on stdout);\n"
         "                      no time run unless --duration is given too\n"
         "  --modes-csv FILE    mode shapes: mode,period_s,frequency_hz,character,point,s,x,y,dx,dy\n"
         "  --help              this text\n"
         "\n"
         "exit codes: 0 ok, 2 bad input (option, scene, an output file that cannot be opened),\n"
         "3 diverged or initial statics failed, 4 an output could not be written (disk full, I/O error;\n"
         "the message names the file or stdout)\n";
}

CliOptions parseOptions(int argc, char** argv) {
  CliOptions o;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i], value;
    bool has_value = false;
    const size_t eq = arg.find('=');
    if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_value = true;
    }
    const auto takeValue = [&]() -> std::string {
      if (has_value) return value;
      if (i + 1 >= argc) throw UsageError(arg + ": missing value");
      return argv[++i];
    };
    const auto noValue = [&]() {
      if (has_value) throw UsageError(arg + ": takes no value");
    };
    if (arg == "--help" || arg == "-h") {
      noValue();
      o.help = true;
    } else if (arg == "--scene") {
      o.scene = takeValue();
    } else if (arg == "--set") {
      o.overrides.push_back(takeValue());
    } else if (arg == "--duration") {
      o.duration = seconds(arg, takeValue(), true);
    } else if (arg == "--csv") {
      o.csv = takeValue();
      if (o.csv.empty()) throw UsageError("--csv: empty file name");
    } else if (arg == "--output-dt") {
      o.output_dt = seconds(arg, takeValue(), false);
    } else if (arg == "--summary") {
      noValue();
      o.summary = true;
    } else if (arg == "--modes") {
      const std::string text = takeValue();
      char* end = nullptr;
      const long k = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || k < 1 || k > 100000)
        throw UsageError("--modes: expected a whole number of modes >= 1, got '" + text + "'");
      o.modes = static_cast<int>(k);
    } else if (arg == "--probe-rfe") {
      const std::string text = takeValue();
      char* end = nullptr;
      const long k = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || k < 0 || k > 1000000)
        throw UsageError("--probe-rfe: expected an rfe index >= 0, got '" + text + "'");
      o.probe_rfes.push_back(static_cast<int>(k));
    } else if (arg == "--range-graph") {
      o.range_graph = takeValue();
      if (o.range_graph.empty()) throw UsageError("--range-graph: empty file name");
    } else if (arg == "--modes-csv") {
      o.modes_csv = takeValue();
      if (o.modes_csv.empty()) throw UsageError("--modes-csv: empty file name");
    } else if (arg == "--quiet" || arg == "-q") {
      noValue();
      o.quiet = true;
    } else {
      throw UsageError("unknown option '" + std::string(argv[i]) + "' (see --help)");
    }
  }
  if (!o.help && o.scene.empty()) throw UsageError("--scene FILE is required (see --help)");
  if (!o.modes_csv.empty() && o.modes == 0) throw UsageError("--modes-csv: needs --modes K");
  if (!o.probe_rfes.empty() && o.csv.empty()) throw UsageError("--probe-rfe: needs --csv FILE");
  return o;
}

}  // namespace cli
}  // namespace riser_sim
