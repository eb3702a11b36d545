// Modal analysis about a static equilibrium: natural periods and mode shapes of the RFEM
// model linearised in the independent coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] (Δ dropped when the
// line is inextensible), with A_0 held at its static position.
//
//   M_II θ'' + K θ = 0,   K = -∂Q_θ/∂θ,   Q_θ = J^T Q_abs,   M_II = J^T M J.
//
// - K: central finite differences of the generalised forces of every force term of the model in a
//   steady sea, as the statics see it (springs, gravity, buoyancy, seabed, current drag at rest,
//   internal-flow centrifugal part; no waves, the current at its velocity at ModalOptions::time), so
//   geometric stiffness (tension, weight) comes in through J(θ). The seabed's tangential anchors are
//   placed at the static contact points (sticking contact). K is symmetrised; the dropped
//   antisymmetric part (follower loads such as current drag) is reported as `asymmetry`.
// - M_II: the dense mass matrix of IndependentFormulation (rigid parts, internal fluid, added mass).
// - Left out: every velocity-proportional force (Morison drag, structural damping, internal-flow
//   Coriolis terms): the modes are undamped.
// - The end force that held the static state (StaticsResult::end_force: the horizontal force of a
//   'displaced' state, the anchor reaction of 'between_points') stays applied as a dead load.
// - Pinned bottom: the two linearised end constraints C θ = 0 are enforced by projecting onto an
//   orthonormal null-space basis N of C (K_red = N^T K N, M_red = N^T M N); with the anchor reaction
//   applied as a dead load, K contains the constraint-curvature term λ·∂²E/∂θ².
// - Solve: dense Eigen::GeneralizedSelfAdjointEigenSolver, O(n³): fine for n up to a few hundred
//   (n = 200: about a second). The banded structure is not used.
#pragma once
#include <string>
#include <vector>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"
#include "riser_sim/planar/statics.h"

namespace riser_sim {

struct Scene;

struct ModalOptions {
  int modes = 10;         // how many of the lowest modes to return (clamped to the number of dofs)
  double fd_step = 1e-6;  // central-difference step: rad for φ, × segment length for Δ
  double time = 0.0;      // t [s] at which the forces are evaluated
};

struct Mode {
  double omega2 = 0.0;     // ω² [1/s²]; < 0: the state is unstable in this direction
  double omega = 0.0;      // [rad/s], 0 when ω² <= 0
  double frequency = 0.0;  // [Hz]
  double period = 0.0;     // [s], 0 when ω == 0 (no oscillation)
  // Share of the mode's kinetic energy (rigid parts) moving along the line, 0..1.
  double axial_fraction = 0.0;
  std::string character;  // "axial" (axial_fraction > 0.5) or "transverse"
  VecX theta;             // mode in θ, mass-normalised: θ^T M_II θ = 1
  // Displacements of A_0..A_n and of the end point (n+2), scaled so that the largest is 1 (unitless)
  // and its x (or y) component is positive.
  AlignedVector<Vec2> displacement;
};

struct ModalResult {
  std::vector<double> arc_length;     // unstretched arc length of A_0..A_n, end [m] (n+2)
  AlignedVector<Vec2> points;         // equilibrium positions of A_0..A_n, end [m]
  std::vector<Mode> modes;            // lowest first
  int coordinates = 0;                // size of θ
  int dofs = 0;                       // size of the eigenproblem (coordinates - 2 when pinned)
  bool pinned = false;                // the two end constraints were applied
  double equilibrium_residual = 0.0;  // max |Q_θ| (with the end load) / force scale: ~0 at equilibrium
  double asymmetry = 0.0;             // ||K - K^T||_F / ||K||_F before symmetrisation
  MatX stiffness, mass;               // the (reduced) K and M of the eigenproblem
};

// Modes about `equilibrium` (zero velocities; A_0 = equilibrium[0].A) with `end_force` [N] applied at
// the end of rfe n as a dead load. Throws std::invalid_argument on a bad option, std::runtime_error when
// the eigen-solve fails (e.g. a singular end-constraint Jacobian).
ModalResult computeModes(const Model& model, const Kinematics& equilibrium, const Vec2& end_force,
                         const ModalOptions& options = ModalOptions());

// Statics of the scene's initial state (its end force kept as a dead load; the hanging equilibrium for
// initial.type straight, which is none), then the modes.
// Throws std::runtime_error when the statics do not converge.
ModalResult sceneModes(const Scene& scene, const ModalOptions& options, StaticsResult* statics = nullptr);

}  // namespace riser_sim
