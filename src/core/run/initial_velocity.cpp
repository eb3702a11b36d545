// initial.velocity: the rigid motion given to a start (initial_velocity.h).
#include "riser_sim/run/initial_velocity.h"

#include <cmath>
#include <sstream>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/spatial/simulator.h"

namespace riser_sim {

namespace {

const char* const kRotationKey = "initial.velocity.rotation";
const char* const kTranslationKey = "initial.velocity.translation";

std::string format(double v) {
  std::ostringstream os;
  os.precision(9);
  os << v;
  return os.str();
}
std::string format(const Vec3& v) { return "(" + format(v.x()) + ", " + format(v.y()) + ", " + format(v.z()) + ")"; }

// u(p) = v + Ω e_z × (p - top) [m/s].
Vec3 rigidVelocity(const InitialSpec& spec, const Vec3& top, const Vec3& p) {
  return spec.translation + spec.rotation * Vec3::UnitZ().cross(p - top);
}

// Where the scene's holder is at t = 0 and how fast it moves, in 3D (planar (x, z_up) -> (x, 0, z)).
spatial::PointMotion3 holderAt0(const Scene& scene, const TopMotionSpec& spec) {
  if (scene.space == SpaceKind::kSpatial) return spatial::buildTopMotion3(spec)->at(0.0);
  const PointMotion m = buildTopMotion(spec)->at(0.0);
  spatial::PointMotion3 out;
  out.p = Vec3(m.p.x(), 0.0, m.p.y());
  out.v = Vec3(m.v.x(), 0.0, m.v.y());
  return out;
}

}  // namespace

void checkInitialVelocity(const Scene& scene) {
  const InitialSpec& spec = scene.initial;
  if (!spec.has_velocity) return;
  if (scene.space == SpaceKind::kPlanar && spec.rotation != 0.0)
    throw SceneError(kRotationKey,
                     "turns the line about the vertical, out of the vertical x-z plane of a planar scene "
                     "(space: planar, the default): only in-plane motions (initial.velocity.translation [vx, vz]) "
                     "are representable there; set space: spatial for a whirl");
  const Vec3& v = spec.translation;
  const double tol = 1e-9 * (1.0 + v.norm() + std::abs(spec.rotation) * scene.length);
  const spatial::PointMotion3 top = holderAt0(scene, scene.top);
  // A fixed top is carried along (runTopMotion); any other motion must already move the top at v.
  if (scene.top.type != MotionKind::kFixed && !((top.v - v).norm() <= tol))
    throw SceneError(kTranslationKey, "is " + format(v) + " m/s but top.motion (type " + name(scene.top.type) +
                                          ") moves the top at " + format(top.v) +
                                          " m/s at t = 0: the translation must be the hang-off's velocity there "
                                          "(a fixed top is carried along at the translation)");
  if (scene.bottom != BottomBoundary::kPinned) return;
  const spatial::PointMotion3 bottom =
      scene.space == SpaceKind::kSpatial ? holderAt0(scene, scene.bottom_motion) : spatial::PointMotion3{};
  const Vec3 p_bottom = scene.space == SpaceKind::kSpatial ? bottom.p : inSpace(inPlane(scene.bottom_point));
  const Vec3 u = rigidVelocity(spec, top.p, p_bottom);
  if (!((u - bottom.v).norm() <= tol)) {
    const std::string key = spec.rotation == 0.0 ? kTranslationKey : v.isZero() ? kRotationKey : "initial.velocity";
    throw SceneError(key, "moves the pinned bottom at " + format(u) + " m/s at t = 0 but bottom.motion moves it at " +
                              format(bottom.v) + " m/s: a velocity that contradicts a held end is refused");
  }
}

std::unique_ptr<TopMotion> runTopMotion(const Scene& scene) {
  const InitialSpec& spec = scene.initial;
  if (spec.has_velocity && scene.top.type == MotionKind::kFixed && !spec.translation.isZero())
    return std::make_unique<ConstantVelocityMotion>(inPlane(scene.top.position), inPlane(spec.translation));
  return buildTopMotion(scene.top);
}

std::unique_ptr<spatial::TopMotion3> runTopMotion3(const Scene& scene) {
  const InitialSpec& spec = scene.initial;
  if (spec.has_velocity && scene.top.type == MotionKind::kFixed && !spec.translation.isZero())
    return std::make_unique<spatial::ConstantVelocityMotion3>(scene.top.position, spec.translation);
  return spatial::buildTopMotion3(scene.top);
}

Kinematics withInitialVelocity(const InitialSpec& spec, const Kinematics& kin) {
  Kinematics out = kin;
  if (!spec.has_velocity) return out;
  const Vec2 v(spec.translation.x(), spec.translation.z());  // the loader refuses y and Ω in a planar scene
  for (BodyKinematics& b : out) b.A_dot += v;
  return out;
}

spatial::Kinematics3 withInitialVelocity3(const InitialSpec& spec, const Vec3& top, const spatial::Kinematics3& kin) {
  spatial::Kinematics3 out = kin;
  if (!spec.has_velocity) return out;
  const Vec3 w = spec.rotation * Vec3::UnitZ();
  for (spatial::BodyKinematics3& b : out) {
    b.A_dot += rigidVelocity(spec, top, b.A);
    b.e_dot += w.cross(b.e);
  }
  return out;
}

void setInitialSpinRates(const InitialSpec& spec, spatial::Simulator3& sim) {
  const int nt = sim.formulation().twistDofs();
  if (!spec.has_velocity || spec.rotation == 0.0 || nt == 0) return;
  const int nq = sim.model().dofs(), p = sim.formulation().positionSize();
  spatial::Kinematics3 kin(sim.model().bodies());
  sim.kinematics(kin);
  const VecX theta = sim.state().segment(nq, nt);
  VecX omega = sim.state().segment(p + nq, nt);
  for (int i = 0; i < nt; ++i) omega[i] += spec.rotation * kin[i].e.z();  // Ω e_z·e_i
  sim.setTwist(theta, omega);                                             // a held rfe 0 stays held
}

std::string initialVelocityAbout(const InitialSpec& spec) {
  if (!spec.has_velocity) return "";
  return "; moving at t = 0 (initial.velocity: rotation " + format(spec.rotation) + " rad/s about the vertical " +
         "through the top, translation " + format(spec.translation) + " m/s)";
}

}  // namespace riser_sim
