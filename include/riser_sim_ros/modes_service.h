// ~modes: the modal analysis of a static state (riser_sim::computeModes) as a riser_sim/Modes response.
#pragma once
#include <string>

#include "riser_sim/Modes.h"
#include "riser_sim/kinematics.h"
#include "riser_sim/scene.h"

namespace riser_sim_ros {

// Modes of `scene` (top fixed at its hang-off) about the static state `kin` with `end_force` [N] kept as
// a dead load; for initial.type straight (not an equilibrium) about the hanging equilibrium instead.
// Builds its own model: the analysis sets up terms with run state (seabed anchors), so it must never
// share the running simulator's. count is checked (1..dofs); errors come back as success = false with
// the reason, e.g. "count: must be >= 1, got 0". Allocates; meant for a service thread.
void computeModesResponse(const riser_sim::Scene& scene, const riser_sim::Kinematics& kin,
                          const riser_sim::Vec2& end_force, int count, riser_sim::Modes::Response& res);

}  // namespace riser_sim_ros
