// One run of a scene over either engine: the planar Simulator (buildRun) or the 3D Run3, chosen by
// scene.space, with one set of outputs in 3D. A planar scene's outputs are the 3D outputs in its plane:
// planar (x, y), y up, is 3D (x, 0, y), z up. Its holders (the top, a pinned bottom) may be driven live from
// outside (LineRunInputs: the node's pose feeds). The per-step calls (step(), outputs(), addSample())
// allocate nothing.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "riser_sim/motion/external_motion.h"
#include "riser_sim/run/force_noise.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/planar/statics.h"
#include "riser_sim/types.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace riser_sim {

using Vec3 = Eigen::Vector3d;

// Every output of the current state, in 3D (z up), sized once per run.
struct RunOutputs {
  double t = 0.0;                                                // [s]
  Vec3 top_point = Vec3::Zero(), end_point = Vec3::Zero();       // A_0, the end of rfe n [m]
  Vec3 top_force = Vec3::Zero(), bottom_force = Vec3::Zero();    // on the hang-off, on the anchor [N]
  Vec3 top_moment = Vec3::Zero(), bottom_moment = Vec3::Zero();  // through a flex joint (else 0) [N m]
  Vec3 bottom_point = Vec3::Zero();             // the pinned bottom's anchor (3D; moves with bottom.motion) [m]
  double top_twist = 0.0;                       // line.torsion: the twisting moment the hang-off holds [N m]
  double top_tension = 0.0, max_tension = 0.0;  // [N]
  double energy = 0.0, work = 0.0;              // T + V, work fed in since t = 0 [J]
  double energy_drift = 0.0;                    // (E - E0 - W) / max(|E0|, m g L)
  double constraint_error = 0.0;                // [m]
  AlignedVector<Vec3> springs;                  // per rfe: the point of its axial spring [m]
  std::vector<double> axial_force;              // per rfe [N]
  double bottom_tension = 0.0;                  // axial force of the bottom rfe [N]

  // The line in full (n + 1 rfes, n joints), for the node's messages.
  AlignedVector<Vec3> points;  // A_0..A_n and the end of rfe n (n + 2) [m]
  // Per rfe: its frame, x along the rfe. Planar: the turn φ_i about -y (x towards z). 3D: the minimal-rotation
  // frames (rfe_frames.h: continuous in time and along the line), with line.torsion the material frames.
  std::vector<Eigen::Quaterniond> frames;
  std::vector<double> elongations;  // Δ_i per rfe [m]
  std::vector<double> arc_length;   // unstretched arc length from the top to the middle of rfe i [m]
  std::vector<double> angles;       // planar: φ_i per rfe [rad]; 3D: empty
  // Per joint i = 1..n (between rfe i - 1 and i): the bending moment vector (EI κ along e_{i-1} × e_i plus the
  // damper's; planar (0, -M_i, 0)) [N m], its size as the planar message has it (planar: M_i signed; 3D: its
  // norm) [N m], and the curvature |turn| / d [1/m].
  AlignedVector<Vec3> bending_moment_vector;
  std::vector<double> bending_moment;
  std::vector<double> curvature;
  // Per attachment (scene order, attachment.h): its centre [m] and the force on it, its weight included and its
  // inertia not [N]. Empty without attachments.
  AlignedVector<Vec3> attachment_points, attachment_forces;
};

// Every field of o is finite (what may be published).
bool allFinite(const RunOutputs& o);

// A holder driven from outside: where it starts and when.
struct HolderStart {
  Vec3 point = Vec3::Zero();                                     // [m]
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // planar: not used (the planar top is pinned)
  double t = 0.0;                                                // time of that pose on the run's clock [s]
};

// What a caller gives beyond the scene: live holders instead of the scene's motions.
struct LineRunInputs {
  std::optional<HolderStart> top;     // the top an external motion from here (planar: projected onto x-z)
  std::optional<HolderStart> bottom;  // a pinned bottom driven from outside (3D, bottom.type pinned)
  ExternalMotionOptions motion;       // the smoothing, prediction and gap rejoin of their samples
  StaticsProgress statics_progress;   // optional: the start's statics report their progress (statics.h)
};

enum class Holder { kTop, kBottom };

// What the run starts from.
struct StartReport {
  std::string about;        // what the initial state is ("hanging equilibrium", ...)
  bool equilibrium = true;  // false for initial.type straight
  int statics_iterations = 0;
  double statics_residual = 0.0;  // relative to the total weight
  std::string statics_message;
  Vec3 end_force = Vec3::Zero();       // force at the end that holds the initial state [N]
  bool has_rest_acceleration = false;  // the engine checks the state's accelerations at rest (3D)
  double initial_acceleration = 0.0, initial_acceleration_bound = 0.0;  // [m/s^2]
  bool has_twist_moment = false;                                        // line.torsion
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
  virtual double energyScale() const = 0;  // m g L [J]
  virtual const ForceNoiseMonitor& forceNoise() const = 0;
  virtual std::string forceWarning(const ForceNoise& e) const = 0;
  virtual double stableStepEstimate() const = 0;  // [s]
  // Empty, or why solver.dt is above the explicit scheme's estimated limit, with a safe step.
  virtual std::string stepAboveLimit() const = 0;
  virtual double highestFrequency() const = 0;  // [rad/s]
  virtual bool explicitFixedStep() const = 0;
  virtual Integrator::Stats integratorStats() const = 0;

  // Live holders (LineRunInputs). A pose sample stamped t_sample [s], applied at the run's time: false when
  // the holder's motion refused it or there is no live holder at that end.
  virtual bool addSample(Holder h, double t_sample, const Vec3& p, const Eigen::Quaterniond& q) = 0;
  // The holder restarts at rest at (p, q) at time t (after its feed's clock moved).
  virtual void restartHolder(Holder h, double t, const Vec3& p, const Eigen::Quaterniond& q) = 0;
  virtual void shiftSampleTimes(double dt) = 0;  // every live holder's sample times, by dt [s]
  virtual bool live(Holder h) const = 0;
  virtual MotionGaps gaps(Holder h) const = 0;  // of a live holder's samples (none: empty)

  const StartReport& start() const { return start_; }
  // The scene this run steps, its live holders fixed where they started: what its modes are about.
  const Scene& heldScene() const { return held_; }
  virtual bool bottomMoves() const { return false; }  // outputs().bottom_point moves
  virtual bool hasTorsion() const { return false; }   // outputs().top_twist
  // Flex joints: whether there is one at the top / bottom and the largest |moment| so far [N m].
  virtual bool hasTopFlexJoint() const { return false; }
  virtual bool hasBottomFlexJoint() const { return false; }
  virtual double maxTopMoment() const { return 0.0; }
  virtual double maxBottomMoment() const { return 0.0; }

 protected:
  StartReport start_;
  Scene held_;
};

// The run of the scene: buildRun (planar) or spatial::Run3 (space: spatial), with `inputs`' live
// holders. Throws as they do (std::invalid_argument: what the engine cannot run, e.g. a live bottom in a
// planar scene; std::runtime_error: the initial state failed).
std::unique_ptr<LineRun> buildLineRun(const Scene& scene, const LineRunInputs& inputs = {});

}  // namespace riser_sim
