// Static equilibria of the spatial line at rest, in the independent coordinates of IndependentFormulation3
// (Newton with the finite-difference stiffness of the terms' generalised forces): hanging from A_0 (a pinned
// end held), and a free end held horizontally by a force. Free or pinned bottom only.
#pragma once
#include "riser_sim/run/linear_stability.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

// Options of the statics and of the modes (modal.h).
struct ModalOptions3 {
  double fd_step = 1e-6;  // central-difference step: chart units (~rad) for u, x segment length for Δ
  // The statics: settle in a stable equilibrium. Plain Newton finds any (a line bent about its stiff axis is
  // one); with this each step's K is shifted by σ M until it is positive definite on the motions the ends allow
  // (Cholesky), σ = 0 near a stable equilibrium, and the one found is checked stable (else it throws).
  bool stable = false;
  // Torsion on: the hang-off's twist frame (torsion.h; not given: made at the guess's top rfe), as
  // Simulator3::reset takes it.
  HangOff hang_off;
};

// Static equilibrium of the line at rest hanging from A_0 = guess[0].A: Newton on Q_θ = 0 with the
// finite-difference K, from the guess's directions and Δ (its joints are closed from A_0); a pinned end held
// at bottomPoint() with its force as a multiplier. Throws std::runtime_error when it does not reach a residual
// of 1e-12 of the weight (and an end gap of 1e-12 of the length) in `iterations`.
// Torsion on, material_axes given: in, the guess's material axis 1 per rfe (its spins; empty: untwisted); out,
// the equilibrium's (torsion.h: frame-free). The hang-off's frame: options.hang_off, else made at the guess.
Kinematics3 equilibrium3(const Model3& model, const Kinematics3& guess, int iterations = 20,
                         const ModalOptions3& options = ModalOptions3(), AlignedVector<Vec3>* material_axes = nullptr);
// Static equilibrium of a free end whose horizontal position is held at `xy` [m] by a horizontal force: Newton
// on Q_θ + Φᵀ F = 0 with the gap E_xy - xy as a constraint and F = (F_x, F_y, 0) its multiplier (a dead load:
// its geometric stiffness in K), from `guess` and `force` (in: the first guess of F; out: F [N], the force on
// the line's end). Throws std::runtime_error when it does not reach a residual of 1e-12 of the weight and a
// gap of 1e-12 of the length in `iterations`.
Kinematics3 equilibriumHeldEnd3(const Model3& model, const Kinematics3& guess, const Vec2& xy, Vec3& force,
                                int iterations = 30, const ModalOptions3& options = ModalOptions3(),
                                AlignedVector<Vec3>* material_axes = nullptr);

// The stability of an equilibrium at rest (the statics' criterion, linear_stability.h) from the modes'
// linearisation (RestLine: K, M_θ, and C = -∂Q_θ/∂θ' of drag and damping): a pinned end held (its anchor force a
// dead load, the motions in the null space of Φ); a free end held horizontally where it is when `held_end` (the
// horizontal end force a dead load, end_force [N]); else free with end_force a dead load. The model: the scene's
// in still water (its steady current).
LinearStability stability3(const Model3& model, const Kinematics3& equilibrium, bool held_end,
                           const ModalOptions3& options = ModalOptions3(),
                           const AlignedVector<Vec3>* material_axes = nullptr);

}  // namespace spatial
}  // namespace riser_sim
