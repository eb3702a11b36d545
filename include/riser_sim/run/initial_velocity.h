// initial.velocity (InitialSpec, scene.h): a rigid motion of the whole line at t = 0, given to the velocity part of
// either engine's start after its statics or straight line (the positions are unchanged). A point p of the line
// moves at
//   u(p) = v + Ω e_z × (p - p_top),
// Ω the rotation about the vertical through the top [rad/s] (counter-clockwise seen from above), v the translation
// [m/s]. Each rfe gets the rigid body's velocity: 3D Ȧ_i = u(A_i), ė_i = Ω e_z × e_i, Δ̇_i = 0, and with
// line.torsion each free spin the rate Ω e_z·e_i (a spin held by the hang-off follows it); planar Ȧ_i = v,
// φ̇_i = Δ̇_i = 0 (a rotation about the vertical leaves the plane: refused).
// The holders: the top is on the axis, so the rotation leaves it in place. A translation carries the top with it:
// a fixed top moves at v from top.position (p(t) = position + v t); any other top motion must move the top at v at
// t = 0. A pinned bottom must move at u(p_bottom) at t = 0 (a fixed one: u = 0 there). A velocity that contradicts a
// held end is refused naming the key. Without initial.velocity none of this runs.
#pragma once
#include <memory>
#include <string>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {
class Simulator3;
}

using Vec3 = Eigen::Vector3d;

// Throws SceneError naming initial.velocity.rotation / .translation (or initial.velocity) when the velocity cannot
// be represented (a rotation in a planar scene) or contradicts a held end (see above). No-op without the key.
void checkInitialVelocity(const Scene& scene);

// The top's motion of a run of the scene: buildTopMotion(3)(scene.top), or for a fixed top with a translation the
// constant-velocity motion from top.position.
std::unique_ptr<TopMotion> runTopMotion(const Scene& scene);
std::unique_ptr<spatial::TopMotion3> runTopMotion3(const Scene& scene);

// kin (a start at rest) with the rigid motion's velocities added; kin itself without initial.velocity.
Kinematics withInitialVelocity(const InitialSpec& spec, const Kinematics& kin);
spatial::Kinematics3 withInitialVelocity3(const InitialSpec& spec, const Vec3& top, const spatial::Kinematics3& kin);
// line.torsion on and a rotation: the free spins' rates Ω e_z·e_i in sim's state (its angles kept). Else no-op.
void setInitialSpinRates(const InitialSpec& spec, spatial::Simulator3& sim);

// "" without initial.velocity; else "; moving at t = 0 (initial.velocity: ...)" for the start's description.
std::string initialVelocityAbout(const InitialSpec& spec);

}  // namespace riser_sim
