// Shared part of the two independent-coordinate formulations (paper section 2.2): the line as a serial
// chain hanging from the prescribed top point A_0, coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] (Δ dropped
// when axial flexibility is off), positions by forward kinematics A_{i+1} = A_i + (l_i + Δ_i) e(φ_i)
// (chain_kinematics.h). A_0 is not part of the state (the paper's x_0, y_0 are prescribed, eq. 7.2): every
// call that needs positions takes the top motion.
#pragma once
#include <memory>

#include "riser_sim/planar/chain_shifted_solver.h"
#include "riser_sim/planar/formulation.h"

namespace riser_sim {

class ChainFormulation;

// Workspaces of one evaluation and of the structured solves.
class ChainData : public FormulationData {
 public:
  ChainData(const ChainFormulation& owner, const Model& model);

  // bias[i] = 2Δ'φ' n_i - (l_i+Δ_i) φ'² e_i: velocity-product acceleration of A_{i+1} relative to A_i.
  AlignedVector<Vec2> bias;
  VecX Q, h;              // applied forces and velocity terms, absolute coordinates (M q'' = Q - h)
  AlignedVector<Mat4> M;  // mass blocks (rigid parts + every term's inertia)

  // Structured solves: the linearised evaluation's kinematics and joint forces (copies: later evaluations
  // overwrite kin and reactions), its mass blocks and stiffness, and the solver's factorisation.
  Kinematics lin_kin;
  AlignedVector<Mat4> lin_M;
  AlignedVector<Vec2> lin_joint;
  VecX lin_h, lin_r, lin_x, lin_dy;
  StiffnessBlocks lin_S;
  ChainShiftedSolver shifted;
  double shifted_c = 0.0;
  bool linearized = false, factored = false;
};

class ChainFormulation : public Formulation {
 public:
  ChainFormulation(const Model& model, double stabilization);
  int positionSize() const override { return k_ * model_.bodies(); }
  void packState(const Kinematics& kin, VecX& y) const override;
  void kinematics(const VecX& y, const PointMotion& top, Kinematics& kin) const override;
  // 0 for a free bottom (joints hold by construction); the gap at the pinned bottom otherwise.
  double constraintError(const VecX& y, const PointMotion& top) const override;
  bool hasShiftedSolve() const override { return true; }
  void linearize(double t, const VecX& y, const PointMotion& top, FormulationData& data) const override;
  void factorShifted(double c, FormulationData& data) const override;
  void solveShifted(const VecX& b, VecX& x, FormulationData& data) const override;

  // Coordinates per rfe: 2 (Δ, φ) or 1 (φ, inextensible line).
  int dofsPerRfe() const { return k_; }

 protected:
  bool holdsState(const VecX& y, const Kinematics& kin) const override;
  // Starts an evaluation: records t and top, fills d.kin, d.bias, the terms' forces d.Q and their power.
  void beginEvaluation(double t, const VecX& y, const PointMotion& top, ChainData& d) const;
  bool pinned() const { return model_.bottom() == BottomBoundary::kPinned; }
  // Joint reactions from the absolute accelerations A''_i (i = 0..n+1) and (Δ'', φ'') of every rfe
  // (general mass blocks d.M, d.h must be current): Newton's law on every sub-chain i..n.
  void reactionsFromAccelerations(const AlignedVector<Vec2>& A_dd, const VecX& theta_dd, const Vec2& tip_force,
                                  ChainData& d) const;

  const int k_;         // coordinates per rfe
  const double omega_;  // Baumgarte frequency for the pinned bottom [rad/s]
  bool rigid_only_ = true;
};

}  // namespace riser_sim
