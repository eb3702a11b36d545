// Cross-section and material of the line, given either from geometry or directly.
#pragma once
#include <string>

namespace riser_sim {

struct LineProperties {
  double EA = 0.0;                       // axial stiffness [N]
  double EI = 0.0;                       // bending stiffness [N m^2]
  double mass_per_length = 0.0;          // structural mass [kg/m]
  double outer_diameter = 0.0;           // [m], 0 when not given (no hydrodynamics then)
  double inner_diameter = 0.0;           // [m]
  double content_mass_per_length = 0.0;  // internal fluid ρ_f A_f [kg/m]: moves with the pipe
  double axial_damping = 0.0;            // c_EA [N s]: axial force per unit strain rate
  // ζ of each element's own axial mode (its spring between its two halves, reduced mass m1 m2 / (m1 + m2)):
  // adds 2 ζ sqrt(k_i m_r,i) to the element's damper (the damping ratio other tools quote per segment).
  double axial_damping_ratio = 0.0;
  double bending_damping = 0.0;  // c_EI [N m^2 s]: moment per unit curvature rate

  // Pipe of outer/inner diameter [m], Young's modulus [Pa], density [kg/m^3].
  static LineProperties fromGeometry(double outer_diameter, double inner_diameter, double youngs_modulus,
                                     double density);
  double wallArea() const;      // [m^2]
  double internalArea() const;  // [m^2]
  double externalArea() const;  // [m^2]
};

}  // namespace riser_sim
