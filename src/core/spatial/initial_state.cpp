// The 3D initial state (run_builder.h): the planar statics in a vertical plane, rotated into 3D and checked
// against the 3D model at rest; a current across that plane, or a sloped seabed under the line, is relaxed in 3D
// (relaxation.h).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "riser_sim/spatial/forces/end_load.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/statics.h"
#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/relaxation.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/planar/statics.h"
#include "initial_twist.h"

namespace riser_sim {
namespace spatial {

namespace {

// Planarity of the statics' data in its plane, relative to the sizes involved (round-off of the rotation).
constexpr double kPlanarTolerance = 1e-12;

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

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
  const Vec2 h = c.velocity.head<2>();
  return h.norm() > 0.0 ? Vec2(h.normalized()) : Vec2::Zero();
}

// The current in the vertical plane along u (x along u, y_up = z), for the planar statics; `across` gets its
// largest horizontal component normal to that plane beyond round-off (kPlanarTolerance of the speeds) [m/s].
CurrentSpec planarCurrent(const CurrentSpec& c, const Vec2& u, double& across) {
  const Vec2 nrm(-u.y(), u.x());
  CurrentSpec p = c;
  p.velocity = inSpace(Vec2(c.velocity.head<2>().dot(u), c.velocity.z()));
  p.acceleration = inSpace(Vec2(c.acceleration.head<2>().dot(u), c.acceleration.z()));
  across = std::max(std::abs(c.velocity.head<2>().dot(nrm)), std::abs(c.acceleration.head<2>().dot(nrm)));
  double speed = std::max(c.velocity.norm(), c.acceleration.norm());
  for (CurrentSpec::Point& q : p.profile) {
    const Vec2 v(q.vx, q.vy);
    across = std::max(across, std::abs(v.dot(nrm)));
    speed = std::max(speed, v.norm());
    q.vx = v.dot(u), q.vy = 0.0;
  }
  if (across <= kPlanarTolerance * speed) across = 0.0;
  return p;
}

// line.bending_axis must leave a direction across the top rfe to measure the spin from.
void checkBendingAxis(const Scene& scene, const Kinematics3& kin) {
  const Vec3& a = scene.bending_axes.axis;
  if (scene.bending_axes.enabled && !(a.normalized().cross(kin[0].e.normalized()).norm() > 1e-6))
    throw std::runtime_error(
        "line.bending_axis: lies along the top rfe at t = 0 (within 1e-6 rad): give material "
        "axis 1 across the line");
}

}  // namespace

std::shared_ptr<Model3> restModel3(const Scene& scene, const Kinematics3& kin, const Vec3& end_force) {
  BuildOptions o;
  o.terms.steady_sea = true;
  if (scene.bottom == BottomBoundary::kPinned)
    o.pinned_at = kin.back().end();
  else
    o.end_force = end_force;
  return buildModel3(scene, o);
}

void checkStable(const Scene& scene, const InitialState3& init, bool held_end) {
  const std::shared_ptr<Model3> model = restModel3(scene, init.kin, init.end_force);
  ModalOptions3 o;
  o.hang_off = init.hang_off;
  const LinearStability s =
      stability3(*model, init.kin, held_end, o, init.material_axes.empty() ? nullptr : &init.material_axes);
  if (!s.stable)
    throw std::runtime_error("initial: the " + std::string(name(scene.initial.type)) + " equilibrium (" + init.about +
                             ") fails the check stability: " + s.describe());
}

double restAcceleration(const Scene& scene, const Kinematics3& kin, const Vec3& end_force, const Vec3& top,
                        int& where) {
  double moment = 0.0;
  int moment_where = 0;
  return restAcceleration(*restModel3(scene, kin, end_force), scene.solver.stabilization, kin, top,
                          AlignedVector<Vec3>(), where, moment, moment_where);
}

double restAcceleration(const Model3& rest, double stabilization, const Kinematics3& kin, const Vec3& top,
                        const AlignedVector<Vec3>& material_axes, int& where, double& moment, int& moment_where,
                        const HangOff& hang_off) {
  const NaturalFormulation f(rest, stabilization);
  auto data = f.makeData();
  const int nq = f.positionSize();  // the velocities' offset (torsion adds θ to q)
  VecX y = VecX::Zero(2 * nq), dy = VecX::Zero(2 * nq);
  f.packState(kin, y);
  f.initTwist(y, *data, Mat3::Identity(), hang_off);  // untwisted unless the material axes say otherwise
  const int first = rest.hasTorsion() ? firstSpin(rest) : rest.bodies();
  if (!material_axes.empty() && rest.hasTorsion()) {
    VecX theta(rest.bodies());
    spinsFromAxes(kin, data->twist.frames, material_axes, theta.data());  // a held rfe 0 keeps the hang-off's
    for (int i = first; i < rest.bodies(); ++i) y[rest.dofs() + i] = theta[i];
  }
  f.derivative(0.0, y, PointMotion3{top, Vec3::Zero(), Vec3::Zero()}, dy, *data);
  double amax = 0.0;
  where = 0;
  for (int i = 0; i < rest.bodies(); ++i) {
    const double* u = dy.data() + nq + kDofPerBody3 * i;
    const Vec3 aA(u[kA], u[kA + 1], u[kA + 2]), ee(u[kE], u[kE + 1], u[kE + 2]);
    const Vec3 aE = aA + u[kDelta3] * kin[i].e + kin[i].len * ee;
    const double a = std::max(aA.norm(), aE.norm());
    if (!(a <= amax)) amax = a, where = i;  // a NaN wins
  }
  moment = 0.0;
  moment_where = 0;
  for (int i = first; i < rest.bodies(); ++i)
    if (!(std::abs(data->twist.moment[i]) <= moment)) moment = std::abs(data->twist.moment[i]), moment_where = i;
  return amax;
}

namespace {

// Stage 1. The vertical plane of the statics: through the top, along the horizontal unit vector u (the straight
// line's heading, the displaced end's offset, the anchor's direction, or downstream for a free end in a current;
// down the fall line for a free end on a slope in still water).
struct StaticsPlane {
  Vec2 u = Vec2(1.0, 0.0);
  Mat3 R = Mat3::Identity();  // planar (x, y_up) -> u x + y_up z
  Vec3 origin = Vec3::Zero(), normal = Vec3::UnitY();
  bool free_hang = false;  // the end hangs free (hanging, or displaced by zero)
  bool sloped = false;     // a sloped seabed
};

StaticsPlane staticsPlane(const Scene& scene, const Vec3& top) {
  StaticsPlane p;
  const InitialKind kind = scene.initial.type;
  const Vec2 bottom_h = scene.bottom_point.head<2>() - top.head<2>();
  if (kind == InitialKind::kStraight) p.u = Vec2(std::cos(scene.initial.heading), std::sin(scene.initial.heading));
  if (kind == InitialKind::kDisplaced && scene.initial.end_offset.norm() > 0.0)
    p.u = scene.initial.end_offset.normalized();
  if (kind == InitialKind::kBetweenPoints && bottom_h.norm() > 0.0) p.u = bottom_h.normalized();
  // A line hanging free in a current leans downstream: its plane is the current's (the statics see it steady).
  const Vec2 cur = scene.water.enabled ? currentDirection(scene.water.current) : Vec2::Zero();
  p.free_hang =
      kind == InitialKind::kHanging || (kind == InitialKind::kDisplaced && scene.initial.end_offset.norm() == 0.0);
  if (p.free_hang && cur.norm() > 0.0) p.u = cur;
  p.sloped = scene.seabed.enabled && scene.seabed.slope > 0.0;
  const Vec2 uphill(std::cos(scene.seabed.slope_heading), std::sin(scene.seabed.slope_heading));
  if (p.sloped && p.free_hang && cur.norm() == 0.0) p.u = -uphill;
  p.R = yaw(p.u);
  p.origin = Vec3(top.x(), top.y(), 0.0);
  p.normal = Vec3(-p.u.y(), p.u.x(), 0.0);
  return p;
}

// Stage 2. The planar scene in that plane: x along u from the top, y_up = z, the current projected (`across`
// gets its part across the plane), no waves. A sloped seabed becomes a level one at the slope's height somewhere
// under the line, relaxed in 3D where it touches: a free end's at the top's vertical (the footprint downhill of
// it is above the slope), a pinned end's at the anchor (which then lies on it as in 2D), a displaced end's the
// higher of the two (the guess is above the slope; it is solved clear of the slope only). `principal`: with
// bending axes, whether the plane's bend is about one of them (else the 3D Newton twists it).
Scene planarScene(const Scene& scene, const StaticsPlane& plane, const Vec3& top, double& across, bool& principal) {
  const SeabedSpec& bed = scene.seabed;
  const Vec2 uphill(std::cos(bed.slope_heading), std::sin(bed.slope_heading));
  const auto slopeHeight = [&](const Vec2& p) { return bed.level + std::tan(bed.slope) * uphill.dot(p); };
  const InitialKind kind = scene.initial.type;
  Scene ps = scene;
  ps.space = SpaceKind::kPlanar;
  principal = true;
  if (scene.bending_axes.enabled) ps.line.EI = detail::planarBendingStiffness(scene, plane.normal, principal);
  ps.bending_axes = BendingAxesSpec();
  ps.top = TopMotionSpec();
  ps.top.position = Vec3(0.0, 0.0, top.z());
  ps.initial.end_dx = scene.initial.end_offset.norm();
  ps.bottom_point = inSpace(Vec2((scene.bottom_point.head<2>() - top.head<2>()).norm(), scene.bottom_point.z()));
  ps.water.current = planarCurrent(scene.water.current, plane.u, across);
  ps.water.waves = WaveSpec();  // the statics never see the waves
  if (plane.sloped && kind == InitialKind::kBetweenPoints)
    ps.seabed.level = slopeHeight(scene.bottom_point.head<2>());
  else if (plane.sloped && !plane.free_hang)
    ps.seabed.level = std::max(slopeHeight(top.head<2>()), slopeHeight(top.head<2>() + scene.initial.end_offset));
  else if (plane.sloped)
    ps.seabed.level = slopeHeight(top.head<2>());
  ps.seabed.slope = ps.seabed.slope_heading = 0.0;
  return ps;
}

// Stage 3 (initial.type straight). Not an equilibrium, but it must not start inside the seabed (the contact
// springs would throw it out): no contact point deeper than the sink of one carrying the whole weight.
InitialState3 straightStart(const Scene& scene, const StaticsPlane& plane, const Model& planar, const Vec2& top) {
  InitialState3 init;
  init.plane_direction = Vec3(plane.u.x(), plane.u.y(), 0.0);
  init.kin = fromPlanar(straightLine(planar, top, scene.initial.angle), plane.R, plane.origin);
  if (scene.seabed.enabled) {
    const Seabed bed(scene.seabed, Vec3(0.0, 0.0, -scene.gravity));
    const double sink = restingSinkAllowance(scene.seabed, planar.totalMass() * planar.gravity());
    for (size_t i = 0; i < init.kin.size(); ++i) {
      const Vec3 end = init.kin[i].end();
      if (bed.penetration(end) > sink)
        throw std::runtime_error("initial: the straight line reaches (" + fmt(end.x()) + ", " + fmt(end.y()) + ", " +
                                 fmt(end.z()) + ") m at the end of rfe " + std::to_string(i) + ", " +
                                 fmt(bed.penetration(end)) + " m below the seabed (seabed.level " +
                                 fmt(scene.seabed.level) + " m); use initial.type hanging or change initial.angle");
    }
  }
  init.equilibrium = false;
  checkBendingAxis(scene, init.kin);
  init.about = "straight line (not an equilibrium)";
  init.statics.converged = true;
  init.statics.message = init.about;
  return init;
}

// Stage 4. The planar statics in the plane, rotated into 3D; refused when the problem is not planar there (the
// anchor, the end force or the solution off the plane beyond round-off).
void planarEquilibrium(const Scene& scene, const StaticsPlane& plane, const Model& planar, const Scene& ps,
                       const Vec3& top, const StaticsProgress& progress, InitialState3& init) {
  const InitialKind kind = scene.initial.type;
  const double L = scene.length;
  const auto offPlane = [&](const Vec3& p) { return std::abs(plane.normal.dot(p - plane.origin)); };
  std::string check;
  if (kind == InitialKind::kBetweenPoints &&
      offPlane(scene.bottom_point) > kPlanarTolerance * std::max(L, (scene.bottom_point - top).norm()))
    check = "bottom.position is " + fmt(offPlane(scene.bottom_point)) + " m off the plane";
  if (check.empty()) {
    StaticsProblem problem = staticsProblem(ps);
    problem.progress = progress;
    init.statics = solveStatics(planar, problem, 0.0);
    if (!init.statics.converged) throw std::runtime_error("initial: " + init.statics.message);
    init.kin = fromPlanar(init.statics.kin, plane.R, plane.origin);
    init.end_force = planarPoint(init.statics.end_force, plane.R);
    if (std::abs(plane.normal.dot(init.end_force)) > kPlanarTolerance * init.end_force.norm())
      check = "the end force points " + fmt(plane.normal.dot(init.end_force)) + " N out of the plane";
    for (size_t i = 0; i < init.kin.size() && check.empty(); ++i)
      if (offPlane(init.kin[i].end()) > kPlanarTolerance * L)
        check = "rfe " + std::to_string(i) + " ends " + fmt(offPlane(init.kin[i].end())) + " m off the plane";
  }
  const Vec2& u = plane.u;
  if (!check.empty())
    throw std::runtime_error("initial: the statics are solved in the vertical plane through the top along (" +
                             fmt(u.x()) + ", " + fmt(u.y()) + "), but the problem is not planar there: " + check);
  init.about = std::string(name(kind)) + " equilibrium (planar statics in the vertical plane along (" + fmt(u.x()) +
               ", " + fmt(u.y()) + "), rotated into 3D)";
}

// Stage 5. At rest in 3D where the plane's solution is not: a displaced end in a current across the plane or on
// a slope by Newton in 3D with the end held by a horizontal force (modal.h); a current across the plane or a
// slope under the line by the dynamic relaxation (relaxation.h). `where` gets the rfe of the largest acceleration.
void restIn3D(const Scene& scene, const StaticsPlane& plane, double current_across, const Vec3& top,
              InitialState3& init, int& where) {
  const InitialKind kind = scene.initial.type;
  const Vec2& u = plane.u;
  const bool relax = scene.water.enabled && current_across > 0.0;
  const bool held_end = relax && kind == InitialKind::kDisplaced && !plane.free_hang;
  // On a slope: relaxed when the guess touches it (off the seabed it is the planar equilibrium).
  const bool relax_slope = plane.sloped && !(init.max_acceleration <= init.acceleration_bound);
  const bool slope_end = relax_slope && kind == InitialKind::kDisplaced && !plane.free_hang;
  if (held_end || slope_end) {
    BuildOptions steady;
    steady.terms.steady_sea = true;
    const std::shared_ptr<Model3> model = buildModel3(scene, steady);
    const Vec2 xy = top.head<2>() + scene.initial.end_offset;
    try {
      init.kin = equilibriumHeldEnd3(*model, init.kin, xy, init.end_force);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string("initial: the displaced end ") +
                               (slope_end ? "on the sloped seabed (seabed.slope"
                                          : "in the current across the plane "
                                            "(environment.current") +
                               "): " + e.what());
    }
    init.about = std::string("displaced equilibrium ") +
                 (slope_end ? "on the sloped seabed: the planar statics on a level seabed above it"
                            : "in the current across the plane: the planar statics with the current projected") +
                 ", then Newton in 3D with the end held at (" + fmt(xy.x()) + ", " + fmt(xy.y()) +
                 ") by the horizontal force (" + fmt(init.end_force.x()) + ", " + fmt(init.end_force.y()) + ") N";
    init.max_acceleration = restAcceleration(scene, init.kin, init.end_force, top, where);
  } else if ((relax || relax_slope) && !scene.bending_axes.enabled) {  // with bending axes: stage 6's Newton
    const Relaxed3 r = relaxToRest(scene, init.kin, top, init.acceleration_bound);
    init.kin = r.kin;
    if (scene.bottom == BottomBoundary::kPinned) init.end_force = r.end_force;
    init.about = std::string(name(kind)) + " equilibrium " +
                 (relax ? "in the current across the plane" : "on the sloped seabed, from the plane") + " along (" +
                 fmt(u.x()) + ", " + fmt(u.y()) + "): the planar statics" +
                 (relax ? " with the current projected" : " on a level seabed") + ", relaxed in 3D (" + fmt(r.time) +
                 " s, " + std::to_string(r.steps) + " steps)";
    init.max_acceleration = restAcceleration(scene, init.kin, init.end_force, top, where);
  }
}

// Stage 4b. Where the planar statics iterate and fail (a buoyant section or buoys whose continuations stall as
// touch-down contacts switch, or end on an unstable balance): relaxed in 3D from the planar first guess under every
// load at once (relaxation.h); the checks that follow are those of any start.
void relaxFromTheGuess(const Scene& scene, const StaticsPlane& plane, const Model& planar, const Scene& ps,
                       const Vec3& top, const std::string& statics_failure, InitialState3& init) {
  Relaxed3 r;
  try {
    r = relaxFromFirstGuess(scene, planar, staticsProblem(ps), plane.R, plane.origin, top, init.acceleration_bound);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(statics_failure + "; relaxed in 3D from the statics' first guess: " + e.what());
  }
  init.kin = r.kin;
  init.end_force = r.end_force;
  init.statics.converged = true;
  init.statics.message = "relaxed in 3D from the first guess";
  init.about = std::string(name(scene.initial.type)) + " equilibrium relaxed in 3D from the planar statics' first " +
               "guess (" + fmt(r.time) + " s, " + std::to_string(r.steps) + " steps), where the planar statics " +
               "stop: " + statics_failure;
}

}  // namespace

// The stages above, then the spins at rest (stage 6: bent between bending axes, Newton in 3D with the spins) and
// the checks every accepted start passes: at rest (accelerations and twist moments within the bounds from
// initial.tolerance) and stable (checkStable).
InitialState3 solveInitialState3(const Scene& scene, const Vec3& top, const StaticsProgress& progress) {
  const InitialKind kind = scene.initial.type;
  const StaticsPlane plane = staticsPlane(scene, top);
  double current_across = 0.0;
  bool principal = true;
  const Scene ps = planarScene(scene, plane, top, current_across, principal);
  const std::shared_ptr<Model> planar = buildModel(ps);
  if (kind == InitialKind::kStraight) return straightStart(scene, plane, *planar, inPlane(ps.top.position));

  InitialState3 init;
  init.plane_direction = Vec3(plane.u.x(), plane.u.y(), 0.0);
  // The rotated state must be an equilibrium of the 3D model: its accelerations at rest ~0 (the bound from
  // initial.tolerance: relaxation.h).
  const double W = planar->totalMass() * scene.gravity;
  init.acceleration_bound = restAccelerationBound(scene, *planar);
  int where = 0;
  bool relaxed_from_guess = false;
  try {
    planarEquilibrium(scene, plane, *planar, ps, top, progress, init);
  } catch (const std::runtime_error& e) {
    if (!relaxationMayReach(staticsProblem(ps), init.statics)) throw;
    relaxFromTheGuess(scene, plane, *planar, ps, top, e.what(), init);
    relaxed_from_guess = true;
  }
  init.max_acceleration = restAcceleration(scene, init.kin, init.end_force, top, where);
  if (!relaxed_from_guess) restIn3D(scene, plane, current_across, top, init, where);

  // The spins at rest (torsion on): a moment on a free spin is a residual as a force is, bounded as the 3D
  // statics' moment rows are, relative to weight x length (100x initial.tolerance, plus round-off).
  checkBendingAxis(scene, init.kin);
  init.twist_moment_bound = (100.0 * scene.initial.tolerance + 1e-12) * W * scene.length;
  int moment_where = 0;
  const auto atRest = [&] {
    init.max_acceleration =
        restAcceleration(*restModel3(scene, init.kin, init.end_force), scene.solver.stabilization, init.kin, top,
                         init.material_axes, where, init.max_twist_moment, moment_where, init.hang_off);
    return init.max_acceleration <= init.acceleration_bound && init.max_twist_moment <= init.twist_moment_bound;
  };
  // Stage 6. Bending axes: a line bent between them twists (and leaves the plane): Newton in 3D with the spins.
  if (!atRest() && scene.bending_axes.enabled) {
    const bool end_held = kind == InitialKind::kDisplaced && !plane.free_hang;
    detail::twistedEquilibrium(scene, end_held, top.head<2>() + scene.initial.end_offset, init);
    init.about += std::string("; ") + (principal ? "" : "bent between the bending axes: ") +
                  "then Newton in 3D with the spins (the line twists)";
    atRest();
  }
  if (!(init.max_acceleration <= init.acceleration_bound))
    throw std::runtime_error("initial: the " + std::string(name(kind)) +
                             " equilibrium rotated into 3D is not an "
                             "equilibrium of the 3D model: acceleration " +
                             fmt(init.max_acceleration) + " m/s^2 at rest at rfe " + std::to_string(where) +
                             " (bound " + fmt(init.acceleration_bound) + " m/s^2 from initial.tolerance)");
  if (!(init.max_twist_moment <= init.twist_moment_bound))
    throw std::runtime_error("initial: the " + std::string(name(kind)) + " equilibrium is not at rest in twist: " +
                             fmt(init.max_twist_moment) + " N m about rfe " + std::to_string(moment_where) +
                             "'s axis (bound " + fmt(init.twist_moment_bound) + " N m from initial.tolerance)");
  checkStable(scene, init, kind == InitialKind::kDisplaced && !plane.free_hang);
  return init;
}

}  // namespace spatial
}  // namespace riser_sim
