// Paper section 2.2: independent coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] with the full mass matrix
// M_II = J^T M J (J: θ' → absolute velocities q'_i of every rfe) and a dense LDLT solve, as the paper
// does (it used Gauss elimination with pivoting): O(n³) per evaluation. The Lagrange equations are
//   M_II θ'' = J^T (Q - h - M (J' θ' + J_0 a_top)).
// M_II is assembled in O(n²) from suffix sums of the per-rfe blocks. Joints hold by construction.
// A pinned bottom adds its two constraints (end of rfe n at the anchor) with a Lagrange multiplier
// (Schur complement of the dense KKT system) and Baumgarte stabilisation.
#pragma once
#include <Eigen/Cholesky>

#include "riser_sim/planar/chain_formulation.h"

namespace riser_sim {

class IndependentFormulation;

// Workspaces of the dense solve (ChainData's besides).
class IndependentData : public ChainData {
 public:
  IndependentData(const IndependentFormulation& owner, const Model& model);

  MatX Mii;  // M_II (lower triangle filled)
  MatX W, C, X;
  VecX f;  // generalised forces of every rfe with θ'' = 0 (4 per rfe, absolute coordinates)
  VecX rhs, qdd;
  Eigen::LDLT<MatX> ldlt;
  AlignedVector<Vec2> abias, A_dd;
};

class IndependentFormulation : public ChainFormulation {
 public:
  IndependentFormulation(const Model& model, double stabilization);
  std::string name() const override { return "independent"; }
  std::unique_ptr<FormulationData> makeData() const override;
  void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy, FormulationData& data) const override;

  // The dense mass matrix of data's evaluation (lower triangle filled).
  const MatX& massMatrix(const FormulationData& data) const;
};

}  // namespace riser_sim
