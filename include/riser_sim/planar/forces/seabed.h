// Seabed (paper's J-lay case): linear springs on the contact points below the seabed level y_b — the
// joints A_0..A_n and the end of rfe n. Normal: F_y = C_y (y_b - y) - c_y y' (never pulls);
// tangential: F_x = -C_x (x - x_touch) - c_x x', anchored where the point touched down. Stiffnesses are
// per contact point [N/m]. No force without contact. The anchors are run data (SeabedData, one per
// simulator); without data (statics) the tangential springs are not anchored and give no force.
#pragma once
#include <vector>

#include "riser_sim/planar/force_term.h"

namespace riser_sim {

struct SeabedSpec {
  bool enabled = false;
  double level = 0.0;                 // y_b [m]
  double stiffness_normal = 0.0;      // C_E,y [N/m] per contact point
  double stiffness_tangential = 0.0;  // C_E,x [N/m] per contact point
  double damping_normal = 0.0;        // [N s/m] per contact point
  double damping_tangential = 0.0;    // [N s/m] per contact point
  // Coulomb friction (3D core only, spatial/forces/seabed.h): coefficients along the line's horizontal
  // direction and across it, smoothed below the sliding speed friction_velocity [m/s].
  double friction_axial = 0.0, friction_lateral = 0.0, friction_velocity = 0.01;
  // A sloped plane (3D core only): its angle to the horizontal and the azimuth of its steepest ascent from +x
  // towards +y [rad]; `level` is then its height on the origin's vertical (docs/scene_keys.md).
  double slope = 0.0, slope_heading = 0.0;
};

// How deep a start may put a contact point below the seabed and still be "on" it [m]: the sink of one
// contact point carrying the whole weight W [N] (W / C_E,y). Deeper, the springs would throw the line out.
inline double restingSinkAllowance(const SeabedSpec& spec, double weight) {
  return spec.stiffness_normal > 0.0 ? weight / spec.stiffness_normal : 0.0;
}

// x of every contact point j = 0..n+1 at touchdown; NaN while it is free.
struct SeabedData : TermData {
  std::vector<double> anchor;
};

class Seabed : public ForceTerm {
 public:
  explicit Seabed(const SeabedSpec& spec) : spec_(spec) {}
  std::string name() const override { return "seabed"; }
  void addForces(const Model& model, const TermData* data, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData* data, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData* data, const Kinematics& kin) const override;
  double power(const Model& model, const TermData* data, const Kinematics& kin, double t) const override;
  double seabedLevel() const override { return spec_.level; }
  const SeabedSpec& spec() const { return spec_; }
  std::unique_ptr<TermData> makeData(const Model& model) const override;
  void startRun(const Model& model, const Kinematics& kin, TermData& data) const override;
  bool endStep(const Model& model, const Kinematics& kin, TermData& data) const override;
  int contacts(const Model& model, const Kinematics& kin) const;

 private:
  // Contact point j = 0..n+1: rfe index, position along it (s0, kappa), position and velocity.
  void point(const Model& model, const Kinematics& kin, int j, int& body, double& s0, Vec2& p, Vec2& v) const;
  // Contact force on point j; anchor: the data's anchors (null: none).
  Vec2 force(const double* anchor, int j, const Vec2& p, const Vec2& v, bool damping) const;
  static const double* anchors(const TermData* data);
  // Calls visit(j, rfe, s0, position, velocity) for every contact point below the seabed level.
  template <class Visit>
  void forEachContact(const Model& model, const Kinematics& kin, Visit&& visit) const;
  SeabedSpec spec_;
};

}  // namespace riser_sim
