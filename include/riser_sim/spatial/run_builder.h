// A 3D run from a scene with `space: spatial` (docs/spatial.md, "Running a 3D scene"): the spatial model
// (only the terms the scene lists), the top motion in 3D, the initial state and a Simulator3,
// watched for divergence and energy balance as the planar Simulator is. What the 3D core cannot run yet
// is refused naming the section (unsupported()), never dropped.
//
// Statics: hanging, between two points and end displaced under a horizontal force are planar in the
// vertical plane through the top and the end. They are solved by the planar statics on a planar Scene
// built from the rotated data and rotated into 3D (exact); the builder checks that the problem is
// planar in that plane and that the rotated state is an equilibrium of the 3D model (its accelerations
// at rest, initialAccelerationBound()).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "riser_sim/run/force_noise.h"
#include "riser_sim/run/build_options.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/simulator.h"

namespace riser_sim {
namespace spatial {

// A key and why the 3D path cannot run it.
struct SceneIssue {
  std::string key, message;
};
// The first thing of a spatial scene the 3D core does not have yet (added mass, internal flow, the chain
// formulations, dense Jacobians beyond kMaxDenseElements3).
std::optional<SceneIssue> unsupported(const Scene& scene);
// Implicit schemes with solver.jacobian dense run a p x p Jacobian in 3D, p = 7(n + 1): n <= 570 keeps
// p <= 4000 (the structured solves, auto, have no such limit).
constexpr int kMaxDenseElements3 = 570;

// p(t) = position + amplitude ∘ cos(2π t / period + phase), per axis (phase per axis: a horizontal
// circle is amplitude [R, R, 0], phase [0, -π/2, 0]). With an attitude, the holder also rolls, pitches and
// yaws: (φ, θ, ψ) = attitude ∘ cos(2π t / period + attitude_phase) [rad], R = Rz(ψ) Ry(θ) Rx(φ).
class SinusoidMotion3 : public TopMotion3 {
 public:
  SinusoidMotion3(const Vec3& center, const Vec3& amplitude, double period, const Vec3& phase,
                  const Vec3& attitude = Vec3::Zero(), const Vec3& attitude_phase = Vec3::Zero())
      : center_(center),
        amp_(amplitude),
        omega_(2.0 * M_PI / period),
        phase_(phase),
        att_(attitude),
        att_phase_(attitude_phase) {}
  PointMotion3 at(double t) const override;
  bool rotates() const override { return !att_.isZero(); }

 private:
  Vec3 center_, amp_;
  double omega_;
  Vec3 phase_, att_, att_phase_;
};

// Velocity piecewise linear between knots (the planar VelocityProfileMotion on (x, z) and on y).
class VelocityProfileMotion3 : public TopMotion3 {
 public:
  VelocityProfileMotion3(const Vec3& start, const std::vector<TopMotionSpec::Knot>& knots);
  PointMotion3 at(double t) const override;

 private:
  std::unique_ptr<TopMotion> xz_, y_;
};

// top.motion (or bottom.motion, the same keys) in 3D; external is held at spec.position (the CLI has no feed).
std::unique_ptr<TopMotion3> buildTopMotion3(const TopMotionSpec& spec);
// The scene's line in 3D: gravity (0, 0, -g), the terms the scene lists (force_registry.h), the end mass, the spins
// and bending axes, the bottom free or pinned at bottom.position, and what `options` add (build_options.h: the
// terms' variants, the end held elsewhere or driven, an end load, the relaxation's damping). Run3 then adds the flex
// joints, whose default axes come from the initial state. Throws std::invalid_argument for an end load on a pinned
// end.
std::shared_ptr<Model3> buildModel3(const Scene& scene, const BuildOptions& options = BuildOptions());

struct InitialState3 {
  Kinematics3 kin;                // at rest
  Vec3 end_force = Vec3::Zero();  // force [N] at the end that holds kin (displaced; the anchor's for pinned)
  bool equilibrium = true;        // false for initial.type straight
  std::string about;
  StaticsResult statics;                 // of the planar problem (kin in its plane)
  Vec3 plane_direction = Vec3::UnitX();  // horizontal unit vector of the statics' plane
  double max_acceleration = 0.0;         // largest |acceleration| of a joint or the end at rest [m/s^2]
  double acceleration_bound = 0.0;
  // Torsion on: the largest |moment about e_i| on a free spin at rest [N m] and its bound; with bending axes
  // (line.EI: [EI_1, EI_2]) bent between them, each rfe's material axis 1 (the spins; empty: untwisted).
  double max_twist_moment = 0.0;
  double twist_moment_bound = 0.0;
  AlignedVector<Vec3> material_axes;
  HangOff hang_off;  // then also the hang-off's twist frame the statics held (Simulator3::reset)
};

// The initial state (initial_state.cpp). The model its checks at rest see: the scene's terms in its steady sea (the
// statics never see the waves), the end held as the start holds it: a pinned end where kin ends, a free one
// under end_force [N] (a dead load).
std::shared_ptr<Model3> restModel3(const Scene& scene, const Kinematics3& kin, const Vec3& end_force);
// Throws std::runtime_error("initial: ... fails the check stability: ...") unless the equilibrium init.kin (its end
// force, spins and hang-off frame) has no growing mode in the scene's still water (stability3, statics.h);
// held_end: a displaced free end held horizontally where it is.
void checkStable(const Scene& scene, const InitialState3& init, bool held_end);
// Largest |acceleration| [m/s^2] of A_0..A_n and of the end of the model `rest` (restModel3) in the state kin at
// rest (velocities ignored), with A_0 at top; `where` gets the rfe. ~0 for an equilibrium: solveInitialState3's
// check. With the spins (torsion on): the material axes 1 per rfe (empty: untwisted; a held rfe 0 has the hang-off's
// frame made at kin); `moment` gets the largest |moment about e_i| on a free spin [N m], `moment_where` its rfe.
// `stabilization`: solver.stabilization (the constraints' Baumgarte terms).
double restAcceleration(const Model3& rest, double stabilization, const Kinematics3& kin, const Vec3& top,
                        const AlignedVector<Vec3>& material_axes, int& where, double& moment, int& moment_where,
                        const HangOff& hang_off = HangOff());
// The same for the scene's restModel3 with end_force [N], untwisted.
double restAcceleration(const Scene& scene, const Kinematics3& kin, const Vec3& end_force, const Vec3& top, int& where);

// The scene's initial state with A_0 at top. Throws std::runtime_error("initial: ...") when the statics
// fail, the problem is not planar, or the rotated state is not an equilibrium of the 3D model.
InitialState3 solveInitialState3(const Scene& scene, const Vec3& top, const StaticsProgress& progress = {});

// The scene's flex joints (top.flex_joint, bottom.flex_joint) added to model, their axes given or along the
// line in `initial` at t = 0 (then unloaded) and turning with their holder's motion when it rotates()
// (nullptr or not rotating: fixed in the world); `loaded` names those that start turned ("top.flex_joint
// turned 0.1 rad").
struct FlexJoints3 {
  const FlexJoint* top = nullptr;
  const FlexJoint* bottom = nullptr;
  std::string loaded;
};
FlexJoints3 addFlexJoints(const Scene& scene, const Kinematics3& initial, Model3& model,
                          const std::shared_ptr<const TopMotion3>& top_holder = nullptr,
                          const std::shared_ptr<const TopMotion3>& bottom_holder = nullptr);

// Every output of the current state.
struct LineOutputs3 {
  double t = 0.0;
  AlignedVector<Vec3> points;        // A_0..A_n and the end [m]
  AlignedVector<Vec3> springs;       // A_i + l1_i e_i: the point of rfe i's axial spring [m]
  std::vector<double> axial_force;   // per rfe [N]
  Vec3 top_force = Vec3::Zero();     // force the line exerts on the hang-off [N]
  Vec3 bottom_force = Vec3::Zero();  // on the anchor (pinned; 0 when free) [N]
  // Moment the line exerts on the hang-off / the anchor through a flex joint [N m] (0 when pinned or free:
  // the force acts at the joint's point); at the top with line.torsion, plus the twist the hang-off holds.
  Vec3 top_moment = Vec3::Zero(), bottom_moment = Vec3::Zero();
  // line.torsion: the twisting moment the hang-off holds about its axis [N m] (in top_moment too; 0 when free).
  double top_twist = 0.0;
  Vec3 bottom_point = Vec3::Zero();             // the pinned bottom's anchor p_b(t) [m] (moves with bottom.motion)
  double top_tension = 0.0, max_tension = 0.0;  // [N]
  double kinetic_energy = 0.0, potential_energy = 0.0, work_in = 0.0;  // [J]
  double constraint_error = 0.0;                                       // [m]
};

// What a caller gives instead of the scene's top (as the planar RunInputs): the node's vessel feed.
// bottom_motion: a pinned bottom driven from outside (the node's second pose feed, e.g. an ROV); the
// statics end at its position at t = 0, the path is not shifted by the statics' gap (within
// initial.tolerance). Default: buildTopMotion3(scene.bottom_motion).
struct RunInputs3 {
  std::optional<Vec3> top;                          // A_0 at t = 0 [m]; default: motion's at t = 0
  std::unique_ptr<TopMotion3> motion;               // default: buildTopMotion3(scene.top)
  std::shared_ptr<const TopMotion3> bottom_motion;  // needs bottom.type: pinned
  StaticsProgress statics_progress;                 // optional: the planar statics report their progress
};

class Run3 {
 public:
  // Throws std::invalid_argument("key: ...") for what the 3D core cannot run, std::runtime_error
  // ("initial: ...") when the initial state fails.
  explicit Run3(const Scene& scene, RunInputs3 inputs = {});

  // One step of solver.dt; false once diverged (divergenceReason() names the cause and solver.dt).
  bool step();
  double time() const { return sim_->time(); }
  long steps() const { return steps_; }
  double dt() const { return dt_; }
  bool diverged() const { return !reason_.empty(); }
  const std::string& divergenceReason() const { return reason_; }
  // (E - E0 - W) / max(|E0|, m g L), as the planar Simulator::energyDrift.
  double energyDrift();
  double energyScale() const { return energy_scale_; }  // m g L [J]
  double maxConstraintError() const { return max_constraint_error_; }
  // Largest |moment| of the top / bottom flex joint over every step so far, t = 0 included [N m] (0 without).
  double maxTopMoment() const { return max_moment_[0]; }
  double maxBottomMoment() const { return max_moment_[1]; }
  const LineOutputs3& outputs();

  // Stability of the explicit schemes, estimated at the initial state (Simulator3::estimateStability,
  // docs/spatial.md "Stability"): ω_max [rad/s] and the largest stable step of solver.integrator when it is
  // an explicit fixed-step scheme (rk4's otherwise, for reference) [s].
  double highestFrequency() const { return sim_->highestFrequency(); }
  double stableStepEstimate() const { return sim_->stableStepEstimate(); }
  bool explicitFixedStep() const { return sim_->integrator().explicitFixedStep(); }
  // Empty, or why solver.dt is above the explicit scheme's estimated limit, with a safe step.
  std::string stepAboveLimit() const;
  // Step-to-step noise in the top tension and the largest axial force (force_noise.h), as the planar
  // Simulator::forceNoise(); forceWarning(): empty, or why they are not resolved and what resolves them.
  const ForceNoiseMonitor& forceNoise() const { return noise_; }
  std::string forceWarning(const ForceNoise& e) const;

  const Model3& model() const { return *model_; }
  const InitialState3& initial() const { return initial_; }
  bool bottomMoves() const { return model_->bottomMoves(); }
  bool hasTorsion() const { return model_->hasTorsion(); }
  const FlexJoint* topFlexJoint() const { return top_joint_; }  // nullptr: pinned (free rotation)
  const FlexJoint* bottomFlexJoint() const { return bottom_joint_; }
  Simulator3& simulator() { return *sim_; }

 private:
  void trackMoments();
  void sampleForces();
  std::shared_ptr<Model3> model_;
  InitialState3 initial_;
  const FlexJoint* top_joint_ = nullptr;
  const FlexJoint* bottom_joint_ = nullptr;
  std::unique_ptr<Simulator3> sim_;
  IntegratorKind integrator_kind_;
  double rho_inf_;
  ForceNoiseMonitor noise_;
  double dt_, max_gap_, e0_ = 0.0, energy_scale_ = 1.0, max_constraint_error_ = 0.0;
  long steps_ = 0;
  std::string reason_;
  double max_moment_[2] = {0.0, 0.0};
  Kinematics3 ends_;  // the end rfes' kinematics for trackMoments()
  LineOutputs3 out_;
};

}  // namespace spatial
}  // namespace riser_sim
