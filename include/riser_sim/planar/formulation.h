// Equations of motion behind one small interface, in the style of Pinocchio's aba(model, data, q, v, tau):
// a Formulation is immutable (it holds the model and its settings); every call takes its inputs (time,
// state, top motion) explicitly and writes what it computed into a FormulationData made by makeData().
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "riser_sim/planar/formulation_data.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {

class Formulation {
 public:
  explicit Formulation(const Model& model) : model_(model) {}
  virtual ~Formulation() = default;
  virtual std::string name() const = 0;
  const Model& model() const { return model_; }
  // Size of the position and of the velocity part of the state vector y = [q; v].
  virtual int positionSize() const = 0;
  // Data for this formulation's evaluations, sized once (evaluating then allocates nothing).
  virtual std::unique_ptr<FormulationData> makeData() const = 0;
  // Fills the state for a line whose rfes have the given A_0, Δ_i, φ_i (and rates).
  virtual void packState(const Kinematics& kin, VecX& y) const = 0;
  // Kinematics of every rfe for state y with A_0 moving as `top` (the chain formulations hang the line
  // from top.p, top.v; the absolute one has A_0 in y and ignores it).
  virtual void kinematics(const VecX& y, const PointMotion& top, Kinematics& kin) const = 0;
  // dy/dt at time t [s], A_0 moving as `top`. data then holds this evaluation: t, top, kin, reactions,
  // term_power, constraint_error (FormulationData).
  virtual void derivative(double t, const VecX& y, const PointMotion& top, VecX& dy, FormulationData& data) const = 0;
  // Largest violation of the joint constraints for state y [m].
  virtual double constraintError(const VecX& y, const PointMotion& top) const = 0;
  // Kinetic energy of the line (with every term's inertia) for state y [J]. Uses a workspace of its own in
  // data: data's evaluation is left as it was.
  double kineticEnergy(double t, const VecX& y, const PointMotion& top, FormulationData& data) const;
  // Whether data holds this formulation's evaluation at exactly (t, y, top).
  bool evaluatedAt(double t, const VecX& y, const PointMotion& top, const FormulationData& data) const;

  // --- Structured implicit solves (optional; O(n), see chain_shifted_solver.h) ---
  // Without them the three calls below throw std::logic_error.
  virtual bool hasShiftedSolve() const { return false; }
  // Linearises about the evaluation at (t, y, top) into data's solver workspace: data's evaluation is used
  // when it was made at exactly these inputs (evaluatedAt), else linearize() evaluates there first (data
  // then holds that evaluation). The linearisation stays in data until the next linearize().
  virtual void linearize(double t, const VecX& y, const PointMotion& top, FormulationData& data) const;
  // Factorises I - c J for data's linearisation, J ≈ ∂(q', v')/∂(q, v) (throws before any linearize()).
  virtual void factorShifted(double c, FormulationData& data) const;
  // x = (I - c J)^-1 b on [q; v] (the first 2p entries) with data's factorisation (throws before any
  // factorShifted() on the current linearisation).
  virtual void solveShifted(const VecX& b, VecX& x, FormulationData& data) const;

 protected:
  // data as this formulation's own data type D; throws std::invalid_argument when another formulation
  // made it.
  template <class D>
  D& dataOf(FormulationData& data) const {
    checkOwner(data);
    return static_cast<D&>(data);
  }
  void checkOwner(const FormulationData& data) const {
    if (&data.owner() != this) throw std::invalid_argument(name() + " formulation: data made by another formulation");
  }
  // Whether kin holds exactly the coordinates and rates of state y (as kinematics() copies them).
  virtual bool holdsState(const VecX& y, const Kinematics& kin) const = 0;

  const Model& model_;
};

}  // namespace riser_sim
