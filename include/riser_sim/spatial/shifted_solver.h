// O(n) solves x = (I - c J)^-1 b on y = [q; v] for the implicit integrators, J ≈ ∂(q', v')/∂(q, v) of the
// spatial natural formulation (constrained, Baumgarte-stabilised). With x_q = b_q + c x_v the velocity
// increment solves the KKT system
//   (M + c C + c² K) x_v + Gᵀ ν = M b_v - c K b_q,     (g + c p + c² r) x_v = g b_v - c r b_q (every row),
// where M is the 7x7 mass per rfe, K, C the terms' linearisation (ForceTerm3::addStiffness) plus the
// mass matrix's and the velocity terms' dependence on q, v and the geometric stiffness of the constraint
// forces (the director multiplier on e, the joint force on Δ-e). A constraint row is its Baumgarte law
// linearised on the increment, g δa + p δv + r δq = 0 (g = ∂c/∂q; for A-type rows p = 2ωg, r = ω²g and the
// row is (1 + ωc)² g x_v = g b_v - ω² c g b_q, as the planar chain's pinned end). Rows: the top, the joints,
// a pinned end (3 each) and per rfe the unit-length ½(e·e - 1) = 0.
// The system is solved by a backward sweep from the bottom, as the planar chain solver's Riccati sweep: the
// rfes below rfe i act on its momentum rows as an affine function of x_v,i (S_{i+1} x_v,i + s_{i+1}). Per rfe
// the joint row gives x_A,i from x_v,i-1, the A momentum rows give λ_i, and (Δ, e) with the unit-length
// multiplier ν_i solve a 5x5 system (inverted once per factor), so x_v,i = Φ_i x_v,i-1 + f_i; a forward pass
// applies Φ. The matrices need not be symmetric (damping couplings, Baumgarte rows against Gᵀ columns). A
// pinned end's multiplier λ_n is carried through the sweep linearly (the sensitivities ∂x_v,i/∂λ_n) and fixed
// by its 3x3 row at the end. For the
// shipped terms K and C are the exact linearisation (test_spatial_shifted: the solve matches a dense
// finite-difference one to its accuracy); a term that leaves its part out only slows Newton. Workspaces
// are sized in the constructor; factor() and solve() allocate nothing.
// Torsion on (torsion.h): the spins solve after the KKT system, (J + c C_t + c² K_t) x_ω = J b_ω - c K_t b_θ,
// x_θ = b_θ + c x_ω, tridiagonal (Thomas), with K_t, C_t the twist springs and dampers on θ, ω alone: the
// coupling to e (the twist's forces on e, the gyroscopic term, θ' = ω - a·e') is left out of J. That makes
// the solve approximate: Newton converges to the same step with more iterations (test_spatial_torsion).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/stiffness.h"

namespace riser_sim {
namespace spatial {

class ShiftedSolver3 {
 public:
  ShiftedSolver3(const Model3& model, double stabilization);
  // Linearisation at the evaluation d (its kinematics, forces, joint reactions) with its accelerations
  // acc = v' (7 per rfe).
  void setLinearization(const NaturalData& d, const Eigen::Ref<const VecX>& acc);
  // A kept factor turned with the line (docs/spatial_step_cost.md, "The kept factor turns with the line"): until the
  // next setLinearization(), solve() sees each rfe's director rate, and the rate of A_{i+1} - A_i, turned
  // back by R_i, the smallest rotation taking the linearisation's director e_i to d's (a similarity
  // transform of the kept matrix: its joint and unit-length rows follow the turned directors; the same
  // solution where the factor is exact, fewer Newton iterations where the line turned).
  void followDirectors(const NaturalData& d);
  // Block LU of the KKT matrix for c = κh [s].
  void factor(double c);
  // x = (I - c J)^-1 b on the first 2p entries (c of the last factor()).
  void solve(const VecX& b, VecX& x);
  bool linearized() const { return linearized_; }
  bool factored() const { return factored_; }
  double c() const { return c_; }

  // A 3x7 block [a I, d, b I] on (A, Δ, e): the rows of E_i = A_i + len e_i and of its Baumgarte law.
  struct Row3 {
    double a = 0.0, b = 0.0;
    Vec3 d = Vec3::Zero();
  };
  using Vec11 = Eigen::Matrix<double, 11, 1>;
  using Mat37 = Eigen::Matrix<double, 3, 7>;
  using Mat5 = Eigen::Matrix<double, 5, 5>;
  using Mat45 = Eigen::Matrix<double, 4, 5>;
  using Mat47 = Eigen::Matrix<double, 4, 7>;
  using Mat73 = Eigen::Matrix<double, 7, 3>;
  using Mat43 = Eigen::Matrix<double, 4, 3>;

 private:
  // The solve's fields first (together in memory), then the factor's.
  struct Body {
    // Sweep (factor): Γ = g + c p + c² r of E_i; W = M + cC + c²K + S_{i+1} (the rfes below, as seen by x_i),
    // of which the solve reads the A rows (Wt) and the Δ-e rows of the A columns (Wd);
    // R = [W_uu g_u; γ_uᵀ 0] (u = Δ, e), Ri = the first 4 rows of R⁻¹ (LU with partial pivoting on unit
    // columns), RN = the u rows of R⁻¹ N (x_i's dependence on x_{i-1});
    // Up = the e-e coupling to x_{i+1}; Xmu = ∂x_i/∂λ_n (pinned end).
    Mat37 Wt;
    Mat43 Wd;
    Mat45 Ri;
    Mat47 RN;
    Vec7 x;  // solve: x_i's constant part (backward), then x_v,i (forward)
    // The mass without added mass, for the solve's M b_v: m I, m_k e, S I; m_k eᵀ, m_k e·e, S_k eᵀ; S I, S_k e,
    // I_A I (Δ locked: 1 on Δ, no m_k, S_k). The whole 7x7 M lives in M_ (the factor's, and the solve's with
    // added mass); K, C, K_sub, K_sup, C_sub in S_: K(i, i), C(i, i), rows i / columns i-1.
    double m = 0.0, mk = 0.0, S = 0.0, Sk = 0.0, I = 0.0;
    Vec3 e = Vec3::Zero();
    Mat3 Kup, Up;      // e-e: K(i, i+1) = K_sub[i+1]ᵀ + K_sup[i+1] (the right side's coupling to rfe i+1)
    Row3 gE, rE, Gam;  // Baumgarte law of E_i: g δa + p δv + r δq (g = B_E = ∂E/∂q)
    Vec7 gu, ru;       // Baumgarte law of the unit length
    Row3 pE;
    Vec7 pu;
    Mat73 Xmu;
  };
  void assembleRhs(int blk, const VecX& b, const VecX& b_rates, Vec11& r) const;
  template <typename V>
  Vec7 massTimes(int i, const V& v) const;
  const VecX& turnedBack(const VecX& b);
  int blocks() const { return nb_ + (pinned_ ? 1 : 0); }
  // Φ_i v: x_i's dependence on x_{i-1} ([Γ_{i-1} / s; -RN_u]).
  template <typename In, typename Out>
  void applyPhi(int i, const In& v, Out& out) const;

  const Model3& model_;
  const double omega_;
  const int nb_, nq_, nt_, vo_;  // rfes, natural coordinates, twist coordinates, offset of v in y
  const bool axial_;
  bool pinned_ = false;
  AlignedVector<Body> body_;  // nb_ + 1 (the last: the pinned end's block)
  AlignedVector<Mat7> M_;     // per rfe: the mass, added mass included
  bool added_ = false;        // the last linearisation had added mass (the solve reads M_)
  Stiffness3 S_;
  AlignedVector<Mat3> turn_;  // followDirectors' R_i
  bool turning_ = false;
  VecX b_turned_;                       // the right side's rates turned back (entries vo_..vo_ + nq_)
  std::vector<double> t_diag_, t_mul_;  // torsion: the Thomas factor's pivots and multipliers
  Mat3 Sm_inv_ = Mat3::Zero();          // pinned: (Γ_{n-1} ∂x_{n-1}/∂λ_n)⁻¹
  double c_ = 0.0, s_ = 1.0;
  bool linearized_ = false, factored_ = false;
};

}  // namespace spatial
}  // namespace riser_sim
