// Equations of motion of the spatial line in natural coordinates (kinematics.h), the 3D counterpart of
// the planar AbsoluteFormulation. Per rfe the kinetic energy is exact on |e| = 1:
//   T_i = Σ_p ½ m_p |A' + κ_p Δ' e + s_p e'|² + ½ J_p |e'|²,   s_p = s0_p + κ_p Δ,
// a point-mass system plus a director inertia, so M_i u'' + h_i = Q_i + constraint forces with the 7x7
// M_i (m I, m_k e, S I; m_k, S_k eᵀ; I_A I) and h_i = 2Δ' [m_k e'; m_k e·e'; S_k e'].
// Constraints: per rfe ½(e·e - 1) = 0, eliminated inside the rfe (one scalar Schur step); joints
// E_{k-1} - A_k = 0, the top A_0 = p(t), a pinned end E_n = p_b(t) (fixed or moving), with joint reactions λ_k ∈ R³
// from a block-tridiagonal (3x3 blocks) system solved by block Thomas: O(n) per evaluation. Every constraint is
// Baumgarte-stabilised, c'' + 2ω c' + ω² c = 0. Evaluations allocate nothing (NaturalData).
#pragma once
#include <memory>
#include <vector>

#include "riser_sim/spatial/added_mass.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {

using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat7 = Eigen::Matrix<double, 7, 7>;
using Mat73 = Eigen::Matrix<double, 7, 3>;

struct Reactions3 {
  Vec3 top = Vec3::Zero();     // force the line exerts on the hang-off point A_0 [N]
  Vec3 bottom = Vec3::Zero();  // force the line exerts on the bottom anchor (pinned, fixed or moving) [N]
  // Torsion on: the moment the line exerts on the hang-off [N m], top_twist_moment = τ (h + e_0)/(1 + h·e_0)
  // (h: the hang-off's axis; the holding moment of the homokinetic top), top_twist = τ its part along h.
  double top_twist = 0.0;
  Vec3 top_twist_moment = Vec3::Zero();
  AlignedVector<Vec3> joint;  // λ_k: force on rfe k-1 at its end (minus the force on rfe k at A_k), k = 0..n+1
};

// One evaluation's results and workspaces, sized once by NaturalFormulation::makeData().
class NaturalData {
 public:
  // dense_path: the dense path's per-rfe W, WE too (NaturalFormulation with closed_form false).
  NaturalData(const Model3& model, bool dense_path);
  double t = 0.0;
  PointMotion3 top;
  PointMotion3 bottom;  // the pinned bottom's anchor at t (Model3::bottomAt)
  Kinematics3 kin;
  Reactions3 reactions;
  double term_power = 0.0;        // summed non-conservative power of the terms [W]
  double constraint_error = 0.0;  // largest joint gap [m]

  // Per rfe: u'' = a + W (B_Aᵀ F_A + B_Eᵀ F_E) for forces F_A at A_i, F_E at the end E_i (W: constrained
  // inverse mass, the unit-length constraint eliminated; WE = W B_Eᵀ), and the 3x3 compliances of the
  // accelerations of A_i, E_i under those forces with their free accelerations aA, aE.
  struct Body {
    Vec7 a;
    Mat3 AA, AE, EE;
    Vec3 aA, aE;
    // Closed form: n = e/|e|, rho = |e|; (A·n, Δ) inverse mass entries a_*, transverse (A⊥, e⊥) ones t_*;
    // S, Sk_rho = S_k rho couple the prescribed n·e'' = bdd into the (A·n, Δ) rows.
    Vec3 n;
    double rho, a_aa, a_ad, a_dd, t_AA, t_Ae, t_ee, S, Sk_rho, bdd;
  };
  // The dense path's W and WE = W B_Eᵀ, apart (empty in the closed form: its per-rfe data stays small).
  struct DenseBody {
    Mat7 W;
    Mat73 WE;
  };
  VecX Q, h;
  VecX acc;  // v' of this evaluation (7 per rfe)
  VecX dy;   // workspace [q'; θ'; v'; ω'] for linearize()
  AlignedVector<Body> body;
  AlignedVector<DenseBody> dense;
  AlignedVector<Mat3> diag, up;
  AlignedVector<Vec3> rhs, lambda;
  // Torsion on: the charts (set by NaturalFormulation::initTwist, moved by rechartTwist), the twist of this
  // evaluation and its [θ; ω].
  TwistData twist;
  VecX twist_y;
  // Terms with inertia (added mass): their moments per rfe for this evaluation; empty without such terms.
  std::vector<AddedMass3> added;
};

class ShiftedSolver3;  // shifted_solver.h

class NaturalFormulation {
 public:
  // stabilization: Baumgarte ω [rad/s] (the planar SolverSettings::stabilization, default 50).
  // closed_form: per-rfe inverse in closed form (the mass matrix splits exactly into the direction of e,
  // where the unit-length constraint prescribes n·e'', and the plane across it); false: a dense 7x7
  // Cholesky and a Schur step (the general path for terms with inertia later; a cross-check now).
  NaturalFormulation(const Model3& model, double stabilization, bool closed_form = true);
  const Model3& model() const { return model_; }
  // y = [q; θ; v; ω; rest]: θ, ω (one per rfe) only with torsion on (torsion.h); θ_0 = ω_0 = 0 (held).
  int positionSize() const { return model_.dofs() + twistDofs(); }
  int twistDofs() const { return model_.hasTorsion() ? model_.bodies() : 0; }
  std::unique_ptr<NaturalData> makeData() const { return std::make_unique<NaturalData>(model_, !closed_form_); }
  // y = [q; v] (its first 2 * positionSize() entries) from / to rfe kinematics.
  void packState(const Kinematics3& kin, VecX& y) const;
  void kinematics(const VecX& y, Kinematics3& kin) const;
  BodyKinematics3 body(const VecX& y, int i) const;
  // dy/dt on [q; v] at time t [s] with A_0 moving as top; data holds the evaluation.
  void derivative(double t, const VecX& y, const PointMotion3& top, VecX& dy, NaturalData& data) const;
  // Torsion on: charts at state y (before the first derivative()), the hang-off's frame fixed in the top's
  // holder at its attitude R0 then; moved to y between steps (the state and the frames are unchanged: exact),
  // the hang-off's frame turned to top's attitude. twistEnergy: Σ ½ (GJ/d) m_k² [J] with the hang-off at top.
  // hang_off_ref: the hang-off's reference at y's top rfe (unit, across it; zero: from the bending axis).
  void initTwist(const VecX& y, NaturalData& data, const Mat3& R0 = Mat3::Identity(),
                 const HangOff& hang_off = HangOff()) const;
  void rechartTwist(const VecX& y, const PointMotion3& top, NaturalData& data) const;
  double twistEnergy(const VecX& y, const PointMotion3& top, NaturalData& data) const;
  // Kinetic energy [J] of state y (with the spins' ½ J_i ω_i²).
  double kineticEnergy(const VecX& y) const;
  // Largest joint gap (top, joints, pinned end at bottom.p) [m], and largest | |e_i| - 1 | of state y.
  double constraintError(const VecX& y, const PointMotion3& top, const PointMotion3& bottom) const;
  double directorError(const VecX& y) const;
  // max_i max(| |e_i| - 1 |, |e_i·e'_i| h): the distance from the unit-length manifold over a step h [s].
  double manifoldError(const VecX& y, double h) const;
  // Holds y on the unit-length manifold: e_i <- e_i/|e_i|, e'_i <- e'_i - (e_i·e'_i) e_i.
  void project(VecX& y) const;

  // --- Structured implicit solves (shifted_solver.h): x = (I - c J)^-1 b on [q; v], O(n). ---
  bool hasShiftedSolve() const { return true; }
  std::unique_ptr<ShiftedSolver3> makeShifted() const;
  // Linearises at (t, y): data's evaluation is used when it was made at exactly (t, y), else linearize()
  // evaluates there first (data then holds that evaluation).
  void linearize(double t, const VecX& y, const PointMotion3& top, NaturalData& data, ShiftedSolver3& s) const;
  void factorShifted(double c, ShiftedSolver3& s) const;               // throws std::logic_error before linearize()
  void solveShifted(const VecX& b, VecX& x, ShiftedSolver3& s) const;  // throws before factorShifted()
  // Whether data holds the evaluation at exactly (t, y).
  bool evaluatedAt(double t, const VecX& y, const NaturalData& data) const;

 private:
  double unitGamma(const BodyKinematics3& b) const;  // e·e'' prescribed by the Baumgarte-held |e| = 1
  void denseBody(int i, NaturalData& d) const;
  void closedFormBody(int i, NaturalData& d) const;
  void jointReactions(NaturalData& d) const;  // joint_reactions.cpp
  static void closedFormAcceleration(const NaturalData::Body& c, const Vec7& f, double* udd);
  const Model3& model_;
  const double omega_;
  const bool closed_form_;
};

}  // namespace spatial
}  // namespace riser_sim
