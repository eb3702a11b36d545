// Internal flow at speed u(t) = u0 + u' t relative to the wall (paper eqs. 17-24, re-derived).
// The fluid's mass moving with the pipe is part of the line mass (LineProperties::content_mass_per_length);
// this term adds what the flow adds to the Lagrangian:
//   T2 = ρ_l u Σ_i [A'_i·P_i + Δ'_i K_i + φ'_i R_i]   (Coriolis / gyroscopic, couples φ_{i±1})
//   T3 = ½ ρ_l u² Σ_i [l1 (2/3 + cos(φ_{i-1} - φ_i)/3) + l2 (2/3 + cos(φ_i - φ_{i+1})/3)]  (centrifugal)
// with the paper's interpolated flow direction (eq. 19). Q = -(d/dt ∂T2/∂q' - ∂T2/∂q) + ∂T3/∂q.
// Energy: the Jacobi integral h = T + V - T3, so potentialEnergy() = -T3 and power() = -∂L/∂t.
#pragma once
#include <string>

#include "riser_sim/scene/choices.h"
#include "riser_sim/planar/force_term.h"

namespace riser_sim {

struct InternalFlowSpec {
  double density = 0.0;       // ρ_f [kg/m^3]
  double velocity = 0.0;      // u0 [m/s]
  double acceleration = 0.0;  // u' [m/s^2]
  // pipe_flow: open system, the classical limit (default, docs/limitations.md says why); paper: the
  // paper's closed-system Lagrangian (eqs. 17-24), kept to reproduce its Fig. 14.
  FlowModelKind model = FlowModelKind::kPipeFlow;
};

class InternalFlow : public ForceTerm {
 public:
  InternalFlow(const InternalFlowSpec& spec, double flow_area) : spec_(spec), rho_l_(spec.density * flow_area) {}
  std::string name() const override { return "internal_flow"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const override {
    return potentialEnergyAt(model, nullptr, kin, 0.0);
  }
  double potentialEnergyAt(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  double u(double t) const { return spec_.velocity + spec_.acceleration * t; }
  // ∂T2/∂q' / (ρ_l u)·q' summed (Σ t2) and T3 / (½ ρ_l u²) (F), for energy bookkeeping and tests.
  double sumT2(const Model& model, const Kinematics& kin) const;
  double shapeF(const Model& model, const Kinematics& kin) const;

 private:
  InternalFlowSpec spec_;
  double rho_l_;
};

// Open-system pipe flow (Benjamin / Paidoussis): the force of the flowing contents on the pipe,
// f = -ρ_l (2u ∂v/∂s + u² ∂²r/∂s² + u' ∂r/∂s) per unit length, discretised on the rfes: u² r'' as a point
// force -ρ_l u² (e_i - e_{i-1}) at every joint A_i (outward on a bend: the centrifugal term), the
// Coriolis part -2ρ_l u φ'_i n_i per length on each part and -2ρ_l u Δ'_i e_i at each spring, the u'
// part -ρ_l u' e_i per length. No end thrust. Not conservative: power() = Σ F·v.
class PipeFlow : public ForceTerm {
 public:
  PipeFlow(const InternalFlowSpec& spec, double flow_area) : spec_(spec), rho_l_(spec.density * flow_area) {}
  std::string name() const override { return "pipe_flow"; }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model&, const TermData*, const Kinematics&) const override {
    return 0.0;
  }  // open system
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  double addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                           VecX& Q) const override;

 private:
  // Visits every force (rfe, s0, kappa, F) the flow applies.
  template <class Visit>
  void forces(const Model& model, const Kinematics& kin, double t, Visit&& visit) const;
  InternalFlowSpec spec_;
  double rho_l_;
};

}  // namespace riser_sim
