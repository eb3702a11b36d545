// What a 3D mode is, for the tables of riser_sim_cli --modes and the node's ~modes: its character (axial,
// torsional, in-plane or out-of-plane relative to the statics' vertical plane), and degenerate pairs turned so
// one lies in that plane and the other across it.
#pragma once
#include <vector>

#include "riser_sim/spatial/modal.h"

namespace riser_sim {
namespace spatial {

constexpr double kZeroOmega2 = 1e-12;    // ω² below this share of the largest: no oscillation (as the planar table)
constexpr double kPairTolerance = 1e-6;  // relative ω² gap of a degenerate pair

// "torsional" (most of θᵀ M θ in the spins), "axial" (most of the kinetic energy along the line), else
// "out-of-plane" when most of Σ|d_p|² is along the plane's normal n, "in-plane" otherwise.
const char* modeCharacter(const Mode3& m, const Vec3& n);

// A degenerate pair (bending, ω² within kPairTolerance) spans a plane of shapes and any M-orthonormal rotation of
// it is as good: each is rotated (θ and displacements) onto the eigenvectors of the out-of-plane form, least out
// of the plane first. `modes` lowest first.
void alignDegeneratePairs(std::vector<Mode3>& modes, const Vec3& n);

}  // namespace spatial
}  // namespace riser_sim
