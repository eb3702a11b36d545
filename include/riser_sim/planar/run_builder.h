// The one way a run is assembled from a scene, for the CLI, the node, the modal analysis and the
// benches: model (only the terms the scene lists) -> initial state at the hang-off (statics, or a
// straight line) -> the end load that state holds (initial.end_force: hold) -> simulator.
#pragma once
#include <memory>
#include <optional>

#include "riser_sim/scene/scene.h"

namespace riser_sim {

// The state a run starts from (or the modes are taken about), at rest.
struct InitialState {
  Kinematics kin;
  Vec2 end_force = Vec2::Zero();  // force [N] at the line's end that holds kin (statics' end force)
  bool equilibrium = true;        // false for initial.type straight
  std::string about;              // what kin is, for messages ("hanging equilibrium", ...)
  StaticsResult statics;          // what the statics reported (empty when there were none)
};

// What a caller supplies beyond the scene.
struct RunInputs {
  std::optional<Vec2> top;            // A_0 at t = 0 [m] (the node: hang-off from the vessel pose);
                                      // default: the scene's top motion at t = 0
  std::unique_ptr<TopMotion> motion;  // default: the scene's top.motion
  StaticsProgress statics_progress;   // optional: the statics report their progress
};

struct Run {
  std::shared_ptr<Model> model;  // the scene's terms + the held end load
  InitialState initial;
  std::unique_ptr<Simulator> sim;
};

// The scene's initial state with A_0 at top, for the scene's model. equilibrium_only: an
// initial.type straight scene gets its hanging equilibrium instead (the modal analysis).
// Throws std::runtime_error("initial: ...") when the statics fail.
// progress: the statics' progress report (optional).
InitialState solveInitialState(const Scene& scene, const Model& model, const Vec2& top, bool equilibrium_only = false,
                               const StaticsProgress& progress = {});

// Model, initial state, simulator: ready to step. Throws std::invalid_argument ("key: message") for a
// setup the loader let through, std::runtime_error when the statics fail or the start is not finite.
Run buildRun(const Scene& scene, RunInputs inputs = {});

// buildRun(scene).sim, with the statics' report (tests and tools that need only the simulator).
std::unique_ptr<Simulator> buildSimulator(const Scene& scene, StaticsResult* statics = nullptr);

}  // namespace riser_sim
