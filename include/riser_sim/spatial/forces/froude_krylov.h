// Froude-Krylov force in 3D with C_M = 1 (the planar HydroInertia without added mass, paper eq. 13):
// dF = C_M ρ_w A_w a_w,η dξ on each submerged part's centroid, a_w,η = a_w - (e·a_w) e the water's
// acceleration normal to the rfe. Built only where the water moves (waves, an accelerating current).
#pragma once
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class FroudeKrylov3 : public SpatialForceTerm {
 public:
  explicit FroudeKrylov3(const Water3& water) : water_(water) {}
  std::string name() const override { return "froude_krylov"; }
  void addForces(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const SpatialModel&, const Kinematics3&) const override { return 0.0; }  // power() only
  double power(const SpatialModel& model, const Kinematics3& kin, double t) const override;
  double addForcesAndPower(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const override;

 private:
  double sweep(const SpatialModel& model, const Kinematics3& kin, double t, VecX* Q) const;
  Water3 water_;
};

}  // namespace spatial
}  // namespace riser_sim
