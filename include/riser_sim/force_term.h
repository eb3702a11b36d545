// A physical effect the scene switches on (costmap_2d-style layer). Each term adds its generalised
// forces in absolute coordinates and reports its energy / power so that energy balance is checkable.
#pragma once
#include <string>

#include "riser_sim/kinematics.h"
#include "riser_sim/model.h"

namespace riser_sim {

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual std::string name() const = 0;
  // Adds Q [N, N, N, N m] per rfe (size 4(n+1)) for the state in kin at time t [s].
  virtual void addForces(const Model& model, const Kinematics& kin, double t, VecX& Q) const = 0;
  // Terms with inertia add to the per-rfe mass blocks M_i and to the velocity terms h (moved to the left).
  virtual bool hasInertia() const { return false; }
  virtual void addInertia(const Model&, const Kinematics&, double /*t*/, AlignedVector<Mat4>& /*M*/,
                          VecX& /*h*/) const {}
  // Potential energy of the conservative part [J].
  virtual double potentialEnergy(const Model&, const Kinematics&) const { return 0.0; }
  // Power [W] of the non-conservative part (damping, drag, ...) fed into the line.
  virtual double power(const Model&, const Kinematics&, double /*t*/) const { return 0.0; }
};

}  // namespace riser_sim
