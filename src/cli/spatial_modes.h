// riser_sim_cli --modes K [--modes-csv FILE] for a scene with space: spatial: the 3D modes
// (riser_sim/spatial/modal.h) about the scene's static state, in the planar --modes table and CSV format
// with the character of each mode: in-plane, out-of-plane (of the statics' vertical plane) or axial.
#pragma once
#include <string>

#include "riser_sim/scene.h"

namespace riser_sim {
namespace cli {

// Exit codes as runModes (modal_output.h): 2 bad input (pinned bottom, CSV path), 3 statics or the
// equilibrium failed, 4 write failed.
int runSpatialModes(const Scene& scene, int count, const std::string& csv_path, bool quiet);

}  // namespace cli
}  // namespace riser_sim
