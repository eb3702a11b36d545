// The one check of a loaded scene's solver setup against its engine: the solver values (any engine),
// then what the scene's engine supports (planar: planarUnsupported, solver_setup.h; space: spatial:
// spatial::unsupported, spatial/run_builder.h). The loader throws its answer as a SceneError and the
// node as a parameter error, so a scene one runs the other runs too.
#pragma once
#include <optional>

#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/solver_setup.h"

namespace riser_sim {

// The first problem, naming its scene key (e.g. "solver.jacobian"), or none.
std::optional<SetupError> checkScene(const Scene& scene);

// The line's sections and stiffener (line.sections[k].EA, line.bend_stiffener.length, ...), part of checkScene.
std::optional<SetupError> checkLineSections(const Scene& scene);

}  // namespace riser_sim
