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

// The stable equilibrium with the spins near init.kin: Newton in 3D (statics.h, kept to a stable equilibrium) on
// the still-water model, the end held at xy by a horizontal force (held_end: init.end_force in and out) or loaded
// by init.end_force (a free end) or pinned at bottom.position. The hang-off's twist frame is made at init.kin's
// top rfe (line.bending_axis across it, the joint's axis along it) and kept. Sets init.kin, init.material_axes,
// init.hang_off (and init.end_force). Throws std::runtime_error("initial: ...") when Newton fails.
void twistedEquilibrium(const Scene& scene, bool held_end, const Vec2& xy, InitialState3& init);

}  // namespace detail
}  // namespace spatial
}  // namespace riser_sim
