// Added mass in 3D (Morison inertia, paper eq. 13 with the axial part): on each submerged part, lumped at its
// centroid as the planar HydroInertia, the force -(C_a,n P + C_a,t N) ρ_w A_w a_c dξ, C_a,n = C_M - 1 across
// the rfe and C_a,t (hydrodynamics.axial_added_mass) along it. It enters the mass matrix (added_mass.h); the
// Froude-Krylov part is FroudeKrylov. Energy: ½ m_w v_cᵀ T v_c is kinetic; power() is ½ v_cᵀ T' v_c, the
// part of the force's power that T turning with e leaves over.
#pragma once
#include "riser_sim/line/line_sections.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/water.h"

namespace riser_sim {
namespace spatial {

class AddedMass : public ForceTerm3 {
 public:
  // A line section's own C_M, C_a,t (line_sections.h) replace them on its parts; section_added_mass: some
  // section has added mass of its own.
  AddedMass(const Water3& water, double ca_normal, double ca_axial, bool section_added_mass = false)
      : water_(water), ca_n_(ca_normal), ca_t_(ca_axial), section_added_mass_(section_added_mass) {}
  std::string name() const override { return "added_mass"; }
  void addForces(const Model3&, const Kinematics3&, double, VecX&) const override {}
  double potentialEnergy(const Model3&, const Kinematics3&, double) const override { return 0.0; }
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  bool hasInertia() const override { return ca_n_ != 0.0 || ca_t_ != 0.0 || section_added_mass_; }
  void addInertia(const Model3& model, const Kinematics3& kin, std::vector<AddedMass3>& per_rfe) const override;
  double kineticEnergy(const Model3& model, const Kinematics3& kin) const override;

 private:
  double sweep(const Model3& model, const Kinematics3& kin, bool energy) const;
  double caN(const LineSection& s) const {
    return std::isnan(s.hydro.inertia_coefficient) ? ca_n_ : s.hydro.inertia_coefficient - 1.0;
  }
  double caT(const LineSection& s) const { return orLine(s.hydro.axial_added_mass, ca_t_); }
  Water3 water_;
  double ca_n_, ca_t_;
  bool section_added_mass_;
};

}  // namespace spatial
}  // namespace riser_sim
