// Linearised spatial force terms for the implicit integrators' structured (O(n)) solves, in natural
// coordinates q_i = [A_i, Δ_i, e_i]: K = -∂Q/∂q, C = -∂Q/∂q' (units of Q per unit of q, q'), stored
// block-tridiagonally: diag[i] = rfe i with itself (7x7), sub[i] = rows of rfe i, columns of rfe i-1 (i >= 1),
// and K(i-1, i) = K_sub[i]ᵀ + K_sup[i] (K_sup: the non-symmetric part, e.g. of damping torques; C is
// symmetric). Neighbours couple through their directors only (bending): the sub blocks are the e-e 3x3.
#pragma once
#include "riser_sim/spatial/kinematics.h"

namespace riser_sim {
namespace spatial {

using Mat7 = Eigen::Matrix<double, 7, 7>;

struct Stiffness3 {
  AlignedVector<Mat7> K_diag, C_diag;
  AlignedVector<Mat3> K_sub, K_sup, C_sub;  // e-e
  void resize(int bodies) {
    for (auto* v : {&K_diag, &C_diag}) v->assign(bodies, Mat7::Zero());
    for (auto* v : {&K_sub, &K_sup, &C_sub}) v->assign(bodies, Mat3::Zero());
  }
  void setZero() {
    for (auto* v : {&K_diag, &C_diag})
      for (Mat7& m : *v) m.setZero();
    for (auto* v : {&K_sub, &K_sup, &C_sub})
      for (Mat3& m : *v) m.setZero();
  }
};

}  // namespace spatial
}  // namespace riser_sim
