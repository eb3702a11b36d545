// riser_sim_cli --modes K [--modes-csv FILE], either engine: the scene's statics, then the lowest K natural
// modes about them (riser_sim/run/modes_report.h): the table on stdout, the mode shapes as CSV (planar: x, y with
// y up; space: spatial: x, y, z).
#pragma once
#include <string>

#include "riser_sim/scene/scene.h"

namespace riser_sim {
namespace cli {

// Returns the exit code (cli_options.h): 0 ok, 2 bad input (CSV cannot be opened, bad scene value, a 3D
// bottom that moves), 3 statics or the eigen-solve failed, 4 the table or the CSV could not be written.
int runModes(const Scene& scene, int count, const std::string& csv_path, bool quiet);

}  // namespace cli
}  // namespace riser_sim
