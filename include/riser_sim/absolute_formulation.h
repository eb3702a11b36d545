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

 private:
  void massBlocks(double t);  // fills M_, h_ from kin_
  int constraints() const { return model_.bodies() + (model_.bottom() == BottomBoundary::kPinned ? 1 : 0); }

  const Model& model_;
  double omega_;
  Kinematics kin_;
  VecX Q_, h_;
  AlignedVector<Mat4> M_, Minv_;
  AlignedVector<Mat42> U_, V_;
  AlignedVector<Vec4> a_;
  AlignedVector<Mat24> G_;
  AlignedVector<Vec2> gamma_;
  AlignedVector<Mat2> diag_, low_, up_;
  AlignedVector<Vec2> rhs_, lambda_;
  Reactions reactions_;
};

}  // namespace riser_sim
