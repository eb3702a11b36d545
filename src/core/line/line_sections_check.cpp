// checkLineSections: what a Scene's line.sections and line.bend_stiffener must satisfy, naming the key.
#include <cmath>
#include <string>

#include "riser_sim/scene/scene_check.h"

namespace riser_sim {

namespace {

std::string num(double v) {
  std::ostringstream o;
  o.precision(9);
  o << v;
  return o.str();
}

std::optional<SetupError> checkSection(const Scene& s, const LineSection& sec, const std::string& key) {
  const LineProperties& p = sec.props;
  auto bad = [&](const std::string& k, const std::string& m) { return SetupError{key + "." + k, m}; };
  if (!(sec.length > 0.0)) return bad("length", "must be > 0, got " + num(sec.length));
  if (sec.elements < 1) return bad("elements", "must be >= 1, got " + std::to_string(sec.elements));
  if (!(p.mass_per_length > 0.0)) return bad("mass_per_length", "must be > 0, got " + num(p.mass_per_length));
  if (s.options.axial_flexibility && !(p.EA > 0.0)) return bad("EA", "must be > 0, got " + num(p.EA));
  if (!(p.EA >= 0.0)) return bad("EA", "must be >= 0, got " + num(p.EA));
  if (!(p.EI >= 0.0)) return bad("EI", "must be >= 0, got " + num(p.EI));
  if (!(p.outer_diameter >= 0.0)) return bad("outer_diameter", "must be >= 0, got " + num(p.outer_diameter));
  if (!(p.inner_diameter >= 0.0)) return bad("inner_diameter", "must be >= 0, got " + num(p.inner_diameter));
  if (p.inner_diameter > 0.0 && !(p.inner_diameter < p.outer_diameter))
    return bad("inner_diameter", "must be smaller than the section's outer_diameter (" + num(p.outer_diameter) +
                                     " m), got " + num(p.inner_diameter));
  if (!(p.axial_damping >= 0.0)) return bad("axial_damping", "must be >= 0, got " + num(p.axial_damping));
  if (!(p.axial_damping_ratio >= 0.0 && p.axial_damping_ratio <= 1.0))
    return bad("axial_damping_ratio", "must be in [0, 1], got " + num(p.axial_damping_ratio));
  if (!(p.bending_damping >= 0.0)) return bad("bending_damping", "must be >= 0, got " + num(p.bending_damping));
  if ((s.water.enabled || s.hydro.enabled) && !(p.outer_diameter > 0.0))
    return bad("outer_diameter", "is needed (> 0) for buoyancy and hydrodynamic forces");
  const SectionHydro& h = sec.hydro;
  if (!(h.drag_diameter >= 0.0)) return bad("drag_diameter", "must be >= 0, got " + num(h.drag_diameter));
  if (!std::isnan(h.drag_normal) && !(h.drag_normal >= 0.0)) return bad("drag_normal", "must be >= 0");
  if (!std::isnan(h.drag_tangential) && !(h.drag_tangential >= 0.0)) return bad("drag_tangential", "must be >= 0");
  if (!std::isnan(h.inertia_coefficient) && !(h.inertia_coefficient >= 1.0))
    return bad("inertia_coefficient", "C_M must be >= 1 (added mass C_M - 1 >= 0), got " + num(h.inertia_coefficient));
  if (!std::isnan(h.axial_added_mass) && !(h.axial_added_mass >= 0.0)) return bad("axial_added_mass", "must be >= 0");
  const bool hydro_keys = h.drag_diameter > 0.0 || !std::isnan(h.drag_normal) || !std::isnan(h.drag_tangential) ||
                          !std::isnan(h.inertia_coefficient) || !std::isnan(h.axial_added_mass);
  if (hydro_keys && !s.hydro.enabled)
    return bad(h.drag_diameter > 0.0 ? "drag_diameter" : "drag_normal",
               "a section's hydrodynamics need the hydrodynamics block (and environment.water)");
  const InternalFlowSpec& f = s.internal_fluid;
  if (f.density > 0.0 && !(p.inner_diameter > 0.0)) return bad("inner_diameter", "is needed (> 0) for internal_fluid");
  if (f.density > 0.0 && (f.velocity != 0.0 || f.acceleration != 0.0) && p.inner_diameter != s.line.inner_diameter)
    return bad("inner_diameter", "must be line.inner_diameter (" + num(s.line.inner_diameter) +
                                     " m) with a flow in "
                                     "internal_fluid (the flow term carries one flow area), got " +
                                     num(p.inner_diameter));
  return std::nullopt;
}

std::optional<SetupError> checkStiffener(const Scene& s, const BendStiffener& b) {
  const std::string key = "line.bend_stiffener";
  auto bad = [&](const std::string& k, const std::string& m) { return SetupError{key + "." + k, m}; };
  if (!(b.length > 0.0)) return bad("length", "must be > 0, got " + num(b.length));
  const LineSection& end = b.at_top ? s.sections.front() : s.sections.back();
  if (!(b.length <= end.length))
    return bad("length", num(b.length) + " m is longer than the " + std::string(b.at_top ? "top" : "bottom") +
                             " section it sits on (" + num(end.length) + " m)");
  if (!s.options.bending) return bad("length", "needs bending springs (line.bending: true)");
  if (b.conical) {
    if (!(b.modulus > 0.0)) return bad("youngs_modulus", "must be > 0, got " + num(b.modulus));
    if (!(b.bore > 0.0))
      return bad("tip_diameter", "a conical stiffener needs the line's outer_diameter (> 0): its bore");
    if (!(b.tip_diameter > b.bore))
      return bad("tip_diameter",
                 "must be larger than the line's outer diameter (" + num(b.bore) + " m), got " + num(b.tip_diameter));
    if (!(b.root_diameter >= b.tip_diameter))
      return bad("root_diameter",
                 "must be >= tip_diameter (" + num(b.tip_diameter) + " m), got " + num(b.root_diameter));
    return std::nullopt;
  }
  if (b.x.size() < 2 || b.x.size() != b.EI.size()) return bad("table", "needs at least 2 rows [x, EI]");
  if (b.x.front() != 0.0) return bad("table[0][0]", "the first x must be 0 (at the end), got " + num(b.x.front()));
  for (size_t k = 0; k < b.x.size(); ++k) {
    const std::string row = "table[" + std::to_string(k) + "]";
    if (k > 0 && !(b.x[k] > b.x[k - 1])) return bad(row + "[0]", "x must increase, got " + num(b.x[k]));
    if (!(b.EI[k] > 0.0)) return bad(row + "[1]", "EI must be > 0, got " + num(b.EI[k]));
  }
  if (std::abs(b.x.back() - b.length) > 1e-9 * b.length)
    return bad("table[" + std::to_string(b.x.size() - 1) + "][0]",
               "the last x must be the stiffener's length (" + num(b.length) + " m), got " + num(b.x.back()));
  return std::nullopt;
}

}  // namespace

std::optional<SetupError> checkLineSections(const Scene& s) {
  if (s.sections.empty()) {
    if (!s.stiffeners.empty()) return SetupError{"line.bend_stiffener", "needs the line as sections (internal)"};
    return std::nullopt;
  }
  double L = 0.0;
  long n = 0;
  for (size_t k = 0; k < s.sections.size(); ++k) {
    if (const auto e = checkSection(s, s.sections[k], "line.sections[" + std::to_string(k) + "]")) return e;
    L += s.sections[k].length;
    n += s.sections[k].elements;
  }
  if (!(std::abs(L - s.length) <= 1e-9 * L))
    return SetupError{"line.length", "is " + num(s.length) + " m but the sections add up to " + num(L) + " m"};
  if (n != s.elements)
    return SetupError{"line.elements",
                      "is " + std::to_string(s.elements) + " but the sections have " + std::to_string(n)};
  if (s.stiffeners.size() > 1) return SetupError{"line.bend_stiffener", "one stiffener per line"};
  for (const BendStiffener& b : s.stiffeners)
    if (const auto e = checkStiffener(s, b)) return e;
  if (s.torsion.enabled) {
    const double d0 = s.sections[0].length / s.sections[0].elements;
    for (size_t k = 1; k < s.sections.size(); ++k)
      if (s.sections[k].length / s.sections[k].elements != d0)
        return SetupError{"line.torsion", "needs segments of one length: line.sections[" + std::to_string(k) +
                                              "] has " + num(s.sections[k].length / s.sections[k].elements) +
                                              " m, line.sections[0] " + num(d0) + " m"};
  }
  if (s.bending_axes.enabled)
    return SetupError{"line.EI", "a pair [EI_1, EI_2] needs a line without sections or a stiffener"};
  return std::nullopt;
}

}  // namespace riser_sim
