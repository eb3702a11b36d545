// Morison inertia (paper eq. 13, 15) on each submerged part, across and along it (the paper's normal part and
// the axial one, as peer codes): dF = [C_M ρ_w A_w a_w,η - (C_M - 1) ρ_w A_w a_η] n dξ
// + [(1 + C_a,t) ρ_w A_w a_w,ξ - C_a,t ρ_w A_w a_ξ] e dξ. The added masses (C_M - 1, C_a,t) ρ_w A_w enter the
// mass matrix (implicit, not lagged); the Froude-Krylov parts are applied forces.
#pragma once
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {

class HydroInertia : public ForceTerm {
 public:
  // inertia_coefficient C_M (across the line), axial_added_mass C_a,t (along it); a line section's own values
  // (line_sections.h) replace them on its parts. section_added_mass: some section has added mass of its own.
  HydroInertia(const WaterKinematics& water, double inertia_coefficient, double axial_added_mass = 0.0,
               bool section_added_mass = false)
      : water_(water), cm_(inertia_coefficient), ca_t_(axial_added_mass), section_added_mass_(section_added_mass) {}
  std::string name() const override { return "hydro_inertia"; }
  std::unique_ptr<ForceTerm> steadyTerm(double t) const override {
    return std::make_unique<HydroInertia>(water_.steady(t), cm_, ca_t_, section_added_mass_);
  }
  std::unique_ptr<ForceTerm> steadyTerm(double t, double current_factor) const override {
    return std::make_unique<HydroInertia>(water_.steady(t, current_factor), cm_, ca_t_, section_added_mass_);
  }
  void addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const override;
  bool hasInertia() const override { return cm_ != 1.0 || ca_t_ != 0.0 || section_added_mass_; }
  void addInertia(const Model& model, const Kinematics& kin, double t, AlignedVector<Mat4>& M, VecX& h) const override;
  double power(const Model& model, const TermData*, const Kinematics& kin, double t) const override;
  double potentialEnergy(const Model&, const TermData*, const Kinematics&) const override {
    return 0.0;
  }  // inertia + Froude-Krylov: power() only
  double addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                           VecX& Q) const override;

 private:
  // Adds the Froude-Krylov forces to *Q (when Q is given); returns the term's power [W].
  double sweep(const Model& model, const Kinematics& kin, double t, VecX* Q) const;
  WaterKinematics water_;
  double cm_, ca_t_;
  bool section_added_mass_;
};

}  // namespace riser_sim
