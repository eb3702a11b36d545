// Equations of motion behind one small interface: given the state, return accelerations.
#pragma once
#include <string>

#include "riser_sim/kinematics.h"
#include "riser_sim/model.h"
#include "riser_sim/top_motion.h"

namespace riser_sim {

class TermDataSet;

// Results of the last evaluation that outputs need (reactions, constraint error).
struct Reactions {
  Vec2 top = Vec2::Zero();     // force the line exerts on the hang-off point A_0 [N]
  Vec2 bottom = Vec2::Zero();  // force the line exerts on the bottom anchor (pinned) [N]
  AlignedVector<Vec2> joint;   // λ_k: force on rfe k-1 at its end (= minus force on rfe k at A_k), k=0..n+1
};

class Formulation {
 public:
  virtual ~Formulation() = default;
  virtual std::string name() const = 0;
  // Size of the position and of the velocity part of the state vector y = [q; v].
  virtual int positionSize() const = 0;
  // Fills the state for a line whose rfes have the given A_0, Δ_i, φ_i (and rates).
  virtual void packState(const Kinematics& kin, VecX& y) const = 0;
  // Kinematics of every rfe for state y.
  virtual void kinematics(const VecX& y, Kinematics& kin) const = 0;
  // dy/dt at time t; top gives A_0's motion.
  virtual void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) = 0;
  virtual const Reactions& reactions() const = 0;
  // Largest violation of the joint constraints for state y [m].
  virtual double constraintError(const VecX& y, const PointMotion& top) const = 0;
  // Kinematics of the last derivative() call.
  virtual const Kinematics& lastKinematics() const = 0;
  // Summed power of the terms' non-conservative parts at the last derivative() call [W].
  double lastTermPower() const { return last_term_power_; }
  // Largest joint-constraint violation seen by the last derivative() call [m] (0 when exact).
  virtual double lastConstraintError() const = 0;
  // Kinetic energy of the line (with every term's inertia) for state y [J].
  virtual double kineticEnergy(double t, const VecX& y) = 0;

  // --- Structured implicit solves (optional; O(n), see chain_shifted_solver.h) ---
  virtual bool hasShiftedSolve() const { return false; }
  // Linearises about the state of the last derivative() call at time t [s].
  virtual void linearize(double /*t*/) {}
  // x = (I - c J)^-1 b on [q; v] (the first 2p entries), J ≈ ∂(q', v')/∂(q, v) of that linearisation.
  virtual void factorShifted(double /*c*/) {}
  virtual void solveShifted(const VecX& /*b*/, VecX& /*x*/) {}

  // Run data of the model's terms (history such as the seabed's anchors), owned by the Simulator;
  // null (the default): the terms are evaluated without history.
  void setTermData(const TermDataSet* data) { term_data_ = data; }

 protected:
  const TermDataSet* term_data_ = nullptr;
  double last_term_power_ = 0.0;
};

}  // namespace riser_sim
