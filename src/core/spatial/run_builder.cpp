#include "riser_sim/spatial/run_builder.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "riser_sim/run/force_registry.h"
#include "riser_sim/run/initial_velocity.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/forces/attachments.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/buoyancy.h"
#include "riser_sim/spatial/forces/added_mass.h"
#include "riser_sim/spatial/forces/end_load.h"
#include "riser_sim/spatial/forces/froude_krylov.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/forces/mass_damping.h"
#include "riser_sim/spatial/forces/morison_drag.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/run/stability_estimate.h"

namespace riser_sim {
namespace spatial {

namespace {

// Divergence by unresolved motion, as the planar Simulator: an rfe turning by more than 0.5 rad or
// stretching by more than 10 % of its length in one step.
constexpr double kMaxTurnPerStep = 0.5;
constexpr double kMaxStretchPerStep = 0.1;

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

// Axial force in rfe r [N]: its spring (extensible), else the tension at A_i from the joint reaction.
double axialForce(const Rfe& r, const BodyKinematics3& b, const Vec3& joint_reaction, bool extensible) {
  return extensible ? r.axial_stiffness * b.delta + r.axial_damping * b.delta_dot : joint_reaction.dot(b.e);
}

bool implicitScheme(IntegratorKind k) {
  return k == IntegratorKind::kRosenbrock2 || k == IntegratorKind::kMidpoint || k == IntegratorKind::kGeneralizedAlpha;
}

}  // namespace

std::optional<SceneIssue> unsupported(const Scene& s) {
  const std::string yet = "not available with space: spatial yet";
  if (s.seabed.enabled && s.seabed.stiffness_tangential > 0.0)
    return SceneIssue{"seabed.stiffness_tangential",
                      "anchored tangential springs are " + yet +
                          " (the 3D seabed has Coulomb friction: friction_axial, friction_lateral)"};
  const InternalFlowSpec& f = s.internal_fluid;
  if (f.density > 0.0 && (f.velocity != 0.0 || f.acceleration != 0.0))
    return SceneIssue{"internal_fluid", "a flow (velocity or acceleration != 0) is " + yet +
                                            " (contents at rest are: their mass moves with the pipe)"};
  if (s.solver.formulation != FormulationKind::kAbsolute)
    return SceneIssue{"solver.formulation", "'" + std::string(name(s.solver.formulation)) +
                                                "' is planar; space: spatial runs natural (director) coordinates, "
                                                "the 3D counterpart of 'absolute' (remove the key or set absolute)"};
  if (implicitScheme(s.solver.integrator) && s.solver.jacobian == JacobianKind::kDense &&
      s.elements > kMaxDenseElements3)
    return SceneIssue{"line.elements",
                      "must be <= " + std::to_string(kMaxDenseElements3) + " with a dense " +
                          name(s.solver.integrator) + " Jacobian and space: spatial, got " +
                          std::to_string(s.elements) +
                          " (7(n + 1) coordinates); use solver.jacobian auto (structured O(n) solves)"};
  return std::nullopt;
}

PointMotion3 SinusoidMotion3::at(double t) const {
  PointMotion3 m;
  for (int k = 0; k < 3; ++k) {
    const double arg = omega_ * t + phase_[k];
    const double c = std::cos(arg), s = std::sin(arg);
    m.p[k] = center_[k] + amp_[k] * c;
    m.v[k] = -amp_[k] * omega_ * s;
    m.a[k] = -amp_[k] * omega_ * omega_ * c;
  }
  if (!rotates()) return m;
  Vec3 ang, rate;
  for (int k = 0; k < 3; ++k) {
    const double arg = omega_ * t + att_phase_[k];
    ang[k] = att_[k] * std::cos(arg);
    rate[k] = -att_[k] * omega_ * std::sin(arg);
  }
  setAttitudeZYX(ang, rate, m);
  return m;
}

VelocityProfileMotion3::VelocityProfileMotion3(const Vec3& start, const std::vector<TopMotionSpec::Knot>& knots) {
  std::vector<VelocityProfileMotion::Knot> xz, y;
  for (const auto& k : knots) {
    xz.push_back({k.t, Vec2(k.v.x(), k.v.z())});
    y.push_back({k.t, Vec2(k.v.y(), 0.0)});
  }
  xz_ = std::make_unique<VelocityProfileMotion>(Vec2(start.x(), start.z()), xz);
  y_ = std::make_unique<VelocityProfileMotion>(Vec2(start.y(), 0.0), y);
}

PointMotion3 VelocityProfileMotion3::at(double t) const {
  const PointMotion a = xz_->at(t), b = y_->at(t);
  return PointMotion3{Vec3(a.p.x(), b.p.x(), a.p.y()), Vec3(a.v.x(), b.v.x(), a.v.y()),
                      Vec3(a.a.x(), b.a.x(), a.a.y())};
}

std::unique_ptr<TopMotion3> buildTopMotion3(const TopMotionSpec& spec) {
  switch (spec.type) {
    case MotionKind::kFixed:
    case MotionKind::kExternal: return std::make_unique<FixedMotion3>(spec.position);
    case MotionKind::kSinusoid:
      if (!(spec.period > 0.0)) throw std::invalid_argument("top.motion.period: must be > 0");
      return std::make_unique<SinusoidMotion3>(spec.position, spec.amplitude, spec.period, spec.phase, spec.attitude,
                                               spec.attitude_phase);
    case MotionKind::kVelocityProfile: return std::make_unique<VelocityProfileMotion3>(spec.position, spec.knots);
  }
  throw std::invalid_argument("top.motion.type: unknown motion (accepted: " + choiceNames<MotionKind>() + ")");
}

std::shared_ptr<Model3> buildModel3(const Scene& scene, const BuildOptions& options) {
  const bool pinned = scene.bottom == BottomBoundary::kPinned;
  if (options.end_force.squaredNorm() > 0.0 && pinned)
    throw std::invalid_argument("buildModel3: an end load on a pinned end (its anchor holds it)");
  if ((options.pinned_at || options.bottom_motion) && !pinned)
    throw std::invalid_argument("buildModel3: a pinned or driven anchor for a free end (bottom.type: free)");
  auto model = std::make_shared<Model3>(lineSections(scene), scene.stiffeners, scene.options, scene.end_mass,
                                        Vec3(0.0, 0.0, -scene.gravity));
  model->setBottom(scene.bottom, options.pinned_at ? *options.pinned_at : scene.bottom_point);
  if (options.bottom_motion) model->setBottomMotion(options.bottom_motion);
  // Only the terms the scene needs: the registry's rows (as the planar buildModel).
  addSpatialTerms(scene, *model, options.terms);
  if (scene.torsion.enabled && options.spins != BuildOptions::Spins::kOff) {
    const TorsionSpec& t = scene.torsion;
    TorsionProperties p{t.stiffness,
                        t.polar_inertia,
                        t.damping,
                        t.end_polar_inertia,
                        t.free_top,
                        scene.top_flex_joint.torsional_stiffness,
                        scene.top_flex_joint.torsional_damping};
    if (options.spins == BuildOptions::Spins::kRelaxation) {
      const double D = scene.line.outer_diameter;
      p.end_polar_inertia = 0.0;
      if (D > 0.0) p.polar_inertia = std::min(p.polar_inertia, scene.line.mass_per_length * D * D / 8.0);
    }
    model->setTorsion(p);
  }
  if (scene.bending_axes.enabled)
    model->setBendingAxes(scene.bending_axes.EI1, scene.bending_axes.EI2, scene.bending_axes.axis);
  if (options.end_force.squaredNorm() > 0.0) model->addTerm(std::make_unique<EndLoad>(options.end_force));
  if (options.mass_damping > 0.0) model->addTerm(std::make_unique<MassDamping>(options.mass_damping));
  return model;
}

Run3::Run3(const Scene& scene, RunInputs3 inputs)
    : integrator_kind_(scene.solver.integrator),
      rho_inf_(scene.solver.rho_inf),
      dt_(scene.solver.dt),
      max_gap_(scene.solver.max_constraint_error * scene.length / scene.elements) {
  if (scene.space != SpaceKind::kSpatial) throw std::invalid_argument("space: Run3 needs space: spatial");
  if (const auto issue = unsupported(scene)) throw std::invalid_argument(issue->key + ": " + issue->message);
  std::shared_ptr<const TopMotion3> motion = inputs.motion ? std::move(inputs.motion) : runTopMotion3(scene);
  const Vec3 top = inputs.top ? *inputs.top : motion->at(0.0).p;
  // The statics end at the bottom's position at t = 0 (bottom.motion's, which may differ from bottom.position).
  Scene at0 = scene;
  const bool pinned = scene.bottom == BottomBoundary::kPinned;
  if (inputs.bottom_motion && !pinned)
    throw std::invalid_argument("bottom.motion: a driven bottom needs bottom.type: pinned");
  if (pinned)
    at0.bottom_point =
        inputs.bottom_motion ? inputs.bottom_motion->at(0.0).p : buildTopMotion3(scene.bottom_motion)->at(0.0).p;
  initial_ = solveInitialState3(at0, top, inputs.statics_progress);
  // The run's model, built once the start is known. A pinned end is held where the statics put it: within
  // initial.tolerance x line.length of bottom.position (their end condition), so the run starts without a
  // Baumgarte kick from that gap; a moving bottom's path is shifted by that gap for the same reason. The statics'
  // end force stays on as a constant end load (hold), so the start is an exact equilibrium.
  BuildOptions run_options;
  if (pinned) {
    const Vec3 gap = initial_.kin.back().end() - at0.bottom_point;
    const MotionKind type = scene.bottom_motion.type;
    if (inputs.bottom_motion) {
      run_options.bottom_motion = inputs.bottom_motion;
    } else if (type == MotionKind::kSinusoid || type == MotionKind::kVelocityProfile) {
      TopMotionSpec spec = scene.bottom_motion;
      spec.position += gap;
      run_options.bottom_motion = buildTopMotion3(spec);
    } else {
      run_options.pinned_at = initial_.kin.back().end();
    }
  }
  if (scene.initial.type == InitialKind::kDisplaced && scene.initial.end_force == EndForceKind::kHold)
    run_options.end_force = initial_.end_force;
  model_ = buildModel3(scene, run_options);
  // A loaded joint at t = 0 makes the start no equilibrium (the statics pin the ends): said in initial().about.
  const FlexJoints3 joints = addFlexJoints(scene, initial_.kin, *model_, motion, model_->bottomMotion());
  top_joint_ = joints.top;
  bottom_joint_ = joints.bottom;
  if (!joints.loaded.empty()) {
    initial_.equilibrium = false;
    initial_.about += "; not an equilibrium with the flex joints, which start loaded (" + joints.loaded +
                      " from their axis; the statics pin the ends)";
  }
  // A holder already turning at t = 0 (an attitude's phase, a vessel turning when the node starts) drags a line
  // at rest through the dampers it carries: the joint's, and the twist's with line.torsion held at the top.
  const TorsionProperties& tp = model_->torsion();
  const bool twist_damped = model_->hasTorsion() && !tp.free_top && (tp.damping > 0.0 || tp.top_damping > 0.0);
  const auto turning = [](const std::shared_ptr<const TopMotion3>& m) {
    return m && m->rotates() ? m->at(0.0).w.norm() : 0.0;
  };
  const double w_top = turning(motion), w_bottom = turning(model_->bottomMotion());
  if ((w_top > 0.0 && ((top_joint_ && scene.top_flex_joint.damping > 0.0) || twist_damped)) ||
      (w_bottom > 0.0 && bottom_joint_ && scene.bottom_flex_joint.damping > 0.0)) {
    initial_.equilibrium = false;
    initial_.about += "; not an equilibrium: a holder turns at t = 0 (top " + fmt(w_top) + ", bottom " + fmt(w_bottom) +
                      " rad/s) and its dampers load the line at rest";
  }
  IntegratorOptions io;
  io.tolerance = scene.solver.tolerance;
  io.jacobian_interval = scene.solver.jacobian_interval;
  // auto: the O(n) structured solves (spatial/shifted_solver.h); dense on request.
  io.jacobian = scene.solver.jacobian == JacobianKind::kDense ? JacobianKind::kDense : JacobianKind::kStructured;
  io.rho_inf = scene.solver.rho_inf;
  io.newton_tolerance = scene.solver.newton_tolerance;
  sim_ = std::make_unique<Simulator3>(model_, motion, scene.solver.integrator, io, scene.solver.stabilization);
  sim_->reset(withInitialVelocity3(scene.initial, top, initial_.kin), 0.0, initial_.hang_off);  // initial.velocity
  // The spins of an equilibrium twisted by the bending axes.
  if (!initial_.material_axes.empty()) sim_->setMaterialAxes(initial_.material_axes);
  setInitialSpinRates(scene.initial, *sim_);
  if (scene.initial.has_velocity) initial_.equilibrium = false, initial_.about += initialVelocityAbout(scene.initial);
  sim_->estimateStability();
  const int nb = model_->bodies();
  out_.points.resize(nb + 1);
  out_.springs.resize(nb);
  out_.axial_force.resize(nb);
  energy_scale_ = std::max(model_->line().totalMass() * scene.gravity * scene.length, 1e-12);
  e0_ = sim_->energy();
  max_constraint_error_ = sim_->constraintError();
  ends_.assign(nb, BodyKinematics3());
  trackMoments();
  if (!sim_->state().allFinite() || !std::isfinite(e0_) || !sim_->evaluate().reactions.top.allFinite())
    throw std::runtime_error(
        "initial: the initial state or its forces are not finite (NaN/Inf): the scene's values "
        "combine beyond double range");
}

void Run3::trackMoments() {
  const int nb = model_->bodies();
  const VecX& y = sim_->state();
  if (top_joint_) {
    ends_[0] = sim_->formulation().body(y, 0);
    max_moment_[0] = std::max(max_moment_[0], top_joint_->moment(*model_, ends_, sim_->time()).norm());
  }
  if (bottom_joint_) {
    ends_[nb - 1] = sim_->formulation().body(y, nb - 1);
    max_moment_[1] = std::max(max_moment_[1], bottom_joint_->moment(*model_, ends_, sim_->time()).norm());
  }
}

FlexJoints3 addFlexJoints(const Scene& scene, const Kinematics3& initial, Model3& model,
                          const std::shared_ptr<const TopMotion3>& top_holder,
                          const std::shared_ptr<const TopMotion3>& bottom_holder) {
  FlexJoints3 out;
  const auto add = [&](const FlexJointSpec& spec, FlexJoint::End end, const Vec3& along,
                       const std::shared_ptr<const TopMotion3>& holder, const char* key) {
    if (!spec.enabled) return static_cast<const FlexJoint*>(nullptr);
    const Vec3 axis = spec.has_axis ? Vec3(spec.axis) : along;
    model.addTerm(std::make_unique<FlexJoint>(end, axis, spec.stiffness, spec.damping,
                                              holder && holder->rotates() ? holder : nullptr, 0.0));
    const auto* joint = static_cast<const FlexJoint*>(model.terms().back().get());
    const double theta = joint->angle(model, initial, 0.0);
    // A flex joint bends by degrees; past 90° its spring moment k θ heads for the fold at 180°, where its
    // direction is undefined and its stiffness k θ / sin θ unbounded.
    if (theta > 0.5 * M_PI)
      throw std::invalid_argument(std::string(key) + ".axis: " + fmt(theta * 180.0 / M_PI) +
                                  " deg from the line's direction at the start (at most 90 deg); give the axis "
                                  "along the line, pointing away from the holder");
    if (theta > 1e-9)
      out.loaded += std::string(out.loaded.empty() ? "" : ", ") + key + " turned " + fmt(theta) + " rad";
    return joint;
  };
  out.top = add(scene.top_flex_joint, FlexJoint::End::kTop, initial.front().e, top_holder, "top.flex_joint");
  out.bottom =
      add(scene.bottom_flex_joint, FlexJoint::End::kBottom, -initial.back().e, bottom_holder, "bottom.flex_joint");
  return out;
}

bool Run3::step() {
  if (diverged()) return false;
  const bool stepped = sim_->step(dt_);
  ++steps_;
  const VecX& y = sim_->state();
  const bool finite = y.allFinite();
  double err = 0.0, turn = 0.0, stretch = 0.0, spin = 0.0;
  int fast = -1;
  if (finite) {
    err = sim_->constraintError();
    max_constraint_error_ = std::max(max_constraint_error_, err);
    // line.torsion: the spin rates ω_i follow the velocities of the q part (positionSize() = q + θ).
    const int spins = model_->hasTorsion() ? model_->bodies() : 0;
    const double* omega = y.data() + sim_->formulation().positionSize() + model_->dofs();
    for (int i = 0; i < model_->bodies() && fast < 0; ++i) {
      const BodyKinematics3 b = sim_->formulation().body(y, i);
      turn = b.e_dot.norm() * dt_;
      stretch = std::abs(b.delta_dot) * dt_ / model_->rfe(i).length;
      spin = i < spins ? std::abs(omega[i]) * dt_ : 0.0;
      if (!(turn <= kMaxTurnPerStep && stretch <= kMaxStretchPerStep && spin <= kMaxTurnPerStep)) fast = i;
    }
  }
  if (stepped && finite && err <= max_gap_ && fast < 0) {
    trackMoments();
    sampleForces();
    return true;
  }
  std::ostringstream why;
  const std::string& failure = sim_->integrator().failure();
  if (finite && !failure.empty())
    why << failure;
  else if (finite && fast >= 0)
    why << "rfe " << fast << " turns by " << turn << " rad, stretches by " << stretch << " of its length"
        << (model_->hasTorsion() ? " and spins by " + std::to_string(spin) + " rad" : std::string())
        << " in one step at t = " << time() << " s (limits " << kMaxTurnPerStep << " rad, " << kMaxStretchPerStep
        << "): the motion is not resolved (unstable)";
  else if (!finite)
    why << "state is not finite (NaN/Inf) at t = " << time() << " s";
  else
    why << "joint constraint error " << err << " m exceeds " << max_gap_
        << " m (solver.max_constraint_error x d) at t = " << time() << " s";
  if (failure.find("loosen solver.tolerance") == std::string::npos) why << "; reduce solver.dt (now " << dt_ << " s)";
  if (explicitFixedStep() && highestFrequency() > 0.0)  // as the planar Simulator
    why << divergenceStabilityNote(sim_->integrator().name(), dt_, stableStepEstimate(), highestFrequency());
  reason_ = why.str();
  return false;
}

// The forces of the step's last evaluation when it was made at the step's end time (as the planar
// Simulator::sampleForces: no extra evaluation; the projection after the step moves the state by its
// round-off-sized drift only).
void Run3::sampleForces() {
  if (!sim_->stepEndEvaluated()) return;
  const NaturalData& d = sim_->lastEvaluation();
  const bool axial = model_->options().axial_flexibility;
  double tmax = 0.0;
  for (int i = 0; i < model_->bodies(); ++i) {
    tmax = std::max(tmax, axialForce(model_->rfe(i), d.kin[i], d.reactions.joint[i], axial));
  }
  noise_.add(d.reactions.top.norm(), tmax, dt_);
}

std::string Run3::stepAboveLimit() const {
  if (!explicitFixedStep()) return "";
  return stepAboveLimitMessage(sim_->integrator().name(), dt_, stableStepEstimate(), highestFrequency());
}

std::string Run3::forceWarning(const ForceNoise& e) const {
  return forceNoiseWarning(e, dt_, integrator_kind_, rho_inf_);
}

double Run3::energyDrift() { return (sim_->energy() - e0_ - sim_->work()) / std::max(std::abs(e0_), energy_scale_); }

const LineOutputs3& Run3::outputs() {
  const NaturalData& d = sim_->evaluate();
  const int nb = model_->bodies();
  const bool axial = model_->options().axial_flexibility;
  out_.t = sim_->time();
  double tmax = 0.0;
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics3& b = d.kin[i];
    const Rfe& r = model_->rfe(i);
    out_.points[i] = b.A;
    out_.springs[i] = b.A + r.length1 * b.e;
    out_.axial_force[i] = axialForce(r, b, d.reactions.joint[i], axial);
    tmax = std::max(tmax, out_.axial_force[i]);
  }
  out_.points[nb] = d.kin[nb - 1].end();
  out_.top_force = d.reactions.top;
  out_.bottom_force = d.reactions.bottom;
  out_.top_moment =
      (top_joint_ ? top_joint_->moment(*model_, d.kin, sim_->time()) : Vec3::Zero()) + d.reactions.top_twist_moment;
  out_.bottom_moment = bottom_joint_ ? bottom_joint_->moment(*model_, d.kin, sim_->time()) : Vec3::Zero();
  out_.top_twist = d.reactions.top_twist;
  out_.bottom_point = model_->bottom() == BottomBoundary::kPinned ? d.bottom.p : Vec3::Zero();
  out_.top_tension = d.reactions.top.norm();
  out_.max_tension = tmax;
  out_.kinetic_energy = sim_->kineticEnergy();
  out_.potential_energy = sim_->potentialEnergy();
  out_.work_in = sim_->work();
  out_.constraint_error = sim_->constraintError();
  return out_;
}

}  // namespace spatial
}  // namespace riser_sim
