// Paper section 2.1: absolute coordinates q_i = [x_i, y_i, Δ_i, φ_i] of every rfe, joint reactions λ_k
// as unknowns (eqs. 7-8). The Schur complement J M^-1 J^T is block-tridiagonal (2x2 blocks) and is
// solved by block Thomas elimination: O(n) per evaluation. Constraint drift is held by Baumgarte
// stabilisation c'' + 2ω c' + ω² c = 0.
#pragma once
#include "riser_sim/formulation.h"

namespace riser_sim {

class AbsoluteFormulation : public Formulation {
 public:
  AbsoluteFormulation(const Model& model, double stabilization);
  std::string name() const override { return "absolute"; }
  int positionSize() const override { return model_.dofs(); }
  void packState(const Kinematics& kin, VecX& y) const override;
  void kinematics(const VecX& y, Kinematics& kin) const override;
  void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) override;
  const Reactions& reactions() const override { return reactions_; }
  double constraintError(const VecX& y, const PointMotion& top) const override;
  double kineticEnergy(double t, const VecX& y) override;
  const Kinematics& lastKinematics() const override { return kin_; }
  double lastConstraintError() const override { return last_constraint_error_; }

 private:
  // Per rfe: accelerations of A_i and of its end E_i per unit force at A_i / E_i (2x2 compliances,
  // world frame) and the free accelerations of A_i and E_i under the applied forces.
  struct Compliance {
    Mat2 AA, AE, EE;
    Vec2 aA, aE;
  };
  void massBlocks(double t);  // fills M_, h_ from kin_
  void rigidBody(int i, bool axial);     // closed form for the rigid parts alone
  void generalBody(int i, bool axial);   // any inertia (added mass, internal fluid): 4x4 Cholesky
  void bodyAcceleration(int i, bool axial, const Vec2& FA, const Vec2& FE, double* qdd) const;
  int constraints() const { return model_.bodies() + (model_.bottom() == BottomBoundary::kPinned ? 1 : 0); }

  const Model& model_;
  double omega_;
  bool rigid_only_ = true;
  double last_constraint_error_ = 0.0;  // no term adds inertia: closed-form M^-1
  Kinematics kin_;
  VecX Q_, h_;
  AlignedVector<Mat4> M_, Minv_;
  AlignedVector<Compliance> comp_;
  std::vector<double> body_inv_;  // rigid path: 6 coefficients per rfe (see rigidBody)
  AlignedVector<Mat2> diag_, low_, up_;
  AlignedVector<Vec2> rhs_, lambda_;
  Reactions reactions_;
};

}  // namespace riser_sim
