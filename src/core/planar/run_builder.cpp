#include "riser_sim/planar/run_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "riser_sim/run/initial_velocity.h"
#include "riser_sim/run/relaxed_statics.h"

namespace riser_sim {

InitialState solveInitialState(const Scene& scene, const Model& model, const Vec2& top, bool equilibrium_only,
                               const StaticsProgress& progress) {
  InitialState init;
  const bool straight = scene.initial.type == InitialKind::kStraight;
  if (straight && !equilibrium_only) {
    init.kin = straightLine(model, top, scene.initial.angle);
    // Not an equilibrium, but it must not start inside the seabed (the contact springs would throw it out).
    double level = -INFINITY;
    for (const auto& term : model.terms()) level = std::max(level, term->seabedLevel());
    const double sink = restingSinkAllowance(scene.seabed, model.totalMass() * model.gravity());
    for (size_t i = 0; i < init.kin.size(); ++i) {
      const Vec2 end = init.kin[i].end();
      if (end.y() < level - sink)
        throw std::runtime_error("initial: the straight line reaches y = " + std::to_string(end.y()) +
                                 " m at the end of rfe " + std::to_string(i) + ", below the seabed (seabed.level = " +
                                 std::to_string(level) + " m); use initial.type hanging or change initial.angle");
    }
    init.equilibrium = false;
    init.about = "straight line (not an equilibrium)";
    init.statics.converged = true;
    init.statics.kin = init.kin;
    init.statics.message = init.about;
    return init;
  }
  StaticsProblem problem = staticsProblem(scene);
  problem.top = top;
  problem.progress = progress;
  if (straight) problem.kind = StaticsProblem::Kind::kHanging;  // the modes of a straight start
  init.statics = solveStatics(model, problem, 0.0);
  if (relaxationMayReach(problem, init.statics)) {  // where the continuations stop: relaxed_statics.h
    const StaticsResult relaxed = relaxedPlanarStatics(scene, model, problem);
    if (relaxed.converged)
      init.statics = relaxed;
    else
      init.statics.message += "; " + relaxed.message;
  }
  if (!init.statics.converged) throw std::runtime_error("initial: " + init.statics.message);
  init.kin = init.statics.kin;
  init.end_force = init.statics.end_force;
  init.about = straight ? "hanging equilibrium (initial.type straight is none)"
                        : std::string(name(scene.initial.type)) + " equilibrium";
  if (straight) init.statics.message = init.about + "; " + init.statics.message;
  return init;
}

Run buildRun(const Scene& scene, RunInputs inputs) {
  // A 3D scene run planar would drop its y components: spatial::Run3 builds it.
  if (scene.space != SpaceKind::kPlanar)
    throw std::invalid_argument(
        "space: 'spatial' scenes run through the 3D core (riser_sim/spatial/run_builder.h), "
        "not the planar builder");
  Run run;
  run.model = buildModel(scene);
  if (!inputs.motion) inputs.motion = runTopMotion(scene);  // a fixed top carried by initial.velocity moves
  const Vec2 top = inputs.top ? *inputs.top : inputs.motion->at(0.0).p;
  run.initial = solveInitialState(scene, *run.model, top, false, inputs.statics_progress);
  // The statics' end force stays on as a constant end load, so the start is an exact equilibrium: the run's model is
  // then the statics' with that load.
  if (scene.initial.type == InitialKind::kDisplaced && scene.initial.end_force == EndForceKind::kHold) {
    BuildOptions hold;
    hold.end_force = inSpace(run.initial.end_force);
    run.model = buildModel(scene, hold);
  }
  run.sim = std::make_unique<Simulator>(run.model, std::move(inputs.motion), scene.solver);
  // A pinned bottom that the statics did not place is held where the initial state puts it.
  // initial.velocity: the rigid motion's velocities on the start (run.initial.kin stays at rest, for the modes).
  run.sim->setInitialState(withInitialVelocity(scene.initial, run.initial.kin), 0.0);
  if (scene.initial.has_velocity) {
    run.initial.equilibrium = false;
    run.initial.about += initialVelocityAbout(scene.initial);
  }
  // Values within the loader's limits can still combine into forces beyond double range (an extreme
  // sinusoid, stabilisation or drag): such a run never starts, so nothing non-finite is published.
  if (!run.sim->state().allFinite() || !allFinite(run.sim->outputs()))
    throw std::runtime_error(
        "initial: the initial state or its forces are not finite (NaN/Inf): the scene's values "
        "combine beyond double range");
  return run;
}

std::unique_ptr<Simulator> buildSimulator(const Scene& scene, StaticsResult* statics) {
  Run run = buildRun(scene);
  if (statics) *statics = run.initial.statics;
  return std::move(run.sim);
}

}  // namespace riser_sim
