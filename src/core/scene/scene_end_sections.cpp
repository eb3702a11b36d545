// Scene sections for the line's ends: top (position, motion, flex joint, torsion) and bottom (free, pinned,
// driven), called from parseScene's table (scene_sections.cpp). Errors name the full key path.
#include <cmath>
#include <string>
#include <vector>

#include "scene_section.h"

namespace riser_sim {
namespace scene_detail {

namespace {

void parseKnots(const Section& motion, TopMotionSpec& top, bool planar) {
  const std::string key = motion.key("knots");
  const YAML::Node knots = motion.at("knots");
  if (!knots.IsSequence() || knots.size() == 0)
    throw SceneError(key, "expected a non-empty list of [t, [vx, vz]] or [t, [vx, vy, vz]], got " + describe(knots));
  top.knots.clear();
  for (size_t i = 0; i < knots.size(); ++i) {
    const std::string k = key + "[" + std::to_string(i) + "]";
    const YAML::Node knot = knots[i];
    if (!knot.IsSequence() || knot.size() != 2)
      throw SceneError(k, "expected [t, [vx, vz]] or [t, [vx, vy, vz]], got " + describe(knot));
    const double t = toNumber(knot[0], k + "[0]");
    if (i > 0 && !(t > top.knots.back().t))
      throw SceneError(
          k, "knot times must increase, got " + formatNumber(t) + " after " + formatNumber(top.knots.back().t));
    const Eigen::Vector3d v = toVec3(knot[1], k + "[1]", planar);
    top.knots.push_back({t, v});
  }
}

// A phase: one number for every axis, or [p1, p2, p3] (3D only).
Eigen::Vector3d parsePhase(const Section& motion, const std::string& k, bool planar) {
  if (!motion.has(k) || !motion.at(k).IsSequence()) return Eigen::Vector3d::Constant(motion.number(k, 0.0));
  const std::string key = motion.key(k);
  const YAML::Node ph = motion.at(k);
  if (planar)
    throw SceneError(key, "a phase per axis [px, py, pz] needs space: spatial (a planar sinusoid has one phase)");
  if (ph.size() != 3) throw SceneError(key, "expected a number or [px, py, pz], got " + describe(ph));
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) p[i] = toNumber(ph[i], key + "[" + std::to_string(i) + "]");
  return p;
}

// top.motion.attitude [deg] (roll, pitch, yaw amplitudes of the holder) and attitude_phase: sinusoid, 3D only.
void parseAttitude(const Section& motion, TopMotionSpec& spec, bool planar) {
  if (!motion.has("attitude")) {
    if (motion.has("attitude_phase"))
      throw SceneError(motion.key("attitude_phase"), "needs attitude: [roll, pitch, yaw] (the phase of its sinusoid)");
    return;
  }
  const std::string key = motion.key("attitude");
  if (planar) throw SceneError(key, "needs space: spatial (the planar holder does not turn)");
  if (spec.type != MotionKind::kSinusoid) throw SceneError(key, "only with type: sinusoid (it shares its period)");
  const YAML::Node a = motion.at("attitude");
  if (!a.IsSequence() || a.size() != 3)
    throw SceneError(key, "expected [roll, pitch, yaw] in degrees, got " + describe(a));
  for (int i = 0; i < 3; ++i) spec.attitude[i] = toNumber(a[i], key + "[" + std::to_string(i) + "]") * M_PI / 180.0;
  if (!(std::abs(spec.attitude[1]) < 0.5 * M_PI))
    throw SceneError(key + "[1]", "the pitch amplitude must be below 90 degrees (Z-Y-X angles), got " +
                                      formatNumber(spec.attitude[1] * 180.0 / M_PI));
  spec.attitude_phase = parsePhase(motion, "attitude_phase", planar);
}

// top.motion or bottom.motion (the same keys): spec.position is set by the caller.
void parseMotion(const Section& motion, TopMotionSpec& spec, bool planar) {
  spec.type = motion.choice("type", MotionKind::kFixed);
  // Keys of the other motion types are type-checked but ignored (so --set top.motion.type=... just works).
  const bool sinusoid = spec.type == MotionKind::kSinusoid;
  spec.amplitude =
      sinusoid ? motion.vec3("amplitude", planar) : motion.vec3("amplitude", planar, Eigen::Vector3d::Zero());
  spec.period = sinusoid ? motion.number("period") : motion.number("period", 1.0);
  requirePositive(motion.key("period"), spec.period);
  spec.phase = parsePhase(motion, "phase", planar);
  parseAttitude(motion, spec, planar);
  if (spec.type == MotionKind::kVelocityProfile || motion.has("knots")) parseKnots(motion, spec, planar);
}

// top.flex_joint / bottom.flex_joint: 3D only.
FlexJointSpec parseFlexJoint(const Section& end, bool planar) {
  FlexJointSpec j;
  if (!end.has("flex_joint")) return j;
  const Section fj =
      end.section("flex_joint", {"stiffness", "damping", "axis", "torsional_stiffness", "torsional_damping"});
  if (planar) throw SceneError(end.key("flex_joint"), "needs space: spatial (the planar core has pinned ends only)");
  j.enabled = true;
  j.stiffness = fj.number("stiffness");
  requirePositive(fj.key("stiffness"), j.stiffness);
  j.damping = fj.number("damping", 0.0);
  requireNonNegative(fj.key("damping"), j.damping);
  if (fj.has("torsional_stiffness")) {  // checked against the ends and line.torsion by the callers
    j.torsional_stiffness = fj.number("torsional_stiffness");
    requirePositive(fj.key("torsional_stiffness"), j.torsional_stiffness);
  }
  if (fj.has("torsional_damping")) {
    if (!fj.has("torsional_stiffness"))
      throw SceneError(fj.key("torsional_damping"), "needs torsional_stiffness (the damper acts beside its spring)");
    j.torsional_damping = fj.number("torsional_damping");
    requireNonNegative(fj.key("torsional_damping"), j.torsional_damping);
  }
  j.has_axis = fj.has("axis");
  if (j.has_axis) {
    const YAML::Node a = fj.at("axis");
    if (!a.IsSequence() || a.size() != 3) throw SceneError(fj.key("axis"), "expected [x, y, z], got " + describe(a));
    for (int k = 0; k < 3; ++k) j.axis[k] = toNumber(a[k], fj.key("axis") + "[" + std::to_string(k) + "]");
    if (!(j.axis.norm() > 0.0)) throw SceneError(fj.key("axis"), "must be a non-zero vector");
    j.axis.normalize();
  }
  return j;
}

}  // namespace

void parseTop(const Section& root, Scene& s) {
  const bool planar = s.space == SpaceKind::kPlanar;
  const Section top = root.section("top", {"position", "motion", "flex_joint", "torsion"});
  s.top = TopMotionSpec();
  s.top.position = top.vec3("position", planar, Eigen::Vector3d::Zero());
  parseMotion(top.section("motion", {"type", "amplitude", "period", "phase", "knots", "attitude", "attitude_phase"}),
              s.top, planar);
  s.top_flex_joint = parseFlexJoint(top, planar);
  if (top.has("torsion")) {  // the hang-off's hold on the spin (line.torsion)
    if (!s.torsion.enabled)
      throw SceneError(top.key("torsion"), "needs line.torsion (the spin is no degree of freedom)");
    s.torsion.free_top = top.choice("torsion", "fixed", {"fixed", "free"}) == "free";
  }
  if (s.top_flex_joint.torsional_stiffness > 0.0) {
    const std::string key = "top.flex_joint.torsional_stiffness";
    if (!s.torsion.enabled) throw SceneError(key, "needs line.torsion (the spin is no degree of freedom)");
    if (s.torsion.free_top) throw SceneError(key, "contradicts top.torsion: free (a spring holds the spin)");
  }
}

void parseBottom(const Section& root, Scene& s) {
  const Section bottom = root.section("bottom", {"type", "position", "motion", "flex_joint"});
  const std::string type = bottom.choice("type", "free", {"free", "pinned"});
  s.bottom = type == "pinned" ? BottomBoundary::kPinned : BottomBoundary::kFree;
  const bool planar = s.space == SpaceKind::kPlanar;
  s.bottom_point = s.bottom == BottomBoundary::kPinned ? bottom.vec3("position", planar)
                                                       : bottom.vec3("position", planar, Eigen::Vector3d::Zero());
  s.bottom_motion = TopMotionSpec();
  s.bottom_motion.position = s.bottom_point;
  const bool pinned = s.bottom == BottomBoundary::kPinned;
  for (const char* k : {"motion", "flex_joint"})
    if (bottom.has(k) && !pinned)
      throw SceneError(bottom.key(k), "needs bottom.type: pinned (a free bottom has no joint to move or stiffen)");
  if (bottom.has("motion")) {
    const Section motion =
        bottom.section("motion", {"type", "amplitude", "period", "phase", "knots", "attitude", "attitude_phase"});
    parseMotion(motion, s.bottom_motion, planar);
    if (planar && s.bottom_motion.type != MotionKind::kFixed)
      throw SceneError(motion.key("type"), "needs space: spatial (the planar core pins the bottom at a fixed point)");
  }
  s.bottom_flex_joint = parseFlexJoint(bottom, planar);
  if (s.bottom_flex_joint.torsional_stiffness > 0.0)
    throw SceneError("bottom.flex_joint.torsional_stiffness", "top only (the bottom is free in twist)");
}

}  // namespace scene_detail
}  // namespace riser_sim
