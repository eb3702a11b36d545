#include "riser_sim/scene/scene_check.h"

#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {

std::optional<SetupError> checkScene(const Scene& scene) {
  if (const auto error = checkLineSections(scene)) return error;
  if (const auto error = checkSolverValues(scene.solver)) return error;
  if (scene.space == SpaceKind::kSpatial) {
    if (const auto issue = spatial::unsupported(scene)) return SetupError{issue->key, issue->message};
    return std::nullopt;
  }
  return planarUnsupported(scene.solver, scene.elements, scene.options.axial_flexibility);
}

}  // namespace riser_sim
