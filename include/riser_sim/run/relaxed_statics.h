// A start the planar statics do not reach (a buoyant section or buoys whose continuations stall as touch-down
// contacts switch, or end on an unstable balance): the 3D relaxation (spatial/relaxation.h) from the planar first
// guess under every load at once, in the scene's vertical plane, then Newton in the planar coordinates from where
// it rests. One path for both engines: the 3D start uses the relaxation's state as it is.
#pragma once
#include <string>

#include "riser_sim/planar/statics.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim {

// The planar scene's equilibrium for `problem` (its model `model`) by the relaxation, then solveStaticsFrom;
// converged and checked as any statics, or not converged with the reason (a scene the 3D engine does not run
// names its key).
StaticsResult relaxedPlanarStatics(const Scene& scene, const Model& model, const StaticsProblem& problem);

}  // namespace riser_sim
