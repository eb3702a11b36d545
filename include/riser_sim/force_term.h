// A physical effect the scene switches on (costmap_2d-style layer). Each term adds its generalised
// forces in absolute coordinates and reports its energy / power so that energy balance is checkable.
#pragma once
#include <cmath>
#include <string>

#include "riser_sim/kinematics.h"
#include "riser_sim/model.h"
#include "riser_sim/stiffness.h"

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
  // Adds K = -∂Q/∂q and C = -∂Q/∂q' (see stiffness.h) for the implicit integrators' structured solves.
  // Returns false when the term gives none: it is then treated explicitly by those solves (fine for
  // non-stiff terms; the solves stay exact for every term that answers).
  virtual bool addStiffness(const Model&, const Kinematics&, double /*t*/, StiffnessBlocks&) const {
    return false;
  }
  // Potential energy of the conservative part [J].
  virtual double potentialEnergy(const Model&, const Kinematics&) const { return 0.0; }
  // Same at time t [s], for terms whose potential depends on time (internal flow u(t)).
  virtual double potentialEnergyAt(const Model& m, const Kinematics& k, double /*t*/) const {
    return potentialEnergy(m, k);
  }
  // Power [W] of the non-conservative part (damping, drag, ...) fed into the line.
  virtual double power(const Model&, const Kinematics&, double /*t*/) const { return 0.0; }
  // Run-state hooks for terms with history (seabed contact anchors): at the start of a run and
  // after every step. Terms keep such state in mutable members: one Simulator per Model.
  virtual bool hasRunState() const { return false; }
  // Seabed level y_b [m] for terms that model one (-inf otherwise); used by the statics' first guess.
  virtual double seabedLevel() const { return -INFINITY; }
  virtual void startRun(const Model&, const Kinematics&) const {}
  virtual void endStep(const Model&, const Kinematics&) const {}
};

}  // namespace riser_sim
