// One run of a scene over either engine: the planar Simulator (buildRun) or the 3D SpatialRun, chosen by
// scene.space, with one set of outputs in 3D. A planar scene's outputs are the 3D outputs in its plane:
// planar (x, y), y up, is 3D (x, 0, y), z up. The per-step calls (step(), outputs()) allocate nothing.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "riser_sim/force_noise.h"
#include "riser_sim/integrator.h"
#include "riser_sim/scene.h"
#include "riser_sim/types.h"

#include <Eigen/Core>

namespace riser_sim {

using Vec3 = Eigen::Vector3d;

// Every output of the current state, in 3D (z up), sized once per run.
struct RunOutputs {
  double t = 0.0;                                                 // [s]
  Vec3 top_point = Vec3::Zero(), end_point = Vec3::Zero();         // A_0, the end of rfe n [m]
  Vec3 top_force = Vec3::Zero(), bottom_force = Vec3::Zero();      // on the hang-off, on the anchor [N]
  Vec3 top_moment = Vec3::Zero(), bottom_moment = Vec3::Zero();    // through a flex joint (else 0) [N m]
  Vec3 bottom_point = Vec3::Zero();  // the pinned bottom's anchor (3D; moves with bottom.motion) [m]
  double top_twist = 0.0;            // line.torsion: the twisting moment the hang-off holds [N m]
  double top_tension = 0.0, max_tension = 0.0;                    // [N]
  double energy = 0.0, work = 0.0;                                // T + V, work fed in since t = 0 [J]
  double energy_drift = 0.0;         // (E - E0 - W) / max(|E0|, m g L)
  double constraint_error = 0.0;     // [m]
  AlignedVector<Vec3> springs;       // per rfe: the point of its axial spring [m]
  std::vector<double> axial_force;   // per rfe [N]
};

// What the run starts from.
struct StartReport {
  std::string about;                 // what the initial state is ("hanging equilibrium", ...)
  int statics_iterations = 0;
  double statics_residual = 0.0;     // relative to the total weight
  std::string statics_message;
  Vec3 end_force = Vec3::Zero();     // force at the end that holds the initial state [N]
  bool has_rest_acceleration = false;  // the engine checks the state's accelerations at rest (3D)
  double initial_acceleration = 0.0, initial_acceleration_bound = 0.0;  // [m/s^2]
  bool has_twist_moment = false;     // line.torsion
  double initial_twist_moment = 0.0, initial_twist_moment_bound = 0.0;  // [N m]
};

class LineRun {
 public:
  virtual ~LineRun() = default;
  virtual bool spatial() const = 0;
  // One step of solver.dt; false once diverged (divergenceReason() says why).
  virtual bool step() = 0;
  virtual double time() const = 0;
  virtual long steps() const = 0;
  virtual double dt() const = 0;
  virtual const std::string& divergenceReason() const = 0;
  // The outputs of the current state (filled in place).
  virtual const RunOutputs& outputs() = 0;

  // Health.
  virtual double maxConstraintError() const = 0;  // [m]
  virtual double energyDrift() = 0;
  virtual double energyScale() const = 0;         // m g L [J]
  virtual const ForceNoiseMonitor& forceNoise() const = 0;
  virtual std::string forceWarning(const ForceNoise& e) const = 0;
  virtual double stableStepEstimate() const = 0;  // [s]
  virtual double highestFrequency() const = 0;    // [rad/s]
  virtual bool explicitFixedStep() const = 0;
  virtual Integrator::Stats integratorStats() const = 0;

  const StartReport& start() const { return start_; }
  virtual bool bottomMoves() const { return false; }  // outputs().bottom_point moves
  virtual bool hasTorsion() const { return false; }   // outputs().top_twist
  // Flex joints: whether there is one at the top / bottom and the largest |moment| so far [N m].
  virtual bool hasTopFlexJoint() const { return false; }
  virtual bool hasBottomFlexJoint() const { return false; }
  virtual double maxTopMoment() const { return 0.0; }
  virtual double maxBottomMoment() const { return 0.0; }

 protected:
  StartReport start_;
};

// The run of the scene: buildRun (planar) or spatial::SpatialRun (space: spatial). Throws as they do
// (std::invalid_argument: what the engine cannot run; std::runtime_error: the initial state failed).
std::unique_ptr<LineRun> buildLineRun(const Scene& scene);

}  // namespace riser_sim
