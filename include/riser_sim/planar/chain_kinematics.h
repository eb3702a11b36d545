// The line as a serial chain hanging from A_0 in independent coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n]
// (k = 2 per rfe) or [φ_0, …, φ_n] (k = 1: inextensible line, Δ = 0), A_{i+1} = A_i + (l_i + Δ_i) e(φ_i).
// One copy of the chain's forward kinematics and of Jᵀ (absolute generalised forces to chain ones), shared by
// the chain formulations, the statics and the modal analysis.
#pragma once
#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {

// Coordinates per rfe: 2 (Δ, φ) or 1 (φ) for an inextensible line.
inline int chainDofsPerRfe(const Model& model) { return model.options().axial_flexibility ? 2 : 1; }

// Kinematics of every rfe for θ (k (n+1) entries) and its rates θ' (null: at rest), A_0 at `top` moving
// with `top_velocity`.
void chainKinematics(const Model& model, const Vec2& top, const Vec2& top_velocity, const double* theta,
                     const double* theta_dot, Kinematics& kin);

// Q_θ = Jᵀ Q (k (n+1) entries) for absolute generalised forces Q (4 per rfe) at the chain's kinematics:
// Δ_j and φ_j move every rfe beyond rfe j rigidly by e_j and (l_j + Δ_j) n_j.
void projectToChain(const Model& model, const Kinematics& kin, const double* Q, double* Qt);

}  // namespace riser_sim
