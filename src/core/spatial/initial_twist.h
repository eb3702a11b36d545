// The initial state of a line with bending axes bent between them (internal to initial_state.cpp).
#pragma once
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace spatial {
namespace detail {

// The planar statics' EI for a line with bending axes: a bend in the plane (normal `normal`) is about the normal:
// EI_1 when axis 1 is that normal, EI_2 when it lies in the plane, else the mean (a guess that twistedEquilibrium
// finishes). `principal` tells which of the first two.
double planarBendingStiffness(const Scene& scene, const Vec3& normal, bool& principal);

// The stable equilibrium with the spins near init.kin: dynamic relaxation (relaxation.h; spins from untwisted),
// then Newton in 3D (statics.h) on the still-water model, the end held at xy by a horizontal force (held_end:
// init.end_force in and out) or loaded by init.end_force (a free end) or pinned at bottom.position; the hang-off's
// frame re-made at each solution's top rfe until it stays (its move is second order in the top rfe's turn
// between passes). Sets init.kin, init.material_axes (and init.end_force). Throws std::runtime_error("initial:
// ...") when either fails or the frame does not settle in 6 passes. Needs init.acceleration_bound and
// init.twist_moment_bound.
void twistedEquilibrium(const Scene& scene, bool held_end, const Vec2& xy, InitialState3& init);

}  // namespace detail
}  // namespace spatial
}  // namespace riser_sim
