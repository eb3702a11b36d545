// A physical effect on the spatial line (costmap-style layer, as the planar ForceTerm): generalised
// forces in natural coordinates, potential energy and non-conservative power, so that the energy
// balance is checkable. Terms are immutable parts of the Model3.
#pragma once
#include <string>
#include <vector>

#include "riser_sim/spatial/added_mass.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/stiffness.h"

namespace riser_sim {
namespace spatial {

class ForceTerm3 {
 public:
  virtual ~ForceTerm3() = default;
  virtual std::string name() const = 0;
  // Adds Q per rfe [A: N, Δ: N, e: N m] (size 7(n+1)) for the state kin at time t [s]. The e part
  // matters only up to multiples of e (the unit-length constraint takes those).
  virtual void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const = 0;
  // Potential energy of the conservative part [J].
  virtual double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const = 0;
  // Power [W] of the non-conservative part fed into the line.
  virtual double power(const Model3& model, const Kinematics3& kin, double t) const = 0;
  virtual double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
    addForces(model, kin, t, Q);
    return power(model, kin, t);
  }
  // Adds K = -∂Q/∂q and C = -∂Q/∂q' (stiffness.h) for the implicit schemes' structured solves. Default:
  // nothing; an omitted or approximate linearisation slows Newton, it does not change the converged step.
  virtual void addStiffness(const Model3& /*model*/, const Kinematics3& /*kin*/, double /*t*/,
                            Stiffness3& /*S*/) const {}
  // Hydrodynamic inertia: a term with hasInertia() adds per rfe the moments of its added mass (added_mass.h)
  // for the state kin, and reports that mass's kinetic energy [J] (the line's kinetic energy includes it).
  virtual bool hasInertia() const { return false; }
  virtual void addInertia(const Model3& /*model*/, const Kinematics3& /*kin*/,
                          std::vector<AddedMass3>& /*per_rfe*/) const {}
  virtual double kineticEnergy(const Model3& /*model*/, const Kinematics3& /*kin*/) const { return 0.0; }
};

}  // namespace spatial
}  // namespace riser_sim
