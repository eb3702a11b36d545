// Linearised force terms for the implicit integrators' structured (O(n)) solves. In the rfes' absolute
// coordinates q_i = [x_i, y_i, Δ_i, φ_i]: K = -∂Q/∂q [N/m, N, N m/rad], C = -∂Q/∂q' [N s/m, ...], stored
// block-tridiagonally: diag[i] = rfe i with itself, sub[i] = rows of rfe i, columns of rfe i-1 (i >= 1).
// Blocks are symmetric in the sense K(i-1, i) = sub[i]^T.
#pragma once
#include "riser_sim/planar/kinematics.h"

namespace riser_sim {

struct StiffnessBlocks {
  AlignedVector<Mat4> K_diag, K_sub, C_diag, C_sub;
  void resize(int bodies) {
    for (auto* v : {&K_diag, &K_sub, &C_diag, &C_sub}) v->assign(bodies, Mat4::Zero());
  }
  void setZero() {
    for (auto* v : {&K_diag, &K_sub, &C_diag, &C_sub})
      for (Mat4& m : *v) m.setZero();
  }
};

// Adds the linearisation of a force F [N] applied at distance s = s0 + kappa*Δ from A_i on rfe i, with
// ∂F/∂p = -Kp and ∂F/∂p' = -Cp (2x2, world axes), to rfe i's diagonal blocks: P^T Kp P plus the
// geometric part of F itself (P = ∂p/∂q_i = [I, kappa e, s n] changes with Δ and φ).
inline void addPointStiffness(const BodyKinematics& b, double s0, double kappa, const Vec2& F, const Mat2& Kp,
                              const Mat2& Cp, Mat4& K, Mat4& C) {
  const double s = s0 + kappa * b.delta;
  Mat24 P;
  P << 1.0, 0.0, kappa * b.c, -s * b.s,  //
      0.0, 1.0, kappa * b.s, s * b.c;
  K.noalias() += P.transpose() * Kp * P;
  C.noalias() += P.transpose() * Cp * P;
  const double nF = b.nrm().dot(F), eF = b.e().dot(F);
  K(kDelta, kPhi) -= kappa * nF;
  K(kPhi, kDelta) -= kappa * nF;
  K(kPhi, kPhi) += s * eF;
}

}  // namespace riser_sim
