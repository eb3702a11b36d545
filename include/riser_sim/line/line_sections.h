// Line sections: the line as an ordered list of sections from the top, each with its own length, segment
// count and properties, plus bend stiffeners (EI varying near an end). resolveLine() turns them into the
// per-segment data the RFEM Model holds (segment lengths d_j, the section of each segment, the bending
// compliance of each segment). A uniform line is one section.
#pragma once
#include <cmath>
#include <vector>

#include "riser_sim/line/line_properties.h"

namespace riser_sim {

// Hydrodynamics of one section; NaN: the scene's hydrodynamics block (the force term's coefficient).
struct SectionHydro {
  double drag_diameter = 0.0;                       // D of the Morison drag [m]; 0: the section's outer_diameter
  double drag_normal = NAN, drag_tangential = NAN;  // C_d across / along
  double inertia_coefficient = NAN;                 // C_M across (added mass C_M - 1 on the section's displaced area)
  double axial_added_mass = NAN;                    // C_a,t along
};

// Buoyancy modules clamped on a section, as a vendor sheet gives them (smeared by smearModules).
struct BuoyancyModules {
  bool enabled = false;
  double outer_diameter = 0.0;  // D_m [m]
  double length = 0.0;          // l_m, one module along the line [m]
  double pitch = 0.0;           // p, centre to centre [m], >= l_m
  double mass = 0.0;            // m_m, one module in air [kg]
  double volume = 0.0;          // V_m, one module's displaced volume, the pipe's not included [m^3]
  double drag_normal = 0.0;     // C_d,m across, on D_m
  double added_mass = NAN;      // C_a,m across, on V_m; NaN: the pipe's C_M - 1
};

struct LineSection {
  double length = 0.0;   // [m]
  int elements = 1;      // segments of length length / elements
  LineProperties props;  // outer_diameter sets the displaced area (buoyancy, added mass, Froude-Krylov)
  SectionHydro hydro;
  BuoyancyModules modules;  // the sheet the section's smeared properties came from (enabled: smeared)
  double dragDiameter() const { return hydro.drag_diameter > 0.0 ? hydro.drag_diameter : props.outer_diameter; }
};

inline double orLine(double section_value, double line_value) {
  return std::isnan(section_value) ? line_value : section_value;
}

// Smears modules over the section (per pitch p, f = l_m / p, pipe of outer diameter D, area A = π D²/4):
//   mass per length      m + m_m / p
//   displaced area       A_eq = A + V_m / p                   (outer_diameter := sqrt(4 A_eq / π))
//   normal drag          C_d D_drag = C_d,m D_m f + C_d,n D (1 - f), D_drag = D_m f + D (1 - f)
//   axial drag           C_d,t D (the pipe's skin; the modules' ends are not modelled)
//   added mass across    (C_M - 1) A_eq,eq = (C_M - 1) A + C_a,m V_m / p
// cd_n, cd_t, cm: the pipe's coefficients (the section's own or the hydrodynamics block's). Once per section.
void smearModules(LineSection& section, double cd_n, double cd_t, double cm);

// Bending stiffness EI(x) at distance x [m] from the end it sits at, over [0, length]; beyond, the section's.
// Conical: EI_line + E_s π/64 (D(x)⁴ - D_line⁴), D linear from root_diameter at x = 0 to tip_diameter at
// x = length (a sleeve bending with the pipe). Table: knots (x, EI) linear between, x from 0 to length.
struct BendStiffener {
  bool at_top = true;
  double length = 0.0;  // [m]
  bool conical = false;
  double modulus = 0.0, root_diameter = 0.0, tip_diameter = 0.0, bore = 0.0, line_EI = 0.0;  // conical
  std::vector<double> x, EI;                                                                 // table
  double at(double x) const;  // EI [N m^2], x clamped to [0, length]
};

// Per-segment data of a line (segments j = 0..n-1 from the top).
struct ResolvedLine {
  std::vector<double> segment;     // d_j [m]
  std::vector<int> section;        // section index of segment j
  std::vector<double> compliance;  // ∫ ds / EI(s) over segment j [1/(N m)]; +inf where EI = 0
  std::vector<bool> stiffened;     // a stiffener covers part of segment j
};

// Throws std::invalid_argument naming the section (line.sections[k].key) on a bad value.
ResolvedLine resolveLine(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners);

// ∫ ds / EI over [a, b] (arc length from the top [m]) of a line of total length L whose EI outside the
// stiffeners is EI0 (one section): Gauss-Legendre per piece between the stiffener's knots.
double bendingCompliance(double a, double b, double L, double EI0, const std::vector<BendStiffener>& stiffeners);

}  // namespace riser_sim
