// What a model holds beyond the scene's force terms: the terms' variants and the end conditions. The run's model,
// the statics' and rest checks' models and the relaxation's all come from the one builder of each engine
// (buildModel, scene.h; spatial::buildModel3, spatial/run_builder.h) with these options; nothing edits a scene
// copy to get a variant, and nothing adds a term to a model after its builder returns it.
#pragma once
#include <memory>
#include <optional>

#include <Eigen/Core>

#include "riser_sim/run/force_registry.h"

namespace riser_sim {

namespace spatial {
class TopMotion3;
}  // namespace spatial

struct BuildOptions {
  TermOptions terms;  // the terms' variants (force_registry.h)
  // The spins (line.torsion, 3D only): as the scene says; off (the shape relaxes first without them); or the
  // relaxation's inertias (no end body's, the line's at most a solid rod's m D^2/8: its rest does not depend on them).
  enum class Spins { kScene, kOff, kRelaxation };
  Spins spins = Spins::kScene;
  // A pinned bottom held at this point [m] (the start's end) instead of bottom.position; or moving along
  // bottom_motion (3D only: a driven anchor).
  std::optional<Eigen::Vector3d> pinned_at;
  std::shared_ptr<const spatial::TopMotion3> bottom_motion;
  // A constant force on a free end [N] (EndLoad: initial.end_force hold, or the statics' end force as a dead load);
  // planar: its x and z. A pinned end takes none (its anchor holds it).
  Eigen::Vector3d end_force = Eigen::Vector3d::Zero();
  // Mass-proportional damping Q = -α M q' [1/s] (3D only: the dynamic relaxation, spatial/relaxation.h).
  double mass_damping = 0.0;
};

}  // namespace riser_sim
