// Buoyancy of the displaced water, ρ_w A_w g per submerged length (paper eq. 11, 16), for parts fully or
// partly below the free surface, applied at the centroid of the submerged portion.
// V = -ρ_w g A_w ∫ min(y - y_s, 0) dξ, A_w of each part's line section. (Wall and internal-fluid weights are
// the Gravity term.)
#pragma once
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {

class Buoyancy : public ForceTerm {
 public:
  explicit Buoyancy(const WaterSpec& water) : water_(water) {}
  std::string name() const override { return "buoyancy"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model&, const TermData*, const Kinematics&, double) const override { return 0.0; }  // conservative
  const WaterSpec& water() const { return water_; }

 private:
  double liftPerLength(const Model& model, int i, int p) const;
  WaterSpec water_;
};

// Submerged portion of part p of rfe i: its length [m] and the distance of its centroid from A_i
// at Δ = 0 (the part moves with kappa*Δ).
struct WetPart {
  double length = 0.0, s0 = 0.0, kappa = 0.0, fraction = 0.0;
};
WetPart wetPart(const Model& model, const BodyKinematics& b, int i, int part, double surface);

}  // namespace riser_sim
