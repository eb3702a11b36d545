// Paper section 2.1: absolute coordinates q_i = [x_i, y_i, Δ_i, φ_i] of every rfe, joint reactions λ_k
// as unknowns (eqs. 7-8). The Schur complement J M^-1 J^T is block-tridiagonal (2x2 blocks) and is
// solved by block Thomas elimination: O(n) per evaluation. Constraint drift is held by Baumgarte
// stabilisation c'' + 2ω c' + ω² c = 0.
#pragma once
#include <vector>

#include "riser_sim/planar/formulation.h"

namespace riser_sim {

class AbsoluteFormulation;

// Workspaces of one evaluation (FormulationData's outputs besides).
class AbsoluteData : public FormulationData {
 public:
  AbsoluteData(const AbsoluteFormulation& owner, const Model& model);

  // Per rfe: accelerations of A_i and of its end E_i per unit force at A_i / E_i (2x2 compliances,
  // world frame) and the free accelerations of A_i and E_i under the applied forces.
  struct Compliance {
    Mat2 AA, AE, EE;
    Vec2 aA, aE;
  };
  VecX Q, h;                    // applied forces, velocity terms (M q'' = Q - h)
  AlignedVector<Mat4> M, Minv;  // mass blocks and their inverses (terms with inertia)
  AlignedVector<Compliance> comp;
  std::vector<double> body_inv;       // rigid path: 6 coefficients per rfe (see rigidBody)
  AlignedVector<Mat2> diag, low, up;  // block-tridiagonal Schur complement
  AlignedVector<Vec2> rhs, lambda;
};

class AbsoluteFormulation : public Formulation {
 public:
  AbsoluteFormulation(const Model& model, double stabilization);
  std::string name() const override { return "absolute"; }
  int positionSize() const override { return model_.dofs(); }
  std::unique_ptr<FormulationData> makeData() const override;
  void packState(const Kinematics& kin, VecX& y) const override;
  void kinematics(const VecX& y, const PointMotion& top, Kinematics& kin) const override;
  void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy, FormulationData& data) const override;
  double constraintError(const VecX& y, const PointMotion& top) const override;

 private:
  bool holdsState(const VecX& y, const Kinematics& kin) const override;
  void rigidBody(int i, bool axial, AbsoluteData& d) const;    // closed form for the rigid parts alone
  void generalBody(int i, bool axial, AbsoluteData& d) const;  // any inertia (added mass, internal fluid): 4x4 Cholesky
  void bodyAcceleration(int i, bool axial, const Vec2& FA, const Vec2& FE, const AbsoluteData& d, double* qdd) const;
  int constraints() const { return model_.bodies() + (model_.bottom() == BottomBoundary::kPinned ? 1 : 0); }

  const double omega_;
  bool rigid_only_ = true;  // no term adds inertia: closed-form M^-1
};

}  // namespace riser_sim
