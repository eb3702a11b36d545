// Independent coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] solved in O(n) by an articulated-body recursion
// (beyond the paper). Each rfe is one node of a planar serial chain: its joint at A_i is a pin (only a
// force f_i passes), its own coordinates u_i = (Δ_i, φ_i) move its end A_{i+1} = A_i + (l_i+Δ_i) e_i:
//   A''_{i+1} = A''_i + G_i u''_i + c_i,  G_i = [e_i, (l_i+Δ_i) n_i],  c_i = 2Δ'φ' n_i - (l_i+Δ_i)φ'² e_i.
// With the rfe's mass block M_i = [[P, B], [B^T, D]] (A and u parts; any 4x4 block, so terms that add
// inertia work unchanged), r_i = Q_i - h_i, the force the rfes i..n need at A_i is affine in A''_i:
//   f_i = Λ_i A''_i + β_i   (Λ_{n+1} = 0, β_{n+1} = 0 for a free end).
// Backward pass (n → 0), with Λ', β' of rfe i+1:
//   D̂ = D + G^T Λ' G,  B̂ = B + Λ' G,  ρ = r_u - G^T (β' + Λ' c),
//   Λ_i = P + Λ' - B̂ D̂^-1 B̂^T,  β_i = B̂ D̂^-1 ρ + Λ' c + β' - r_A.
// Forward pass (0 → n) from A''_0 = a_top: u''_i = D̂^-1 (ρ - B̂^T A''_i), f_i = Λ_i A''_i + β_i.
// The joint reactions come out of the forward pass; joints hold exactly, by construction.
// A pinned bottom: everything is affine in the anchor force, so one extra 2x2 sensitivity per rfe
// gives the force that meets the end's Baumgarte-stabilised acceleration, still O(n).
// Λ_i is kept symmetric explicitly: its antisymmetric round-off part would otherwise grow ~2.3x per rfe.
#pragma once
#include <vector>

#include "riser_sim/planar/chain_formulation.h"

namespace riser_sim {

class RecursiveFormulation;

// Workspaces of the recursion (ChainData's besides).
class RecursiveData : public ChainData {
 public:
  RecursiveData(const RecursiveFormulation& owner, const Model& model);

  // Per rfe, from the backward pass (K = coordinates per rfe; stored with room for K = 2).
  struct Node {
    Mat2 Lam;   // Λ_i
    Mat2 T;     // ∂β_i/∂f_{n+1} (pinned bottom only)
    Mat2 Bh;    // B̂ (2xK used)
    Mat2 Dinv;  // D̂^-1 (KxK used)
    Mat2 G;     // G_i (2xK used)
    Vec2 beta, rho, c;
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  };
  // Fast path (rigid parts only, free bottom): the same recursion in scalars, in each rfe's frame
  // (e_i, n_i), where G, B and D are diagonal (see rigidBackwardAxial for the closed-form Λ).
  // Per rfe, everything affine in A''_i so that the forward pass is three 2x2 products per rfe:
  // u''_i = U A''_i + u0, f_i = Λ A''_i + β, A''_{i+1} = M A''_i + m (world axes).
  struct RigidNode {
    double U00, U01, U10, U11, u0, u1;  // (Δ'', φ'') response
    double La, Lb, Ld, bx, by;          // Λ_i = [[La, Lb], [Lb, Ld]], β_i
    double M00, M01, M10, M11, mx, my;  // A''_{i+1}
  };
  AlignedVector<Node> node;
  std::vector<RigidNode> rigid;
};

class RecursiveFormulation : public ChainFormulation {
 public:
  RecursiveFormulation(const Model& model, double stabilization);
  std::string name() const override { return "recursive"; }
  std::unique_ptr<FormulationData> makeData() const override;
  void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy, FormulationData& data) const override;

 private:
  using Node = RecursiveData::Node;
  using RigidNode = RecursiveData::RigidNode;
  template <int K, bool General>
  void backward(RecursiveData& d) const;
  template <int K>
  void forward(const Vec2& a_top, VecX& dy, int nt, RecursiveData& d) const;
  template <int K>
  Vec2 pinnedTipForce(const Vec2& a_top, RecursiveData& d) const;

  // Fills the forward coefficients of nd from the backward pass's quantities in the rfe frame.
  static void finishNode(RigidNode& nd, double c, double s, double len, double c0, double c1, double Di00, double Di01,
                         double Di11, double Bh00, double Bh01, double Bh10, double Bh11, double rho0, double rho1,
                         double L00, double L01, double L11, double be, double bn);
  void rigidBackwardAxial(RecursiveData& d) const;
  void rigidBackwardLocked(RecursiveData& d) const;
  template <bool Axial>
  void rigidForward(const Vec2& a_top, VecX& dy, int nt, RecursiveData& d) const;
};

}  // namespace riser_sim
