// riser_sim_cli for a scene with space: spatial: the 3D run (riser_sim/spatial/run_builder.h), its CSV
// columns and summary keys in 3D, with the planar run's status, warning and exit-code logic.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "cli_options.h"
#include "riser_sim/scene.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace cli {

// t, x/y/z of the top and the end, the forces and the moments on the hang-off and on the anchor, then as
// the planar row; x/y/z_bottom (the anchor) when the bottom moves; then the probes.
std::string spatialCsvHeader(const std::vector<int>& probe_rfes = {}, bool bottom_moves = false, bool torsion = false);
// The row's values, in spatialCsvHeader()'s order; probes: x/y/z_rfeK (spring point) and tension_rfeK.
std::vector<double> spatialSample(spatial::SpatialRun& run, const std::vector<int>& probe_rfes);

// Runs the scene (loaded, --duration applied, --probe-rfe checked); returns the exit code.
int runSpatial(const Scene& scene, const CliOptions& opt);

}  // namespace cli
}  // namespace riser_sim
