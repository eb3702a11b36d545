// The force terms a scene switches on, for both engines: one table whose rows name a term, say whether the
// scene wants it and add it to the planar Model and to the spatial::Model3. buildModel (scene.h) and
// buildModel3 (spatial/run_builder.h) walk it in order, so both engines hold their terms in the table's order.
#pragma once
#include <string>
#include <vector>

namespace riser_sim {

struct Scene;
class Model;
class WaterKinematics;
namespace spatial {
class Model3;
class Water3;
}  // namespace spatial

// How a model's terms differ from the run's, for the statics' and the modes' models (the one table builds them
// all; the planar engine takes steady_sea only).
struct TermOptions {
  // The sea without its waves: every term sees the water's steady part (the current, as at t = 0), as the statics
  // and the checks at rest do.
  bool steady_sea = false;
  // The Morison drag on the line held still in the water (V' = -V_water whatever its velocity): the current's
  // static load without the drag's damping, for the 3D relaxation (spatial/relaxation.h), where the damping would
  // only slow the creep to rest. The line's and each section's coefficients alike.
  bool drag_on_line_at_rest = false;
  // The seabed's tangential friction and damper (the line's and the attachments' contacts): they vanish at rest, so
  // the relaxation leaves them out (they would only slow its creep to rest).
  bool seabed_friction = true;
};

// A row adds its term(s) to a model (null: none in that engine). `water`: the model's one sea, built once by
// add*Terms (null without water); the terms copy it, so they share its wave samples (the waves are paid once
// per point and time, not once per term).
struct ForceTermRow {
  const char* name;                    // the term's name() (planar and spatial alike)
  bool (*wanted)(const Scene& scene);  // whether the scene switches the term on
  void (*planar)(const Scene& scene, const WaterKinematics* water, const TermOptions& options, Model& model);
  void (*spatial)(const Scene& scene, const spatial::Water3* water, const TermOptions& options, spatial::Model3& model);
};

// The rows in the order the terms enter the models.
const std::vector<ForceTermRow>& forceTermRegistry();

// Adds every wanted row's terms to the model.
void addPlanarTerms(const Scene& scene, Model& model, const TermOptions& options = TermOptions());
void addSpatialTerms(const Scene& scene, spatial::Model3& model, const TermOptions& options = TermOptions());

}  // namespace riser_sim
