// Morison drag on the velocity relative to the water, in the rfe frame (paper eq. 12):
// dF = -½ ρ_w D_out [D_ξ |V'_ξ| V'_ξ e + D_η |V'_η| V'_η n] dξ, one quadrature point per submerged part.
#pragma once
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {

class MorisonDrag : public ForceTerm {
 public:
  MorisonDrag(const WaterKinematics& water, double drag_tangential, double drag_normal)
      : water_(water), cd_t_(drag_tangential), cd_n_(drag_normal) {}
  std::string name() const override { return "morison_drag"; }
  const WaterKinematics& water() const { return water_; }
  std::unique_ptr<ForceTerm> steadyTerm(double t) const override {
    return std::make_unique<MorisonDrag>(water_.steady(t), cd_t_, cd_n_);
  }
  std::unique_ptr<ForceTerm> steadyTerm(double t, double current_factor) const override {
    return std::make_unique<MorisonDrag>(water_.steady(t, current_factor), cd_t_, cd_n_);
  }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  double potentialEnergy(const Model&, const TermData*, const Kinematics&) const override {
    return 0.0;
  }  // dissipative: power() only
  double addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                           VecX& Q) const override;
  // Damping C = -∂F/∂v of each quadrature point (the quadratic law's slope 2 k D |V'|). The force's dependence
  // on position (e, n turning, the water's field) is left out: it stays explicit in the structured solves.
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;

 private:
  // Drag force [N] on part p of rfe i, its point of application (s0, kappa) and that point's velocity.
  Vec2 force(const Model& model, const BodyKinematics& b, int i, int p, double t, double& s0, double& kappa,
             Vec2& v) const;
  // Adds the drag forces to *Q (when Q is given); returns their power [W].
  double sweep(const Model& model, const Kinematics& kin, double t, VecX* Q) const;
  WaterKinematics water_;
  double cd_t_, cd_n_;
};

}  // namespace riser_sim
