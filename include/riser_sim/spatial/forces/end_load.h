// A constant force F [N] on the end of the line (the end of rfe n), the 3D counterpart of the planar
// EndLoad (initial.end_force: hold): V = -F·x_end, conservative.
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class EndLoad : public ForceTerm3 {
 public:
  explicit EndLoad(const Vec3& force) : force_(force) {}
  std::string name() const override { return "end_load"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3&, const Kinematics3&, double) const override { return 0.0; }
  const Vec3& force() const { return force_; }

 private:
  Vec3 force_;
};

}  // namespace spatial
}  // namespace riser_sim
