// Shared part of the two independent-coordinate formulations (paper section 2.2): the line as a serial
// chain hanging from the prescribed top point A_0, coordinates θ = [Δ_0, φ_0, …, Δ_n, φ_n] (Δ dropped
// when axial flexibility is off), positions by forward kinematics A_{i+1} = A_i + (l_i + Δ_i) e(φ_i).
//
// A_0 is not part of the state (the paper's x_0, y_0 are prescribed, eq. 7.2). Formulation::kinematics(y)
// has no time argument, so it places A_0 at the top motion of the last derivative() call (or of
// packState() before the first one). The simulator's RK4 evaluates its last stage at the step's end
// time, so energies and outputs read after a step see the right A_0.
#pragma once
#include <memory>

#include "riser_sim/chain_shifted_solver.h"
#include "riser_sim/formulation.h"

namespace riser_sim {

class ChainFormulation : public Formulation {
 public:
  ChainFormulation(const Model& model, double stabilization);
  int positionSize() const override { return k_ * model_.bodies(); }
  void packState(const Kinematics& kin, VecX& y) const override;
  void kinematics(const VecX& y, Kinematics& kin) const override;
  const Reactions& reactions() const override { return reactions_; }
  // 0 for a free bottom (joints hold by construction); the gap at the pinned bottom otherwise.
  double constraintError(const VecX& y, const PointMotion& top) const override;
  const Kinematics& lastKinematics() const override { return kin_; }
  double lastConstraintError() const override { return last_constraint_error_; }
  double kineticEnergy(double t, const VecX& y) override;
  bool hasShiftedSolve() const override { return true; }
  void linearize(double t) override;
  void factorShifted(double c) override;
  void solveShifted(const VecX& b, VecX& x) override;

  // Coordinates per rfe: 2 (Δ, φ) or 1 (φ, inextensible line).
  int dofsPerRfe() const { return k_; }

 protected:
  // kin_ and the velocity-product accelerations bias_[i] = 2Δ'φ' n_i - (l_i+Δ_i) φ'² e_i of A_{i+1}
  // relative to A_i, for the top at p, v.
  void chainKinematics(const VecX& y, const Vec2& p, const Vec2& v, Kinematics& kin) const;
  void updateKinematics(const VecX& y, const PointMotion& top);
  void evaluateForces(double t);      // Q_ from every term
  void generalMassBlocks(double t);   // M_, h_ (rigid parts + every term's inertia)
  bool pinned() const { return model_.bottom() == BottomBoundary::kPinned; }
  // Joint reactions from the absolute accelerations A''_i (i = 0..n+1) and (Δ'', φ'') of every rfe
  // (general mass blocks M_, h_ must be current): Newton's law on every sub-chain i..n.
  void reactionsFromAccelerations(const AlignedVector<Vec2>& A_dd, const VecX& theta_dd, const Vec2& tip_force);

  const Model& model_;
  const int k_;          // coordinates per rfe
  const double omega_;   // Baumgarte frequency for the pinned bottom [rad/s]
  bool rigid_only_ = true;
  mutable PointMotion top_;  // A_0's motion used by kinematics()
  Kinematics kin_;
  AlignedVector<Vec2> bias_;
  VecX Q_, h_;
  AlignedVector<Mat4> M_;
  Reactions reactions_;
  double last_constraint_error_ = 0.0;

 private:
  // Structured implicit solves: linearisation copies (kinematics, mass blocks, joint forces) and the solver.
  Kinematics lin_kin_;
  AlignedVector<Mat4> lin_M_;
  AlignedVector<Vec2> lin_joint_;
  VecX lin_h_, lin_r_, lin_x_;
  StiffnessBlocks lin_S_;
  ChainShiftedSolver shifted_;
  double shifted_c_ = 0.0;
};

}  // namespace riser_sim
