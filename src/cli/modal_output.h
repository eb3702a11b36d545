// riser_sim_cli --modes K [--modes-csv FILE]: statics of the scene's initial state, then the lowest K
// natural modes about it (table on stdout, mode shapes as CSV).
#pragma once
#include <string>

#include "riser_sim/scene.h"

namespace riser_sim {
namespace cli {

// Returns the exit code (cli_options.h): 0 ok, 2 bad input (CSV cannot be opened, bad scene value), 3 statics
// failed, 4 the table or the CSV could not be written.
int runModes(const Scene& scene, int count, const std::string& csv_path, bool quiet);

}  // namespace cli
}  // namespace riser_sim
