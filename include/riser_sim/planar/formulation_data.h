// What one evaluation of a Formulation computed, and the workspaces it needs (Pinocchio's Model / Data
// split): the formulation holds only the model and its settings and is immutable; every evaluation writes
// into a FormulationData made by that formulation (Formulation::makeData(), sized once, so evaluating
// allocates nothing). One formulation can serve several data objects.
#pragma once
#include <limits>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/motion/top_motion.h"

namespace riser_sim {

class Formulation;
class TermDataSet;

// Forces at the joints and ends of the line.
struct Reactions {
  Vec2 top = Vec2::Zero();     // force the line exerts on the hang-off point A_0 [N]
  Vec2 bottom = Vec2::Zero();  // force the line exerts on the bottom anchor (pinned) [N]
  AlignedVector<Vec2> joint;   // λ_k: force on rfe k-1 at its end (= minus force on rfe k at A_k), k=0..n+1
};

class FormulationData {
 public:
  FormulationData(const Formulation& owner, int bodies);
  virtual ~FormulationData() = default;
  FormulationData(const FormulationData&) = delete;  // workspaces may point into each other
  FormulationData& operator=(const FormulationData&) = delete;

  // The formulation that made this data; the only one that accepts it (checked).
  const Formulation& owner() const { return *owner_; }

  // Input set by the caller: run data of the model's terms (history such as the seabed's anchors);
  // null: the terms are evaluated without history.
  const TermDataSet* term_data = nullptr;

  // Written by Formulation::derivative(): its inputs (t, the top motion) and what it computed at them.
  double t = std::numeric_limits<double>::quiet_NaN();  // NaN: nothing evaluated yet
  PointMotion top;
  Kinematics kin;                 // every rfe's kinematics
  Reactions reactions;            // joint and end forces
  double term_power = 0.0;        // summed power of the terms' non-conservative parts [W]
  double constraint_error = 0.0;  // largest joint-constraint violation seen [m] (0 when joints hold exactly)

 private:
  friend class Formulation;
  const Formulation* owner_;
  // Formulation::kineticEnergy()'s workspace (the evaluation above stays as it was).
  Kinematics energy_kin_;
  AlignedVector<Mat4> energy_M_;
  VecX energy_h_;
};

}  // namespace riser_sim
