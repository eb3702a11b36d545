// Small oscillations of the spatial line about a static equilibrium, in the independent coordinates of
// IndependentFormulation3 (charts centred on the equilibrium directors, so θ* = [Δ*, 0, 0, ...]) with A_0
// held at its static position:
//   M_θ(θ*) θ'' + K θ = 0,   K = -∂Q_θ/∂θ (central differences of the terms' generalised forces at rest,
//   symmetrised; the dropped antisymmetric part is reported),
// solved by Eigen's dense GeneralizedSelfAdjointEigenSolver, O(n³). Velocity-proportional forces
// (damping) are left out: the modes are undamped. Free bottom only (as IndependentFormulation3).
// A line hanging straight down has its transverse modes in degenerate pairs (the two planes across the
// vertical) at the planar frequencies, and its axial modes once each.
// Torsion on: the spin angles φ_i are coordinates too (the twist's stiffness and the polar inertia in K and
// M_θ); the torsional modes are those with most of θᵀ M_θ θ in them. A line straight at rest has them apart
// from the bending modes; a curved one couples them through the reference twist.
#pragma once
#include <vector>

#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/statics.h"  // ModalOptions3; the equilibria the modes are about

namespace riser_sim {
namespace spatial {

struct Mode3 {
  double omega2 = 0.0;            // ω² [1/s²]; < 0: unstable in this direction
  double omega = 0.0;             // [rad/s], 0 when ω² <= 0
  double axial_fraction = 0.0;    // share of θᵀ M θ in the Δ coordinates, 0..1
  bool axial = false;             // axial_fraction > 0.5
  double torsion_fraction = 0.0;  // share of θᵀ M θ in the spin angles (torsion on), 0..1
  bool torsional = false;         // torsion_fraction > 0.5
  // Share of the mode's kinetic energy (rigid parts) moving along the line, 0..1: the planar
  // Mode::axial_fraction (what the CLI's table prints as the axial share).
  double along_fraction = 0.0;
  VecX theta;  // mass-normalised: θᵀ M_θ θ = 1
  // Displacements of A_0..A_n and the end per unit of this θ [m] (central difference of the positions along
  // θ, step fd_step: linear to its square); A_0 is held, so its entry is 0.
  AlignedVector<Vec3> displacement;
};

struct ModalResult3 {
  Kinematics3 equilibrium;            // the state the modes are about
  std::vector<Mode3> modes;           // every mode, lowest first
  double equilibrium_residual = 0.0;  // max |Q_θ| / (total weight x length): ~0 at equilibrium
  double asymmetry = 0.0;             // ||K - Kᵀ||_F / ||K||_F before symmetrisation
  MatX stiffness, mass;
};

// Modes about `equilibrium` (zero velocities); a pinned end held (the modes in the null space of its Jacobian,
// the anchor's force a dead load). Throws std::runtime_error when the eigen-solve fails.
// material_axes (torsion on, given and not empty): the equilibrium's spins as each rfe's material axis 1 (a line
// twisted by bending axes, statics.h); else untwisted.
ModalResult3 computeModes3(const Model3& model, const Kinematics3& equilibrium,
                           const ModalOptions3& options = ModalOptions3(),
                           const AlignedVector<Vec3>* material_axes = nullptr);

}  // namespace spatial
}  // namespace riser_sim
