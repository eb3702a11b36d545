// O(n) solves with the implicit integrators' matrix for the chain coordinates θ = [u_0 … u_n],
// u_i = (Δ_i, φ_i) (or φ_i alone for an inextensible line):
//   W = M_θ + c C_θ + c² K_θ,   M_θ = Jᵀ M J,  C_θ = Jᵀ C J,  K_θ = Jᵀ K J + K_g,
// where J maps θ' to the rfes' absolute velocities q'_i = (A'_i, u'_i), M, K, C are block-tridiagonal in
// absolute coordinates (mass blocks, ForceTerm::addStiffness) and K_g is the geometric stiffness of the
// chain: the force λ_{i+1} that rfes i+1..n exert on rfe i at its end turns with φ_i and moves with Δ_i,
//   K_g,i = -λ_{i+1} · ∂²(A_{i+1} - A_i)/∂u_i² = [[0, -λ·n_i], [-λ·n_i, (l_i+Δ_i) λ·e_i]].
// Since λ carries the inertia of the rfes below, K_θ is the exact Jacobian of the accelerations at rest
// for every term that reports its stiffness.
//
// W x = r is the stationarity condition of ½ xᵀ W x - rᵀ x; with stage i's input z_i = q_{i-1}
// (rfe i-1's absolute coordinates) the chain is a discrete-time LQ problem, q_i = E_i z_i + F u_i, solved
// by a backward Riccati sweep (value ½ zᵀ S_i z + s_iᵀ z) and a forward sweep. A pinned bottom adds the
// multiplier μ of the end condition G x = g (G = ∂A_{n+1}/∂θ, g given per solve), affine in every stage
// (one 2x2 solve). Workspaces are sized in the constructor; factor() and solve() allocate nothing.
#pragma once
#include "riser_sim/planar/model.h"
#include "riser_sim/planar/stiffness.h"

namespace riser_sim {

class ChainShiftedSolver {
 public:
  ChainShiftedSolver(const Model& model, int dofs_per_rfe);

  // Linearisation at one state: kinematics, absolute mass blocks, term stiffness, and the joint forces
  // λ_k (force on rfe k-1 at its end, k = 0..n+1; Reactions::joint). Kept by reference until factor().
  void setLinearization(const Kinematics& kin, const AlignedVector<Mat4>& M, const StiffnessBlocks& S,
                        const AlignedVector<Vec2>& joint);
  // Backward Riccati sweep for W = M_θ + c C_θ + c² K_θ.
  void factor(double c);
  // x = W^-1 r (size p = k (n+1)); pinned bottom: x = W^-1 (r + Gᵀ μ) with G x = end.
  void solve(const VecX& r, VecX& x, const Vec2& end = Vec2::Zero());
  // G w = ∂A_{n+1}/∂θ w: the end's displacement (or velocity) for chain increments (rates) w.
  Vec2 endMotion(const Eigen::Ref<const VecX>& w) const;
  // y = M_θ a - c K_θ b (the right-hand side of the shifted system), size p.
  void massMinusStiffness(const Eigen::Ref<const VecX>& a, const Eigen::Ref<const VecX>& b, double c, VecX& y);

 private:
  struct Stage {
    Mat4 E;     // q_i = E z_i + F u_i
    Mat2 Rinv;  // (k x k used)
    Mat24 RN;   // R^-1 N (k x 4 used)
    Mat42 T;    // ∂s_i/∂μ (pinned)
    Mat2 Um;    // ∂u_i/∂μ (k x 2 used, pinned)
    Vec2 gu;    // per solve: R^-1 (F^T s_{i+1} - r_i)
    Vec2 x;     // per solve: u_i before the pinned correction
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  };
  Vec4 lift(const Vec2& u) const;  // F u
  Vec2 drop(const Vec4& q) const;  // F^T q
  Mat2 geometric(int i) const;     // K_g,i (k x k used)
  // Absolute velocities q'_i of every rfe for chain rates w (A'_0 = 0) into q_.
  void toAbsolute(const Eigen::Ref<const VecX>& w);

  const int k_, nb_;
  const bool pinned_;
  const Kinematics* kin_ = nullptr;
  const AlignedVector<Mat4>* M_ = nullptr;
  const StiffnessBlocks* S_ = nullptr;
  const AlignedVector<Vec2>* joint_ = nullptr;
  AlignedVector<Stage> st_;
  AlignedVector<Vec4> q_, q2_, f_;
  Mat2 Sm_inv_ = Mat2::Identity();  // (∂A_{n+1}/∂μ)^-1
};

}  // namespace riser_sim
