// The two engines behind LineRun: the planar Simulator (its plane is 3D's x-z) and spatial::SpatialRun.
#include "riser_sim/line_run.h"

#include <cmath>

#include "riser_sim/run_builder.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {

namespace {

// Planar (x, y), y up -> 3D (x, 0, y), z up.
Vec3 inSpace(const Vec2& p) { return Vec3(p.x(), 0.0, p.y()); }

class PlanarLineRun : public LineRun {
 public:
  explicit PlanarLineRun(const Scene& scene) : run_(buildRun(scene)), sim_(*run_.sim) {
    const InitialState& init = run_.initial;
    start_.about = init.about;
    start_.statics_iterations = init.statics.iterations;
    start_.statics_residual = init.statics.residual;
    start_.statics_message = init.statics.message;
    start_.end_force = inSpace(init.statics.end_force);
    const int rfes = sim_.model().bodies();
    out_.springs.assign(rfes, Vec3::Zero());
    out_.axial_force.assign(rfes, 0.0);
  }
  bool spatial() const override { return false; }
  bool step() override { return sim_.step(); }
  double time() const override { return sim_.time(); }
  long steps() const override { return sim_.steps(); }
  double dt() const override { return sim_.dt(); }
  const std::string& divergenceReason() const override { return sim_.divergenceReason(); }
  const RunOutputs& outputs() override {
    const LineOutputs& o = sim_.outputs();
    out_.t = o.t;
    out_.top_point = inSpace(o.points.front());
    out_.end_point = inSpace(o.points.back());
    out_.top_force = inSpace(o.top_force);
    out_.bottom_force = inSpace(o.bottom_force);
    out_.top_tension = o.top_tension;
    out_.max_tension = o.max_tension;
    out_.energy = o.kinetic_energy + o.potential_energy;
    out_.work = o.work_in;
    out_.constraint_error = o.constraint_error;
    for (size_t k = 0; k < out_.springs.size(); ++k) {  // A_k + l1_k (cos φ_k, sin φ_k)
      const double l1 = sim_.model().rfe(static_cast<int>(k)).length1, phi = o.angles[k];
      out_.springs[k] = inSpace(o.points[k] + l1 * Vec2(std::cos(phi), std::sin(phi)));
      out_.axial_force[k] = o.axial_force[k];
    }
    out_.energy_drift = sim_.energyDrift();
    return out_;
  }
  double maxConstraintError() const override { return sim_.maxConstraintError(); }
  double energyDrift() override { return sim_.energyDrift(); }
  double energyScale() const override { return sim_.energyScale(); }
  const ForceNoiseMonitor& forceNoise() const override { return sim_.forceNoise(); }
  std::string forceWarning(const ForceNoise& e) const override { return sim_.forceWarning(e); }
  double stableStepEstimate() const override { return sim_.stableStepEstimate(); }
  double highestFrequency() const override { return sim_.highestFrequency(); }
  bool explicitFixedStep() const override { return sim_.integrator().explicitFixedStep(); }
  Integrator::Stats integratorStats() const override { return sim_.integrator().stats(); }

 private:
  Run run_;
  Simulator& sim_;
  RunOutputs out_;
};

class SpatialLineRun : public LineRun {
 public:
  explicit SpatialLineRun(const Scene& scene) : run_(scene) {
    const spatial::InitialState3& init = run_.initial();
    start_.about = init.about;
    start_.statics_iterations = init.statics.iterations;
    start_.statics_residual = init.statics.residual;
    start_.statics_message = init.statics.message;
    start_.end_force = init.end_force;
    start_.has_rest_acceleration = true;
    start_.initial_acceleration = init.max_acceleration;
    start_.initial_acceleration_bound = init.acceleration_bound;
    start_.has_twist_moment = scene.torsion.enabled;
    start_.initial_twist_moment = init.max_twist_moment;
    start_.initial_twist_moment_bound = init.twist_moment_bound;
  }
  bool spatial() const override { return true; }
  bool step() override { return run_.step(); }
  double time() const override { return run_.time(); }
  long steps() const override { return run_.steps(); }
  double dt() const override { return run_.dt(); }
  const std::string& divergenceReason() const override { return run_.divergenceReason(); }
  const RunOutputs& outputs() override {
    const spatial::LineOutputs3& o = run_.outputs();
    out_.t = o.t;
    out_.top_point = o.points.front();
    out_.end_point = o.points.back();
    out_.top_force = o.top_force;
    out_.bottom_force = o.bottom_force;
    out_.top_moment = o.top_moment;
    out_.bottom_moment = o.bottom_moment;
    out_.bottom_point = o.bottom_point;
    out_.top_twist = o.top_twist;
    out_.top_tension = o.top_tension;
    out_.max_tension = o.max_tension;
    out_.energy = o.kinetic_energy + o.potential_energy;
    out_.work = o.work_in;
    out_.constraint_error = o.constraint_error;
    out_.springs.resize(o.springs.size());  // the same size every call: allocates once
    out_.axial_force.resize(o.axial_force.size());
    for (size_t k = 0; k < o.springs.size(); ++k) out_.springs[k] = o.springs[k];
    for (size_t k = 0; k < o.axial_force.size(); ++k) out_.axial_force[k] = o.axial_force[k];
    out_.energy_drift = run_.energyDrift();
    return out_;
  }
  double maxConstraintError() const override { return run_.maxConstraintError(); }
  double energyDrift() override { return run_.energyDrift(); }
  double energyScale() const override { return run_.energyScale(); }
  const ForceNoiseMonitor& forceNoise() const override { return run_.forceNoise(); }
  std::string forceWarning(const ForceNoise& e) const override { return run_.forceWarning(e); }
  double stableStepEstimate() const override { return run_.stableStepEstimate(); }
  double highestFrequency() const override { return run_.highestFrequency(); }
  bool explicitFixedStep() const override { return run_.explicitFixedStep(); }
  Integrator::Stats integratorStats() const override { return run_.simulator().integrator().stats(); }
  bool bottomMoves() const override { return run_.bottomMoves(); }
  bool hasTorsion() const override { return run_.hasTorsion(); }
  bool hasTopFlexJoint() const override { return run_.topFlexJoint() != nullptr; }
  bool hasBottomFlexJoint() const override { return run_.bottomFlexJoint() != nullptr; }
  double maxTopMoment() const override { return run_.maxTopMoment(); }
  double maxBottomMoment() const override { return run_.maxBottomMoment(); }

 private:
  mutable spatial::SpatialRun run_;  // simulator() is non-const
  RunOutputs out_;
};

}  // namespace

std::unique_ptr<LineRun> buildLineRun(const Scene& scene) {
  if (scene.space == SpaceKind::kSpatial) return std::make_unique<SpatialLineRun>(scene);
  return std::make_unique<PlanarLineRun>(scene);
}

}  // namespace riser_sim
