// line.sections and line.bend_stiffener: each section inherits what it does not give from the line block;
// buoyancy modules are smeared once the hydrodynamics block is read (finishLineSections).
#include <cmath>
#include <string>

#include "riser_sim/scene/scene_check.h"
#include "scene_section.h"

namespace riser_sim {
namespace scene_detail {

namespace {

const std::vector<std::string> kSectionKeys = {"length",
                                               "elements",
                                               "segment_length",
                                               "outer_diameter",
                                               "inner_diameter",
                                               "youngs_modulus",
                                               "density",
                                               "EA",
                                               "EI",
                                               "mass_per_length",
                                               "axial_damping",
                                               "axial_damping_ratio",
                                               "bending_damping",
                                               "drag_diameter",
                                               "drag_normal",
                                               "drag_tangential",
                                               "inertia_coefficient",
                                               "axial_added_mass",
                                               "buoyancy_modules"};

LineSection parseOne(const Section& sec, const Scene& s) {
  LineSection out;
  out.length = sec.number("length");
  requirePositive(sec.key("length"), out.length);
  if (sec.has("elements") && sec.has("segment_length"))
    throw SceneError(sec.key("segment_length"), "give either elements or segment_length, not both");
  if (sec.has("segment_length")) {
    const double d = sec.number("segment_length");
    requirePositive(sec.key("segment_length"), d);
    const double n = std::ceil(out.length / d - 1e-9);
    if (!(n <= kMaxSceneElements))
      throw SceneError(sec.key("segment_length"),
                       "gives " + formatNumber(n) + " elements, more than " + std::to_string(kMaxSceneElements));
    out.elements = std::max(1, int(n));
  } else {
    out.elements = sec.integer("elements");
    if (out.elements < 1) throw SceneError(sec.key("elements"), "must be >= 1, got " + std::to_string(out.elements));
  }
  LineProperties& p = out.props;
  p = s.line;  // inherited
  p.outer_diameter = sec.number("outer_diameter", p.outer_diameter);
  p.inner_diameter = sec.number("inner_diameter", p.inner_diameter);
  if (sec.has("youngs_modulus") || sec.has("density")) {  // geometry + material: EA, EI and mass from them
    for (const char* k : {"EA", "EI", "mass_per_length"})
      if (sec.has(k))
        throw SceneError(sec.key(k), "give either youngs_modulus and density or EA, EI and mass_per_length, not both");
    const double E = sec.number("youngs_modulus"), rho = sec.number("density");
    requirePositive(sec.key("youngs_modulus"), E);
    requirePositive(sec.key("density"), rho);
    requirePositive(sec.key("outer_diameter"), p.outer_diameter);
    const LineProperties g = LineProperties::fromGeometry(p.outer_diameter, p.inner_diameter, E, rho);
    p.EA = g.EA;
    p.EI = g.EI;
    p.mass_per_length = g.mass_per_length;
  } else {
    p.EA = sec.number("EA", p.EA);
    if (sec.has("EI") && sec.at("EI").IsSequence())
      throw SceneError(sec.key("EI"), "a pair [EI_1, EI_2] is a line-level key (line.EI); a section takes one EI");
    p.EI = sec.number("EI", p.EI);
    p.mass_per_length = sec.number("mass_per_length", p.mass_per_length);
  }
  p.axial_damping = sec.number("axial_damping", p.axial_damping);
  p.axial_damping_ratio = sec.number("axial_damping_ratio", p.axial_damping_ratio);
  p.bending_damping = sec.number("bending_damping", p.bending_damping);
  SectionHydro& h = out.hydro;
  h.drag_diameter = sec.number("drag_diameter", 0.0);
  h.drag_normal = sec.number("drag_normal", NAN);
  h.drag_tangential = sec.number("drag_tangential", NAN);
  h.inertia_coefficient = sec.number("inertia_coefficient", NAN);
  h.axial_added_mass = sec.number("axial_added_mass", NAN);
  if (sec.has("buoyancy_modules")) {
    const Section m = sec.section("buoyancy_modules",
                                  {"outer_diameter", "length", "pitch", "mass", "volume", "drag_normal", "added_mass"});
    BuoyancyModules& b = out.modules;
    b.enabled = true;
    b.outer_diameter = m.number("outer_diameter");
    b.length = m.number("length");
    b.pitch = m.number("pitch");
    b.mass = m.number("mass");
    b.volume = m.number("volume");
    b.drag_normal = m.number("drag_normal");
    b.added_mass = m.number("added_mass", NAN);
    const double D = p.outer_diameter;
    if (!(D > 0.0)) throw SceneError(sec.key("outer_diameter"), "is needed (> 0) under buoyancy modules");
    if (!(b.outer_diameter > D))
      throw SceneError(m.key("outer_diameter"), "must be larger than the pipe's outer diameter (" + formatNumber(D) +
                                                    " m), got " + formatNumber(b.outer_diameter));
    requirePositive(m.key("length"), b.length);
    requirePositive(m.key("pitch"), b.pitch);
    if (!(b.length <= b.pitch))
      throw SceneError(m.key("pitch"),
                       "must be >= the module length (" + formatNumber(b.length) + " m), got " + formatNumber(b.pitch));
    requireNonNegative(m.key("mass"), b.mass);
    requirePositive(m.key("volume"), b.volume);
    const double annulus = M_PI / 4.0 * (b.outer_diameter * b.outer_diameter - D * D) * b.length;
    if (!(b.volume <= annulus * (1.0 + 1e-9)))
      throw SceneError(m.key("volume"), formatNumber(b.volume) +
                                            " m^3 is more than a module of that outer diameter "
                                            "and length displaces around the pipe (" +
                                            formatNumber(annulus) + " m^3)");
    requireNonNegative(m.key("drag_normal"), b.drag_normal);
    if (m.has("added_mass")) requireNonNegative(m.key("added_mass"), b.added_mass);
    if (sec.has("drag_diameter"))
      throw SceneError(sec.key("drag_diameter"), "is set by buoyancy_modules (the smeared modules' drag)");
  }
  return out;
}

// One stiffener: conical (root_diameter, tip_diameter, youngs_modulus) or a table EI: [[x, EI], ...].
BendStiffener parseStiffener(const Section& st, const Scene& s) {
  BendStiffener b;
  const std::string end = st.choice("end", "top", {"top", "bottom"});
  b.at_top = end == "top";
  b.length = st.number("length");
  requirePositive(st.key("length"), b.length);
  const LineSection& sec = b.at_top ? s.sections.front() : s.sections.back();
  if (st.has("table")) {
    for (const char* k : {"root_diameter", "tip_diameter", "youngs_modulus"})
      if (st.has(k)) throw SceneError(st.key(k), "give either a table or a conical stiffener's geometry, not both");
    const YAML::Node t = st.at("table");
    const std::string key = st.key("table");
    if (!t.IsSequence() || t.size() < 2)
      throw SceneError(key, "expected a list of at least 2 [x, EI], got " + describe(t));
    for (size_t k = 0; k < t.size(); ++k) {
      const Vec2 row = toVec2(t[k], key + "[" + std::to_string(k) + "]");
      b.x.push_back(row.x());
      b.EI.push_back(row.y());
    }
  } else {
    b.conical = true;
    b.root_diameter = st.number("root_diameter");
    b.tip_diameter = st.number("tip_diameter");
    b.modulus = st.number("youngs_modulus");
    b.bore = sec.props.outer_diameter;
    b.line_EI = sec.props.EI;
  }
  return b;
}

}  // namespace

void parseLineSections(const Section& line, Scene& s) {
  s.sections.clear();
  s.stiffeners.clear();
  if (line.has("sections")) {
    const YAML::Node list = line.at("sections");
    const std::string key = line.key("sections");
    if (!list.IsSequence() || list.size() == 0)
      throw SceneError(key, "expected a list of sections from the top, got " + describe(list));
    for (size_t k = 0; k < list.size(); ++k)
      s.sections.push_back(parseOne(Section(list[k], key + "[" + std::to_string(k) + "]", kSectionKeys), s));
    double L = 0.0;
    long n = 0;
    for (const LineSection& sec : s.sections) L += sec.length, n += sec.elements;
    if (line.has("length") && !(std::abs(L - s.length) <= 1e-9 * L))
      throw SceneError(line.key("length"), "is " + formatNumber(s.length) + " m but the sections add up to " +
                                               formatNumber(L) + " m (give one or make them agree)");
    if (line.has("elements") && n != s.elements)
      throw SceneError(line.key("elements"), "is " + std::to_string(s.elements) + " but the sections have " +
                                                 std::to_string(n) + " (give one or make them agree)");
    if (n > kMaxSceneElements)
      throw SceneError(
          key, "have " + std::to_string(n) + " elements in all, more than " + std::to_string(kMaxSceneElements));
    s.length = L;
    s.elements = int(n);
  }
  if (line.has("bend_stiffener")) {
    if (s.sections.empty()) s.sections.push_back(LineSection{s.length, s.elements, s.line, SectionHydro(), {}});
    s.stiffeners.push_back(parseStiffener(
        line.section("bend_stiffener", {"end", "length", "root_diameter", "tip_diameter", "youngs_modulus", "table"}),
        s));
  }
}

void finishLineSections(Scene& s) {
  for (LineSection& sec : s.sections)
    if (sec.modules.enabled) {  // checked by parseOne
      const HydroSpec& h = s.hydro;
      smearModules(sec, orLine(sec.hydro.drag_normal, h.drag_normal),
                   orLine(sec.hydro.drag_tangential, h.drag_tangential),
                   orLine(sec.hydro.inertia_coefficient, h.inertia_coefficient));
    }
}

}  // namespace scene_detail
}  // namespace riser_sim
