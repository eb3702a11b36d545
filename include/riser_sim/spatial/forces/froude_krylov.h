// Froude-Krylov force in 3D (the planar HydroInertia's applied part, paper eq. 13 with the axial part):
// dF = [C_M ρ_w A_w a_w,η + (1 + C_a,t) ρ_w A_w a_w,ξ] dξ on each submerged part's centroid, a_w,ξ = (e·a_w) e
// the water's acceleration along the rfe and a_w,η = a_w - a_w,ξ across it. The added mass is AddedMass.
// Built only where the water moves (waves, an accelerating current).
#pragma once
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class FroudeKrylov : public ForceTerm3 {
 public:
  // cm_normal C_M, cm_axial 1 + C_a,t.
  FroudeKrylov(const Water3& water, double cm_normal, double cm_axial)
      : water_(water), cm_n_(cm_normal), cm_t_(cm_axial) {}
  std::string name() const override { return "froude_krylov"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3&, const Kinematics3&, double) const override { return 0.0; }  // power() only
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;

 private:
  double sweep(const Model3& model, const Kinematics3& kin, double t, VecX* Q) const;
  Water3 water_;
  double cm_n_, cm_t_;
};

}  // namespace spatial
}  // namespace riser_sim
