// A physical effect the scene switches on (costmap_2d-style layer). Each term adds its generalised
// forces in absolute coordinates and reports its energy / power so that energy balance is checkable.
// Terms are immutable parts of the Model; a term with history (the seabed's contact anchors) keeps it
// in a TermData that whoever runs the model owns (Pinocchio-style model + data): one model can drive
// any number of simulators.
#pragma once
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"
#include "riser_sim/planar/stiffness.h"

namespace riser_sim {

// Run data of one term (its history), made by ForceTerm::makeData() with every buffer preallocated.
class TermData {
 public:
  virtual ~TermData() = default;
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual std::string name() const = 0;
  // Every evaluation gets the term's run data: null for terms without history, and null when the
  // model is evaluated outside a run (statics): the term then acts as on a fresh run with no history.
  // Adds Q [N, N, N, N m] per rfe (size 4(n+1)) for the state in kin at time t [s].
  virtual void addForces(const Model& model, const TermData* data, const Kinematics& kin, double t, VecX& Q) const = 0;
  // Terms with inertia add to the per-rfe mass blocks M_i and to the velocity terms h (moved to the left).
  // Inertia depends on the state only, never on history.
  virtual bool hasInertia() const { return false; }
  virtual void addInertia(const Model&, const Kinematics&, double /*t*/, AlignedVector<Mat4>& /*M*/,
                          VecX& /*h*/) const {}
  // Adds K = -∂Q/∂q and C = -∂Q/∂q' (see stiffness.h) for the implicit integrators' structured solves.
  // Returns false when the term gives none: it is then treated explicitly by those solves (fine for
  // non-stiff terms; the solves stay exact for every term that answers).
  virtual bool addStiffness(const Model&, const TermData*, const Kinematics&, double /*t*/, StiffnessBlocks&) const {
    return false;
  }
  // Energy report (pure: a term states both, 0 where it has none; test_term_power checks
  // Q·q' = -dV/dt + P). Potential energy of the conservative part [J].
  virtual double potentialEnergy(const Model&, const TermData*, const Kinematics&) const = 0;
  // Same at time t [s], for terms whose potential depends on time (internal flow u(t)).
  virtual double potentialEnergyAt(const Model& m, const TermData* d, const Kinematics& k, double /*t*/) const {
    return potentialEnergy(m, d, k);
  }
  // Power [W] of the non-conservative part (damping, drag, ...) fed into the line.
  virtual double power(const Model&, const TermData*, const Kinematics&, double t) const = 0;
  // addForces() and returns power() in one pass: the simulation's derivative needs both at every stage.
  // Terms whose power repeats the work of their forces (drag, flow) override it.
  virtual double addForcesAndPower(const Model& model, const TermData* data, const Kinematics& kin, double t,
                                   VecX& Q) const {
    addForces(model, data, kin, t, Q);
    return power(model, data, kin, t);
  }
  // Seabed level y_b [m] for terms that model one (-inf otherwise); used by the statics' first guess.
  virtual double seabedLevel() const { return -INFINITY; }
  // The term as the statics see it at time t [s] when that differs from the term itself: a steady sea
  // (no waves, the current frozen at its velocity at t). Null: the term itself.
  virtual std::unique_ptr<ForceTerm> steadyTerm(double /*t*/) const { return nullptr; }
  // The same with the current's velocity x current_factor (the statics' continuation in the current); terms that
  // do not see the current ignore the factor.
  virtual std::unique_ptr<ForceTerm> steadyTerm(double t, double /*current_factor*/) const { return steadyTerm(t); }

  // --- History (optional) ---
  // The term's run data, preallocated for the model (null: the term has no history).
  virtual std::unique_ptr<TermData> makeData(const Model&) const { return nullptr; }
  // At the start of a run (state kin) and after every step; only called with data from makeData().
  // endStep() returns whether the history changed (the forces at an unchanged state are then different).
  virtual void startRun(const Model&, const Kinematics&, TermData&) const {}
  virtual bool endStep(const Model&, const Kinematics&, TermData&) const { return false; }
};

// The run data of every term of one model, indexed like model.terms(): owned by a Simulator (or the
// modal analysis), made once; startRun/endStep allocate nothing.
class TermDataSet {
 public:
  TermDataSet() = default;
  explicit TermDataSet(const Model& model) {
    for (const auto& term : model.terms()) {
      data_.push_back(term->makeData(model));
      any_ = any_ || data_.back() != nullptr;
    }
  }
  // Data of term k (null for terms without history, or for an empty set).
  const TermData* at(size_t k) const { return k < data_.size() ? data_[k].get() : nullptr; }
  bool any() const { return any_; }
  void startRun(const Model& model, const Kinematics& kin) {
    for (size_t k = 0; k < data_.size(); ++k)
      if (data_[k]) model.terms()[k]->startRun(model, kin, *data_[k]);
  }
  // Whether any term's history changed.
  bool endStep(const Model& model, const Kinematics& kin) {
    bool changed = false;
    for (size_t k = 0; k < data_.size(); ++k)
      if (data_[k]) changed = model.terms()[k]->endStep(model, kin, *data_[k]) || changed;
    return changed;
  }

 private:
  std::vector<std::unique_ptr<TermData>> data_;
  bool any_ = false;
};

// Sums over every term of the model; data: the run data of a Simulator (null outside a run).
inline void addTermForces(const Model& model, const TermDataSet* data, const Kinematics& kin, double t, VecX& Q) {
  const auto& terms = model.terms();
  for (size_t k = 0; k < terms.size(); ++k) terms[k]->addForces(model, data ? data->at(k) : nullptr, kin, t, Q);
}
// Both at once; returns the summed power (see ForceTerm::addForcesAndPower).
inline double addTermForcesAndPower(const Model& model, const TermDataSet* data, const Kinematics& kin, double t,
                                    VecX& Q) {
  const auto& terms = model.terms();
  double p = 0.0;
  for (size_t k = 0; k < terms.size(); ++k)
    p += terms[k]->addForcesAndPower(model, data ? data->at(k) : nullptr, kin, t, Q);
  return p;
}
inline void addTermStiffness(const Model& model, const TermDataSet* data, const Kinematics& kin, double t,
                             StiffnessBlocks& S) {
  const auto& terms = model.terms();
  for (size_t k = 0; k < terms.size(); ++k) terms[k]->addStiffness(model, data ? data->at(k) : nullptr, kin, t, S);
}
inline double termPotentialEnergy(const Model& model, const TermDataSet* data, const Kinematics& kin, double t) {
  const auto& terms = model.terms();
  double v = 0.0;
  for (size_t k = 0; k < terms.size(); ++k)
    v += terms[k]->potentialEnergyAt(model, data ? data->at(k) : nullptr, kin, t);
  return v;
}

}  // namespace riser_sim
