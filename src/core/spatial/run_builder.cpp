#include "riser_sim/spatial/run_builder.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/buoyancy.h"
#include "riser_sim/spatial/forces/end_load.h"
#include "riser_sim/spatial/forces/froude_krylov.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/forces/morison_drag.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/relaxation.h"
#include "riser_sim/stability_estimate.h"

namespace riser_sim {
namespace spatial {

namespace {

// Divergence by unresolved motion, as the planar Simulator: an rfe turning by more than 0.5 rad or
// stretching by more than 10 % of its length in one step.
constexpr double kMaxTurnPerStep = 0.5;
constexpr double kMaxStretchPerStep = 0.1;
// Planarity of the statics' data in its plane, relative to the sizes involved (round-off of the rotation).
constexpr double kPlanarTolerance = 1e-12;

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
  if (s.hydro.enabled && s.hydro.inertia_coefficient != 1.0)
    return SceneIssue{"hydrodynamics.inertia_coefficient",
                      "C_M != 1 (added mass) is " + yet + " (buoyancy, drag and the Froude-Krylov force with C_M = 1 are)"};
  if (s.seabed.enabled && s.seabed.stiffness_tangential > 0.0)
    return SceneIssue{"seabed.stiffness_tangential", "anchored tangential springs are " + yet +
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
    return SceneIssue{"line.elements", "must be <= " + std::to_string(kMaxDenseElements3) + " with a dense " +
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
  return m;
}

VelocityProfileMotion3::VelocityProfileMotion3(const Vec3& start, const std::vector<TopMotionSpec::Knot3>& knots) {
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
  return PointMotion3{Vec3(a.p.x(), b.p.x(), a.p.y()), Vec3(a.v.x(), b.v.x(), a.v.y()), Vec3(a.a.x(), b.a.x(), a.a.y())};
}

std::unique_ptr<TopMotion3> buildTopMotion3(const TopMotionSpec& spec) {
  switch (spec.type) {
    case MotionKind::kFixed:
    case MotionKind::kExternal: return std::make_unique<FixedMotion3>(spec.position3);
    case MotionKind::kSinusoid:
      if (!(spec.period > 0.0)) throw std::invalid_argument("top.motion.period: must be > 0");
      return std::make_unique<SinusoidMotion3>(spec.position3, spec.amplitude3, spec.period, spec.phase3);
    case MotionKind::kVelocityProfile: return std::make_unique<VelocityProfileMotion3>(spec.position3, spec.knots3);
  }
  throw std::invalid_argument("top.motion.type: unknown motion (accepted: " + choiceNames<MotionKind>() + ")");
}

std::shared_ptr<SpatialModel> buildSpatialModel(const Scene& scene) {
  LineProperties props = scene.line;
  props.content_mass_per_length = scene.internal_fluid.density * props.internalArea();
  auto model = std::make_shared<SpatialModel>(scene.length, scene.elements, props, scene.options, scene.end_mass,
                                              Vec3(0.0, 0.0, -scene.gravity));
  model->setBottom(scene.bottom, scene.bottom_point3);
  // Only the terms the scene needs (as the planar buildModel).
  if (scene.gravity != 0.0) model->addTerm(std::make_unique<Gravity>());
  if (scene.options.axial_flexibility) model->addTerm(std::make_unique<AxialSpring>());
  if (scene.options.bending && (scene.line.EI > 0.0 || scene.line.bending_damping > 0.0))
    model->addTerm(std::make_unique<BendingSpring>());
  if (scene.water.enabled) {  // the sea's terms, as the planar buildModel builds them
    const Water3 water(scene.water, model->gravity());
    if (scene.gravity != 0.0) model->addTerm(std::make_unique<Buoyancy3>(water));
    const HydroSpec& h = scene.hydro;
    if (h.enabled && (h.drag_normal > 0.0 || h.drag_tangential > 0.0))
      model->addTerm(std::make_unique<MorisonDrag3>(water, h.drag_tangential, h.drag_normal));
    if (h.enabled && water.moving()) model->addTerm(std::make_unique<FroudeKrylov3>(water));
  }
  if (scene.seabed.enabled) model->addTerm(std::make_unique<Seabed3>(scene.seabed, model->gravity()));
  if (scene.torsion.enabled) {
    const TorsionSpec& t = scene.torsion;
    model->setTorsion(TorsionProperties{t.stiffness, t.polar_inertia, t.damping, t.end_polar_inertia});
  }
  return model;
}

namespace {

// Rotation about z taking +x to the horizontal unit vector u: the planar (x, y_up) -> u x + y_up z.
Mat3 yaw(const Vec2& u) {
  Mat3 R;
  R << u.x(), -u.y(), 0.0, u.y(), u.x(), 0.0, 0.0, 0.0, 1.0;
  return R;
}

// The current's horizontal direction (uniform, or the first non-zero point of the profile); zero if none.
Vec2 currentDirection(const CurrentSpec& c) {
  if (!c.profile.empty()) {
    for (const CurrentSpec::Point& p : c.profile)
      if (Vec2(p.vx, p.vy).norm() > 0.0) return Vec2(p.vx, p.vy).normalized();
    return Vec2::Zero();
  }
  const Vec2 h = c.velocity3.head<2>();
  return h.norm() > 0.0 ? Vec2(h.normalized()) : Vec2::Zero();
}

// The current in the vertical plane along u (x along u, y_up = z), for the planar statics; `across` gets its
// largest horizontal component normal to that plane beyond round-off (kPlanarTolerance of the speeds) [m/s].
CurrentSpec planarCurrent(const CurrentSpec& c, const Vec2& u, double& across) {
  const Vec2 nrm(-u.y(), u.x());
  CurrentSpec p = c;
  p.velocity = Vec2(c.velocity3.head<2>().dot(u), c.velocity3.z());
  p.acceleration = Vec2(c.acceleration3.head<2>().dot(u), c.acceleration3.z());
  across = std::max(std::abs(c.velocity3.head<2>().dot(nrm)), std::abs(c.acceleration3.head<2>().dot(nrm)));
  double speed = std::max(c.velocity3.norm(), c.acceleration3.norm());
  for (CurrentSpec::Point& q : p.profile) {
    const Vec2 v(q.vx, q.vy);
    across = std::max(across, std::abs(v.dot(nrm)));
    speed = std::max(speed, v.norm());
    q.vx = v.dot(u), q.vy = 0.0;
  }
  if (across <= kPlanarTolerance * speed) across = 0.0;
  return p;
}

}  // namespace

Scene stillWater(const Scene& scene) {
  Scene s = scene;
  s.water.waves.height = 0.0;
  s.water.waves.significant_height = 0.0;
  return s;
}

double restAcceleration(const Scene& scene, const Kinematics3& kin, const Vec3& end_force, const Vec3& top,
                        int& where) {
  std::shared_ptr<SpatialModel> model = buildSpatialModel(stillWater(scene));
  if (scene.bottom == BottomBoundary::kPinned) model->setBottom(BottomBoundary::kPinned, kin.back().end());
  if (end_force.squaredNorm() > 0.0 && scene.bottom != BottomBoundary::kPinned)
    model->addTerm(std::make_unique<EndLoad3>(end_force));
  const NaturalFormulation f(*model, scene.solver.stabilization);
  auto data = f.makeData();
  const int nq = f.positionSize();  // the velocities' offset (torsion adds θ to q)
  VecX y = VecX::Zero(2 * nq), dy = VecX::Zero(2 * nq);
  f.packState(kin, y);
  f.initTwist(y, *data);  // untwisted: no twist forces
  f.derivative(0.0, y, PointMotion3{top, Vec3::Zero(), Vec3::Zero()}, dy, *data);
  double amax = 0.0;
  where = 0;
  for (int i = 0; i < model->bodies(); ++i) {
    const double* u = dy.data() + nq + kDofPerBody3 * i;
    const Vec3 aA(u[kA], u[kA + 1], u[kA + 2]), ee(u[kE], u[kE + 1], u[kE + 2]);
    const Vec3 aE = aA + u[kDelta3] * kin[i].e + kin[i].len * ee;
    const double a = std::max(aA.norm(), aE.norm());
    if (!(a <= amax)) amax = a, where = i;  // a NaN wins
  }
  return amax;
}

InitialState3 solveInitialState3(const Scene& scene, const Vec3& top) {
  InitialState3 init;
  const InitialKind kind = scene.initial.type;
  // The vertical plane of the problem: through the top, along the horizontal unit vector u.
  Vec2 u(1.0, 0.0);
  const Vec2 bottom_h = scene.bottom_point3.head<2>() - top.head<2>();
  if (kind == InitialKind::kStraight) u = Vec2(std::cos(scene.initial.heading), std::sin(scene.initial.heading));
  if (kind == InitialKind::kDisplaced && scene.initial.end_offset.norm() > 0.0) u = scene.initial.end_offset.normalized();
  if (kind == InitialKind::kBetweenPoints && bottom_h.norm() > 0.0) u = bottom_h.normalized();
  // A line hanging free in a current leans downstream: its plane is the current's (the statics see it steady).
  const Vec2 cur = scene.water.enabled ? currentDirection(scene.water.current) : Vec2::Zero();
  const bool free_hang = kind == InitialKind::kHanging || (kind == InitialKind::kDisplaced && scene.initial.end_offset.norm() == 0.0);
  if (free_hang && cur.norm() > 0.0) u = cur;
  const Mat3 R = yaw(u);
  const Vec3 origin(top.x(), top.y(), 0.0);
  const Vec3 normal(-u.y(), u.x(), 0.0);  // of the plane
  init.plane_direction = Vec3(u.x(), u.y(), 0.0);

  // The planar scene in that plane: x along u from the top, y_up = z.
  Scene ps = scene;
  ps.space = SpaceKind::kPlanar;
  ps.top = TopMotionSpec();
  ps.top.position = Vec2(0.0, top.z());
  ps.initial.end_dx = scene.initial.end_offset.norm();
  ps.bottom_point = Vec2(bottom_h.norm(), scene.bottom_point3.z());
  double current_across = 0.0;
  ps.water.current = planarCurrent(scene.water.current, u, current_across);
  ps.water.waves = WaveSpec();  // the statics never see the waves
  const std::shared_ptr<Model> planar = buildModel(ps);

  if (kind == InitialKind::kStraight) {
    init.kin = fromPlanar(straightLine(*planar, ps.top.position, scene.initial.angle), R, origin);
    init.equilibrium = false;
    init.about = "straight line (not an equilibrium)";
    init.statics.converged = true;
    init.statics.message = init.about;
    return init;
  }

  // The problem is planar in that plane: gravity vertical, the top, the anchor and the end force in it.
  const double L = scene.length;
  const auto offPlane = [&](const Vec3& p) { return std::abs(normal.dot(p - origin)); };
  std::string check;
  if (buildSpatialModel(scene)->gravity().head<2>().norm() != 0.0) check = "gravity is not vertical";
  if (check.empty() && kind == InitialKind::kBetweenPoints &&
      offPlane(scene.bottom_point3) > kPlanarTolerance * std::max(L, (scene.bottom_point3 - top).norm()))
    check = "bottom.position is " + fmt(offPlane(scene.bottom_point3)) + " m off the plane";
  // A current across the plane (or veering with depth): the planar statics with its projection give the guess
  // that the 3D relaxation starts from (relaxation.h). An end held by a force (displaced) is not relaxed.
  const bool relax = scene.water.enabled && current_across > 0.0;
  if (check.empty() && relax && kind == InitialKind::kDisplaced)
    check = "the current has " + fmt(current_across) + " m/s across the plane (environment.current; a displaced "
            "end is solved in its plane only)";

  const StaticsProblem problem = staticsProblem(ps);
  if (check.empty()) {
    init.statics = solveStatics(*planar, problem, 0.0);
    if (!init.statics.converged) throw std::runtime_error("initial: " + init.statics.message);
    init.kin = fromPlanar(init.statics.kin, R, origin);
    init.end_force = planarPoint(init.statics.end_force, R);
    if (std::abs(normal.dot(init.end_force)) > kPlanarTolerance * init.end_force.norm())
      check = "the end force points " + fmt(normal.dot(init.end_force)) + " N out of the plane";
    for (size_t i = 0; i < init.kin.size() && check.empty(); ++i)
      if (offPlane(init.kin[i].end()) > kPlanarTolerance * L)
        check = "rfe " + std::to_string(i) + " ends " + fmt(offPlane(init.kin[i].end())) + " m off the plane";
  }
  if (!check.empty())
    throw std::runtime_error("initial: the statics are solved in the vertical plane through the top along (" +
                             fmt(u.x()) + ", " + fmt(u.y()) + "), but the problem is not planar there: " + check);
  init.about = std::string(name(kind)) + " equilibrium (planar statics in the vertical plane along (" + fmt(u.x()) +
               ", " + fmt(u.y()) + "), rotated into 3D)";

  // The rotated state must be an equilibrium of the 3D model: its accelerations at rest ~0. The statics
  // leave a residual force up to initial.tolerance x the weight W on a coordinate; on the lightest rfe
  // (mass m_min) that is an acceleration of tolerance W / m_min. The bound allows 100x that (the residual
  // spreads over the force, Δ and moment equations of an rfe), plus 1e-9 g of round-off.
  const Model& line = *planar;
  double m_min = INFINITY;
  for (int i = 0; i < line.bodies(); ++i) m_min = std::min(m_min, line.rfe(i).mass);
  const double W = line.totalMass() * scene.gravity;
  init.acceleration_bound = 100.0 * scene.initial.tolerance * W / m_min + 1e-9 * std::max(scene.gravity, 1.0);
  if (relax) {
    const Relaxed3 r = relaxToRest(scene, init.kin, top, init.acceleration_bound);
    init.kin = r.kin;
    init.about = std::string(name(kind)) + " equilibrium in the current across the plane along (" + fmt(u.x()) + ", " +
                 fmt(u.y()) + "): the planar statics with the current projected, relaxed in 3D (" + fmt(r.time) +
                 " s, " + std::to_string(r.steps) + " steps)";
  }
  int where = 0;
  init.max_acceleration = restAcceleration(scene, init.kin, init.end_force, top, where);
  if (!(init.max_acceleration <= init.acceleration_bound))
    throw std::runtime_error("initial: the " + std::string(name(kind)) + " equilibrium rotated into 3D is not an "
                             "equilibrium of the 3D model: acceleration " + fmt(init.max_acceleration) +
                             " m/s^2 at rest at rfe " + std::to_string(where) + " (bound " +
                             fmt(init.acceleration_bound) + " m/s^2 from initial.tolerance)");
  return init;
}

SpatialRun::SpatialRun(const Scene& scene)
    : integrator_kind_(scene.solver.integrator), rho_inf_(scene.solver.rho_inf), dt_(scene.solver.dt), max_gap_(scene.solver.max_constraint_error * scene.length / scene.elements) {
  if (scene.space != SpaceKind::kSpatial) throw std::invalid_argument("space: SpatialRun needs space: spatial");
  if (const auto issue = unsupported(scene)) throw std::invalid_argument(issue->key + ": " + issue->message);
  model_ = buildSpatialModel(scene);
  std::unique_ptr<TopMotion3> motion = buildTopMotion3(scene.top);
  // The statics end at the bottom's position at t = 0 (bottom.motion's, which may differ from bottom.position).
  Scene at0 = scene;
  const bool pinned = scene.bottom == BottomBoundary::kPinned;
  if (pinned) at0.bottom_point3 = buildTopMotion3(scene.bottom_motion)->at(0.0).p;
  initial_ = solveInitialState3(at0, motion->at(0.0).p);
  // A pinned end is held where the statics put it: within initial.tolerance x line.length of
  // bottom.position (their end condition), so the run starts without a Baumgarte kick from that gap. A
  // moving bottom's path is shifted by that gap for the same reason.
  if (pinned) {
    const Vec3 gap = initial_.kin.back().end() - at0.bottom_point3;
    const MotionKind type = scene.bottom_motion.type;
    if (type == MotionKind::kSinusoid || type == MotionKind::kVelocityProfile) {
      TopMotionSpec spec = scene.bottom_motion;
      spec.position3 += gap;
      model_->setBottomMotion(buildTopMotion3(spec));
    } else {
      model_->setBottom(BottomBoundary::kPinned, initial_.kin.back().end());
    }
  }
  // A loaded joint at t = 0 makes the start no equilibrium (the statics pin the ends): said in initial().about.
  const FlexJoints3 joints = addFlexJoints(scene, initial_.kin, *model_);
  top_joint_ = joints.top;
  bottom_joint_ = joints.bottom;
  if (!joints.loaded.empty()) {
    initial_.equilibrium = false;
    initial_.about += "; not an equilibrium with the flex joints, which start loaded (" + joints.loaded +
                      " from their axis; the statics pin the ends)";
  }
  // The statics' end force stays on as a constant end load (hold), so the start is an exact equilibrium.
  if (scene.initial.type == InitialKind::kDisplaced && scene.initial.end_force == EndForceKind::kHold)
    model_->addTerm(std::make_unique<EndLoad3>(initial_.end_force));
  IntegratorOptions io;
  io.tolerance = scene.solver.tolerance;
  io.jacobian_interval = scene.solver.jacobian_interval;
  // auto: the O(n) structured solves (spatial/shifted_solver.h); dense on request.
  io.jacobian = scene.solver.jacobian == JacobianKind::kDense ? JacobianKind::kDense : JacobianKind::kStructured;
  io.rho_inf = scene.solver.rho_inf;
  sim_ = std::make_unique<SpatialSimulator>(model_, std::move(motion), scene.solver.integrator, io,
                                            scene.solver.stabilization);
  sim_->reset(initial_.kin, 0.0);
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
    throw std::runtime_error("initial: the initial state or its forces are not finite (NaN/Inf): the scene's values "
                             "combine beyond double range");
}

void SpatialRun::trackMoments() {
  const int nb = model_->bodies();
  const VecX& y = sim_->state();
  if (top_joint_) {
    ends_[0] = sim_->formulation().body(y, 0);
    max_moment_[0] = std::max(max_moment_[0], top_joint_->moment(*model_, ends_).norm());
  }
  if (bottom_joint_) {
    ends_[nb - 1] = sim_->formulation().body(y, nb - 1);
    max_moment_[1] = std::max(max_moment_[1], bottom_joint_->moment(*model_, ends_).norm());
  }
}

FlexJoints3 addFlexJoints(const Scene& scene, const Kinematics3& initial, SpatialModel& model) {
  FlexJoints3 out;
  const auto add = [&](const FlexJointSpec& spec, FlexJoint::End end, const Vec3& along, const char* key) {
    if (!spec.enabled) return static_cast<const FlexJoint*>(nullptr);
    const Vec3 axis = spec.has_axis ? Vec3(spec.axis) : along;
    model.addTerm(std::make_unique<FlexJoint>(end, axis, spec.stiffness, spec.damping));
    const auto* joint = static_cast<const FlexJoint*>(model.terms().back().get());
    const double theta = joint->angle(model, initial);
    if (theta > 1e-9) out.loaded += std::string(out.loaded.empty() ? "" : ", ") + key + " turned " + fmt(theta) + " rad";
    return joint;
  };
  out.top = add(scene.top_flex_joint, FlexJoint::End::kTop, initial.front().e, "top.flex_joint");
  out.bottom = add(scene.bottom_flex_joint, FlexJoint::End::kBottom, -initial.back().e, "bottom.flex_joint");
  return out;
}

bool SpatialRun::step() {
  if (diverged()) return false;
  const bool stepped = sim_->step(dt_);
  ++steps_;
  const VecX& y = sim_->state();
  const bool finite = y.allFinite();
  double err = 0.0, turn = 0.0, stretch = 0.0;
  int fast = -1;
  if (finite) {
    err = sim_->constraintError();
    max_constraint_error_ = std::max(max_constraint_error_, err);
    for (int i = 0; i < model_->bodies() && fast < 0; ++i) {
      const BodyKinematics3 b = sim_->formulation().body(y, i);
      turn = b.e_dot.norm() * dt_;
      stretch = std::abs(b.delta_dot) * dt_ / model_->rfe(i).length;
      if (!(turn <= kMaxTurnPerStep && stretch <= kMaxStretchPerStep)) fast = i;
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
    why << "rfe " << fast << " turns by " << turn << " rad and stretches by " << stretch
        << " of its length in one step at t = " << time() << " s (limits " << kMaxTurnPerStep << " rad, "
        << kMaxStretchPerStep << "): the motion is not resolved (unstable)";
  else if (!finite)
    why << "state is not finite (NaN/Inf) at t = " << time() << " s";
  else
    why << "joint constraint error " << err << " m exceeds " << max_gap_ << " m (solver.max_constraint_error x d) at t = "
        << time() << " s";
  if (failure.find("loosen solver.tolerance") == std::string::npos) why << "; reduce solver.dt (now " << dt_ << " s)";
  if (explicitFixedStep() && highestFrequency() > 0.0)  // as the planar Simulator
    why << divergenceStabilityNote(sim_->integrator().name(), dt_, stableStepEstimate(), highestFrequency());
  reason_ = why.str();
  return false;
}

// The forces of the step's last evaluation when it was made at the step's end time (as the planar
// Simulator::sampleForces: no extra evaluation; the projection after the step moves the state by its
// round-off-sized drift only).
void SpatialRun::sampleForces() {
  if (!sim_->stepEndEvaluated()) return;
  const NaturalData& d = sim_->lastEvaluation();
  const bool axial = model_->options().axial_flexibility;
  double tmax = 0.0;
  for (int i = 0; i < model_->bodies(); ++i) {
    tmax = std::max(tmax, axialForce(model_->rfe(i), d.kin[i], d.reactions.joint[i], axial));
  }
  noise_.add(d.reactions.top.norm(), tmax, dt_);
}

std::string SpatialRun::stepAboveLimit() const {
  if (!explicitFixedStep()) return "";
  return stepAboveLimitMessage(sim_->integrator().name(), dt_, stableStepEstimate(), highestFrequency());
}

std::string SpatialRun::forceWarning(const ForceNoise& e) const {
  return forceNoiseWarning(e, dt_, integrator_kind_, rho_inf_);
}

double SpatialRun::energyDrift() {
  return (sim_->energy() - e0_ - sim_->work()) / std::max(std::abs(e0_), energy_scale_);
}

const LineOutputs3& SpatialRun::outputs() {
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
  out_.top_moment = (top_joint_ ? top_joint_->moment(*model_, d.kin) : Vec3::Zero()) + d.reactions.top_twist_moment;
  out_.bottom_moment = bottom_joint_ ? bottom_joint_->moment(*model_, d.kin) : Vec3::Zero();
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
