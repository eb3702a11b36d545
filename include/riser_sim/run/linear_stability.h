// Stability of an equilibrium from its linearisation M θ'' + C θ' + K θ = 0 in independent coordinates (the
// planar and the 3D statics' stability check; K and C need not be symmetric: a current's drag gives a
// non-symmetric stiffness, its dependence on the line's velocity a damping).
//
// Unstable when the first-order system [[0, I], [-M⁻¹K, -M⁻¹C]] has an eigenvalue λ with Re λ above the noise
// bound: a real one is a divergence, a complex pair a flutter. Solved mass-normalised (θ = L⁻ᵀ z, M = L Lᵀ)
// with the positions scaled by ω_ref (the system's norm ~ its largest frequency), a dense O(p³) eigen-solve of
// size 2p. Without asymmetry beyond the noise (no current) and with C's symmetric part positive semi-definite,
// the test is Cholesky of K's symmetric part (stable iff it is positive definite: the energy argument).
#pragma once
#include <string>

#include "riser_sim/types.h"

namespace riser_sim {

struct LinearStability {
  bool stable = true;
  double growth = 0.0;           // largest Re λ [1/s] (the first-order path) or -(lowest ω² of K_sym) [1/s²]
  double bound = 0.0;            // noise bound on growth, same unit
  double frequency = 0.0;        // |Im λ| of the worst eigenvalue [rad/s]: 0 a divergence, > 0 a flutter
  int unstable = 0;              // eigenvalues beyond the bound
  int size = 0;                  // p: the dofs of the problem (after the end conditions)
  bool first_order = false;      // the 2p eigen-solve was needed (asymmetric K, or C not semi-definite)
  bool reduced = false;          // p > kDenseStabilityLimit: solved in the lowest modes' subspace (see .cpp)
  std::string describe() const;  // "the equilibrium is unstable: ..." ("" when stable)
};

// Above this p the first-order eigen-solve is done in the subspace of the kReducedModes lowest undamped modes
// of (K_sym, M) (the divergence of K_sym is still tested on every coordinate by Cholesky).
constexpr int kDenseStabilityLimit = 500;
constexpr int kReducedModes = 200;

// K, C, M: p x p in the coordinates θ (C may be empty: undamped); N: an orthonormal basis (columns) of the motions
// the end conditions allow, or empty (all). noise: the relative finite-difference noise of K's entries.
LinearStability linearStability(const MatX& K, const MatX& C, const MatX& M, const MatX& N, double noise);

}  // namespace riser_sim
