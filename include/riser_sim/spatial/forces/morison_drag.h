// Morison drag in 3D on the velocity V' of each submerged part's centroid relative to the water
// (the planar MorisonDrag, paper eq. 12, by the cross-flow principle):
// dF = -½ ρ_w D_out [D_ξ |V'_ξ| V'_ξ e + D_η |V'_η| V'_η] dξ, V'_ξ = e·V', V'_η = V' - V'_ξ e (the normal
// part's magnitude and direction).
#pragma once
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class MorisonDrag : public ForceTerm3 {
 public:
  // line_at_rest: the force on the line held still in the water (V' = -V_water), whatever its velocity: the
  // static load, for the 3D relaxation (relaxation.h), where the drag's damping would only slow it down.
  MorisonDrag(const Water3& water, double drag_tangential, double drag_normal, bool line_at_rest = false)
      : water_(water), cd_t_(drag_tangential), cd_n_(drag_normal), at_rest_(line_at_rest) {}
  std::string name() const override { return "morison_drag"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3&, const Kinematics3&, double) const override { return 0.0; }  // power() only
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  // Damping C = -∂F/∂V' of each centroid (exact in the rates); the dependence on position stays explicit.
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;

 private:
  // V' of the wet part's centroid: its velocity (none when held at rest) less the water's.
  Vec3 relativeVelocity(const BodyKinematics3& b, const WetPart3& w, double t) const;
  // Adds the forces to *Q (when given); returns their power [W].
  double sweep(const Model3& model, const Kinematics3& kin, double t, VecX* Q) const;
  Water3 water_;
  double cd_t_, cd_n_;
  bool at_rest_;
};

}  // namespace spatial
}  // namespace riser_sim
