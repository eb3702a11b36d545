// Static equilibrium in 3D by dynamic relaxation, for what the planar statics cannot solve in one vertical
// plane (a current across it, a profile that veers with depth). From a guess at rest (the planar statics in
// a nearby plane), the scene's line in still water with its steady current, plus mass-proportional damping
// Q = -α M q' (every mode then decays at least at α/2, the lowest critically), is stepped by the structured
// generalized_alpha with ρ∞ = 0 (the stiff modes die in a step) until the accelerations at rest
// (restAcceleration, the builder's own check) are below the bound.
#pragma once
#include <cmath>
#include <string>

#include "riser_sim/scene/scene.h"
#include "riser_sim/planar/statics.h"
#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

struct Relaxed3 {
  Kinematics3 kin;                    // at rest
  AlignedVector<Vec3> material_axes;  // torsion on: each rfe's material axis 1 at rest (its spins)
  HangOff hang_off;                   // torsion on: the hang-off's twist frame it held (made at the guess)
  Vec3 end_force = Vec3::Zero();      // pinned: the anchor's force on the line's end at rest [N] (free: the given one)
  double acceleration = 0.0;          // largest at rest [m/s^2] (restAcceleration)
  double time = 0.0;                  // simulated [s]
  int steps = 0;
};

// The scene's equilibrium near `guess` with A_0 at top; a pinned bottom is held at bottom.position (the guess's
// points moved onto it along the arc length when its end is off it), a free one carries end_force [N] (a dead
// load). Torsion on: the spins start untwisted and relax too (the moments on them
// within moment_bound [N m]). Throws std::runtime_error("initial: ...") when it does not meet `bound` [m/s^2]
// within its time budget.
Relaxed3 relaxToRest(const Scene& scene, const Kinematics3& guess, const Vec3& top, double bound,
                     const Vec3& end_force = Vec3::Zero(), double moment_bound = INFINITY);

// The same from the planar statics' first guess (staticsFirstGuess) of `problem` for the planar model of the
// scene's line, placed in 3D by R and offset as fromPlanar does: every load at once, where the planar statics'
// continuations do not reach. Throws as relaxToRest.
Relaxed3 relaxFromFirstGuess(const Scene& scene, const Model& planar, const StaticsProblem& problem, const Mat3& R,
                             const Vec3& offset, const Vec3& top, double bound);

// The bound [m/s^2] on the accelerations at rest of a start of the scene (planar: its model `line`): the statics
// leave a residual force up to initial.tolerance x the weight W on a coordinate, on the lightest rfe (mass m_min) an
// acceleration of tolerance W / m_min; the bound allows 100x that (the residual spreads over the force, Δ and
// moment equations of an rfe), plus 1e-9 g of round-off.
double restAccelerationBound(const Scene& scene, const Model& line);

}  // namespace spatial
}  // namespace riser_sim
