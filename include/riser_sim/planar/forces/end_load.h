// A constant force F [N] (world axes) on the end of the line (end of rfe n): e.g. the horizontal
// force that holds a displaced end in its static position (initial.end_force: hold), the bottom
// tension of the pipeline already laid beyond a J-lay touchdown. Conservative: V = -F·r_end.
#pragma once
#include "riser_sim/planar/force_term.h"

namespace riser_sim {

class EndLoad : public ForceTerm {
 public:
  explicit EndLoad(const Vec2& force) : force_(force) {}
  std::string name() const override { return "end_load"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                    StiffnessBlocks& S) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override;
  double power(const Model&, const TermData*, const Kinematics&, double) const override { return 0.0; }  // conservative
  const Vec2& force() const { return force_; }

 private:
  Vec2 force_;
};

}  // namespace riser_sim
