// Buoyancy in 3D: -ρ_w A_w g per submerged length (the planar Buoyancy, paper eq. 11, 16), at the centroid
// of each part's submerged portion; parts crossing the surface are cut there.
// V = -ρ_w |g| A_w ∫ min(h, 0) dξ, h the height above the mean surface (Water3::height).
#pragma once
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class Buoyancy : public ForceTerm3 {
 public:
  explicit Buoyancy(const Water3& water) : water_(water) {}
  std::string name() const override { return "buoyancy"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3&, const Kinematics3&, double) const override { return 0.0; }  // conservative
  // The lift's geometric part on each wet part (its moment arm s = s0 + κΔ); the change of the wet length
  // at the surface stays explicit.
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;

 private:
  Water3 water_;
};

}  // namespace spatial
}  // namespace riser_sim
