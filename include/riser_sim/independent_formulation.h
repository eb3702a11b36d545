// Paper section 2.2: independent coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] with the full mass matrix
// M_II = J^T M J (J: θ' → absolute velocities q'_i of every rfe) and a dense LDLT solve, as the paper
// does (it used Gauss elimination with pivoting): O(n³) per evaluation. The Lagrange equations are
//   M_II θ'' = J^T (Q - h - M (J' θ' + J_0 a_top)).
// M_II is assembled in O(n²) from suffix sums of the per-rfe blocks. Joints hold by construction.
// A pinned bottom adds its two constraints (end of rfe n at the anchor) with a Lagrange multiplier
// (Schur complement of the dense KKT system) and Baumgarte stabilisation.
#pragma once
#include <Eigen/Cholesky>

#include "riser_sim/chain_formulation.h"

namespace riser_sim {

class IndependentFormulation : public ChainFormulation {
 public:
  IndependentFormulation(const Model& model, double stabilization);
  std::string name() const override { return "independent"; }
  void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) override;

  // The last dense mass matrix (lower triangle filled) — for tests.
  const MatX& massMatrix() const { return Mii_; }

 private:
  MatX Mii_, W_, C_, X_;
  VecX rhs_, qdd_;
  Eigen::LDLT<MatX> ldlt_;
  AlignedVector<Vec2> abias_, A_dd_;
  AlignedVector<Vec4> f_;  // generalised forces of rfe i with θ'' = 0
};

}  // namespace riser_sim
