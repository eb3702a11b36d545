// Scene sections: YAML tree -> riser_sim::Scene, one small parse function per section (see
// kSections at the bottom; adding a section = one function + one table row; the sea's sections are in
// scene_sea_sections.cpp). Every error is a
// SceneError naming the full key path. The accepted keys are documented in docs/scene_keys.md.
// Reading files and --set overrides: scene_yaml.cpp.
#include "riser_sim/scene/scene_yaml.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "riser_sim/run/initial_velocity.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/scene/scene_check.h"
#include "riser_sim/spatial/run_builder.h"
#include "scene_section.h"

namespace riser_sim {

using namespace scene_detail;

std::string unknownKeyMessage(const std::string& key, const std::vector<std::string>& accepted) {
  for (const auto& a : accepted)
    if (editDistance(key, a) <= 2 && key.size() > 2) return "unknown key (did you mean '" + a + "'?)";
  return "unknown key (accepted: " + join(accepted) + ")";
}

namespace {

// ---- sections ----

// line.EI: [EI_1, EI_2]: the stiffness about the two material axes (3D, with line.bending_axis and
// line.torsion: checked by parseBendingAxes once those are read); LineProperties::EI gets their mean.
void parseBendingAxesEI(const Section& line, Scene& s) {
  const std::string key = line.key("EI");
  const YAML::Node ei = line.at("EI");
  if (ei.size() != 2)
    throw SceneError(key, "expected a number or [EI_1, EI_2] (about two material axes), got " + describe(ei));
  if (s.space != SpaceKind::kSpatial)
    throw SceneError(key, "[EI_1, EI_2] needs space: spatial (the planar core bends in its plane only)");
  if (!s.options.bending) throw SceneError(key, "[EI_1, EI_2] contradicts line.bending: false");
  BendingAxesSpec& b = s.bending_axes;
  b.enabled = true;
  b.EI1 = toNumber(ei[0], key + "[0]");
  b.EI2 = toNumber(ei[1], key + "[1]");
  requirePositive(key + "[0]", b.EI1);
  requirePositive(key + "[1]", b.EI2);
  s.line.EI = 0.5 * (b.EI1 + b.EI2);
}

// line.bending_axis: axis 1 of line.EI: [EI_1, EI_2] at the hang-off (needs both and line.torsion).
void parseBendingAxes(const Section& line, Scene& s) {
  BendingAxesSpec& b = s.bending_axes;
  if (line.has("bending_axis") && !b.enabled)
    throw SceneError(line.key("bending_axis"), "needs line.EI: [EI_1, EI_2] (the stiffness about the two axes)");
  if (!b.enabled) return;
  if (!s.torsion.enabled)
    throw SceneError(line.key("EI"), "[EI_1, EI_2] needs line.torsion (the material axes turn with the line's spin)");
  // 3D only, so [x, y, z] only (as flex_joint.axis): a 2-vector's planar [x, z] would be a guess here.
  const YAML::Node axis = line.at("bending_axis");
  if (!axis.IsSequence() || axis.size() != 3)
    throw SceneError(line.key("bending_axis"), "expected [x, y, z], got " + describe(axis));
  b.axis = line.vec3("bending_axis", false);
  if (!(b.axis.allFinite() && b.axis.norm() > 0.0))
    throw SceneError(line.key("bending_axis"),
                     "must be a non-zero direction [x, y, z] (material axis 1 at the hang-off)");
}

// line: geometry + material, or EA / EI / mass_per_length directly (never both).
void parseCrossSection(const Section& line, Scene& s) {
  const bool geometry = line.has("youngs_modulus") || line.has("density");
  std::string direct_key;
  for (const char* k : {"EA", "EI", "mass_per_length"})
    if (direct_key.empty() && line.has(k)) direct_key = k;
  if (geometry && !direct_key.empty())
    throw SceneError(line.key(direct_key),
                     "cannot be combined with youngs_modulus/density: give either outer_diameter, inner_diameter, "
                     "youngs_modulus and density, or EA, EI and mass_per_length");
  if (!geometry && direct_key.empty()) {
    if (line.has("outer_diameter")) line.at("youngs_modulus");  // throws "line.youngs_modulus: missing ..."
    throw SceneError("line",
                     "missing cross-section properties: give outer_diameter, youngs_modulus and density, "
                     "or EA, EI and mass_per_length");
  }

  const double outer = line.number("outer_diameter", 0.0);
  const double inner = line.number("inner_diameter", 0.0);
  if (geometry || line.has("outer_diameter"))
    requirePositive(line.key("outer_diameter"), line.number("outer_diameter"));
  requireNonNegative(line.key("inner_diameter"), inner);
  if (line.has("inner_diameter") && !line.has("outer_diameter")) line.at("outer_diameter");
  if (inner > 0.0 && !(inner < outer))
    throw SceneError(line.key("inner_diameter"), "must be smaller than line.outer_diameter (" + formatNumber(outer) +
                                                     " m), got " + formatNumber(inner));

  if (geometry) {
    const double E = line.number("youngs_modulus");
    requirePositive(line.key("youngs_modulus"), E);
    const double rho = line.number("density");
    requirePositive(line.key("density"), rho);
    s.line = LineProperties::fromGeometry(outer, inner, E, rho);
    // Each value > 0 and yet a product may round to 0 (1e-200 m): name the key that does it.
    if (!(s.line.wallArea() > 0.0))
      throw SceneError(line.key(M_PI / 4.0 * outer * outer > 0.0 ? "inner_diameter" : "outer_diameter"),
                       "leaves a wall area of 0 (rounds to 0 in double precision)");
    if (!(s.line.mass_per_length > 0.0))
      throw SceneError(line.key("density"), "is too small: mass per length rounds to 0");
    if (s.options.axial_flexibility && !(s.line.EA > 0.0))
      throw SceneError(line.key("youngs_modulus"), "is too small: EA rounds to 0");
  } else {
    s.line = LineProperties();
    s.line.outer_diameter = outer;
    s.line.inner_diameter = inner;
    s.line.mass_per_length = line.number("mass_per_length");
    requirePositive(line.key("mass_per_length"), s.line.mass_per_length);
    // EA is only needed by an extensible line, EI only with bending springs.
    s.line.EA = s.options.axial_flexibility ? line.number("EA") : line.number("EA", 0.0);
    if (s.options.axial_flexibility) requirePositive(line.key("EA"), s.line.EA);
    requireNonNegative(line.key("EA"), s.line.EA);
    if (line.has("EI") && line.at("EI").IsSequence()) {
      parseBendingAxesEI(line, s);
    } else {
      s.line.EI = s.options.bending ? line.number("EI") : line.number("EI", 0.0);
      requireNonNegative(line.key("EI"), s.line.EI);
    }
  }
}

// line.torsion: GJ, the polar inertia per length (default from the section: m (D² + d²) / 8 of the pipe
// wall, when outer_diameter is given), damping, the end body's polar inertia. 3D only.
void parseTorsion(const Section& line, Scene& s) {
  if (!line.has("torsion")) return;
  if (s.space != SpaceKind::kSpatial)
    throw SceneError(line.key("torsion"), "needs space: spatial (the planar core has no torsion)");
  const Section t = line.section("torsion", {"stiffness", "polar_inertia", "damping", "end_polar_inertia"});
  TorsionSpec& ts = s.torsion;
  ts.enabled = true;
  ts.stiffness = t.number("stiffness");
  requirePositive(t.key("stiffness"), ts.stiffness);
  const double D = s.line.outer_diameter, d = s.line.inner_diameter;
  if (!t.has("polar_inertia") && !(D > 0.0))
    throw SceneError(t.key("polar_inertia"), "missing required key (or give line.outer_diameter to derive it)");
  ts.polar_inertia = t.number("polar_inertia", s.line.mass_per_length * (D * D + d * d) / 8.0);
  requirePositive(t.key("polar_inertia"), ts.polar_inertia);
  ts.damping = t.number("damping", 0.0);
  requireNonNegative(t.key("damping"), ts.damping);
  ts.end_polar_inertia = t.number("end_polar_inertia", 0.0);
  requireNonNegative(t.key("end_polar_inertia"), ts.end_polar_inertia);
}

void parseLine(const Section& root, Scene& s) {
  if (!root.has("line"))
    throw SceneError("line",
                     "missing required section (needs at least length, elements "
                     "and the cross-section properties)");
  const Section line = root.section(
      "line", {"length", "elements", "outer_diameter", "inner_diameter", "youngs_modulus", "density", "EA", "EI",
               "mass_per_length", "end_mass", "bending", "axial_flexibility", "axial_damping", "axial_damping_ratio",
               "bending_damping", "torsion", "bending_axis", "sections", "bend_stiffener"});
  const bool sectioned = line.has("sections");  // then length and elements may come from the sections
  s.length = sectioned && !line.has("length") ? 1.0 : line.number("length");
  requirePositive(line.key("length"), s.length);
  s.elements = sectioned && !line.has("elements") ? 1 : line.integer("elements");
  if (s.elements < 1) throw SceneError(line.key("elements"), "must be >= 1, got " + std::to_string(s.elements));
  if (s.elements > kMaxSceneElements)
    throw SceneError(line.key("elements"), "must be <= " + std::to_string(kMaxSceneElements) + ", got " +
                                               std::to_string(s.elements) +
                                               " (the static initial state is a dense "
                                               "solve: O(n^2) memory, O(n^3) time)");
  s.options.bending = line.boolean("bending", true);
  s.options.axial_flexibility = line.boolean("axial_flexibility", true);

  parseCrossSection(line, s);
  s.line.axial_damping = line.number("axial_damping", 0.0);
  requireNonNegative(line.key("axial_damping"), s.line.axial_damping);
  s.line.axial_damping_ratio = line.number("axial_damping_ratio", 0.0);
  if (!(s.line.axial_damping_ratio >= 0.0 && s.line.axial_damping_ratio <= 1.0))
    throw SceneError(line.key("axial_damping_ratio"), "must be in [0, 1] (a fraction of critical, not percent), got " +
                                                          formatNumber(s.line.axial_damping_ratio));
  if (line.has("axial_damping") && line.has("axial_damping_ratio"))
    throw SceneError(line.key("axial_damping_ratio"),
                     "give the axial damping either as a coefficient (axial_damping) "
                     "or as a ratio, not both");
  s.line.bending_damping = line.number("bending_damping", 0.0);
  requireNonNegative(line.key("bending_damping"), s.line.bending_damping);
  s.end_mass = line.number("end_mass", 0.0);
  requireNonNegative(line.key("end_mass"), s.end_mass);
  parseTorsion(line, s);
  parseBendingAxes(line, s);
  parseLineSections(line, s);
}

void parseInitial(const Section& root, Scene& s) {
  const bool planar = s.space == SpaceKind::kPlanar;
  const Section initial = root.section(
      "initial", {"type", "end_dx", "end_offset", "angle", "heading", "tolerance", "end_force", "velocity"});
  s.initial = InitialSpec();
  s.initial.type = initial.choice("type", InitialKind::kHanging);
  const bool displaced = s.initial.type == InitialKind::kDisplaced;
  if (initial.has("end_offset")) {  // [dx, dy]: horizontal offset of the end from the top
    const std::string key = initial.key("end_offset");
    if (initial.has("end_dx"))
      throw SceneError(key, "give either initial.end_dx (along x) or initial.end_offset ([dx, dy]), not both");
    const YAML::Node off = initial.at("end_offset");
    if (!off.IsSequence() || off.size() != 2)
      throw SceneError(key, "expected [dx, dy] (horizontal: x, y), got " + describe(off));
    s.initial.end_offset = Vec2(toNumber(off[0], key + "[0]"), toNumber(off[1], key + "[1]"));
    if (planar && s.initial.end_offset.y() != 0.0)
      throw SceneError(key + "[1]", "dy = " + formatNumber(s.initial.end_offset.y()) +
                                        " points out of the vertical "
                                        "x-z plane of a planar scene (space: planar, the default); set space: spatial "
                                        "for a 3D scene");
    s.initial.end_dx = s.initial.end_offset.x();
  } else {
    s.initial.end_dx = displaced ? initial.number("end_dx") : initial.number("end_dx", 0.0);
    s.initial.end_offset = Vec2(s.initial.end_dx, 0.0);
  }
  s.initial.angle = initial.number("angle", -90.0) * kDegToRad;
  s.initial.heading = initial.number("heading", 0.0) * kDegToRad;
  if (planar && s.initial.heading != 0.0)
    throw SceneError(initial.key("heading"),
                     "turns the straight line out of the vertical x-z plane of a planar scene "
                     "(space: planar, the default); set space: spatial for a 3D scene");
  s.initial.tolerance = initial.number("tolerance", 1e-9);
  requirePositive(initial.key("tolerance"), s.initial.tolerance);
  s.initial.end_force = initial.choice("end_force", EndForceKind::kRelease);
  if (initial.has("velocity")) {  // initial_velocity.h; checked against the holders in checkCombination
    const Section velocity = initial.section("velocity", {"rotation", "translation"});
    s.initial.has_velocity = true;
    s.initial.rotation = velocity.number("rotation", 0.0);
    s.initial.translation = velocity.vec3("translation", planar, Eigen::Vector3d::Zero());
  }
}

void parseSolver(const Section& root, Scene& s) {
  const Section solver =
      root.section("solver", {"dt", "integrator", "formulation", "stabilization", "max_constraint_error", "tolerance",
                              "jacobian_interval", "jacobian", "rho_inf", "newton_tolerance"});
  const SolverSettings defaults;
  s.solver = defaults;
  s.solver.dt = solver.number("dt", defaults.dt);
  requirePositive(solver.key("dt"), s.solver.dt);
  s.solver.integrator = solver.choice("integrator", defaults.integrator);
  s.solver.formulation = solver.choice("formulation", defaults.formulation);
  s.solver.stabilization = solver.number("stabilization", defaults.stabilization);
  requireNonNegative(solver.key("stabilization"), s.solver.stabilization);
  s.solver.max_constraint_error = solver.number("max_constraint_error", defaults.max_constraint_error);
  requirePositive(solver.key("max_constraint_error"), s.solver.max_constraint_error);
  s.solver.tolerance = solver.number("tolerance", defaults.tolerance);
  requirePositive(solver.key("tolerance"), s.solver.tolerance);
  s.solver.jacobian_interval = solver.number("jacobian_interval", defaults.jacobian_interval);
  requireNonNegative(solver.key("jacobian_interval"), s.solver.jacobian_interval);
  s.solver.jacobian = solver.choice("jacobian", defaults.jacobian);
  s.solver.rho_inf = solver.number("rho_inf", defaults.rho_inf);
  s.solver.newton_tolerance = solver.number("newton_tolerance", defaults.newton_tolerance);
  // The values, the combination and the size limits: checkScene, once every section is read (checkCombination).
}

void parseRun(const Section& root, Scene& s) {
  const Section run = root.section("run", {"duration"});
  s.duration = run.number("duration", 20.0);
  requirePositive(run.key("duration"), s.duration);
  if (!(s.duration / s.solver.dt <= kMaxSceneSteps))
    throw SceneError(run.key("duration"), "is " + formatNumber(s.duration / s.solver.dt) + " steps of solver.dt (" +
                                              formatNumber(s.solver.dt) + " s), more than " +
                                              formatNumber(kMaxSceneSteps));
}

// Checks that need more than one section.
void checkCombination(const Scene& s) {
  const bool pinned = s.bottom == BottomBoundary::kPinned;
  if (s.hydro.enabled && !s.water.enabled)
    throw SceneError("hydrodynamics", "needs environment.water (the line must be in water)");
  if ((s.water.enabled || s.hydro.enabled) && !(s.line.outer_diameter > 0.0))
    throw SceneError("line.outer_diameter", "is needed (> 0) for buoyancy and hydrodynamic forces");
  if (s.internal_fluid.density > 0.0 && !(s.line.inner_diameter > 0.0))
    throw SceneError("line.inner_diameter", "is needed (> 0) for internal_fluid");
  if (s.initial.type == InitialKind::kBetweenPoints && !pinned)
    throw SceneError("initial.type", "'between_points' needs bottom.type: pinned (bottom.position is the end point)");
  // 3D: a straight start may be pinned where it ends (a taut line; checked against bottom.position at t = 0).
  const bool straight3 = s.space == SpaceKind::kSpatial && s.initial.type == InitialKind::kStraight;
  if (pinned && s.initial.type != InitialKind::kBetweenPoints && !straight3)
    throw SceneError("bottom.type",
                     "'pinned' needs initial.type: between_points (the initial state must end at "
                     "bottom.position), got initial.type '" +
                         std::string(name(s.initial.type)) + "'");
  if (pinned && straight3) {
    const double c = std::cos(s.initial.angle), h = s.initial.heading;
    const Eigen::Vector3d end = spatial::buildTopMotion3(s.top)->at(0.0).p +
                                s.length * Eigen::Vector3d(c * std::cos(h), c * std::sin(h), std::sin(s.initial.angle));
    const double gap = (end - spatial::buildTopMotion3(s.bottom_motion)->at(0.0).p).norm();
    if (!(gap <= 1e-9 * s.length))
      throw SceneError("bottom.position",
                       "is " + formatNumber(gap) +
                           " m from the end of the straight initial line "
                           "(initial.type straight with a pinned bottom: the line must end there at t = 0)");
  }
  if (s.initial.type == InitialKind::kDisplaced && s.initial.end_offset.y() != 0.0 &&
      !(s.initial.end_offset.norm() < s.length))
    throw SceneError("initial.end_offset", "must be shorter than line.length (" + formatNumber(s.length) + " m), got " +
                                               formatNumber(s.initial.end_offset.norm()) + " m");
  if (s.initial.type == InitialKind::kDisplaced && !(std::abs(s.initial.end_dx) < s.length))
    throw SceneError("initial.end_dx", "must be smaller than line.length (" + formatNumber(s.length) +
                                           " m) in magnitude, got " + formatNumber(s.initial.end_dx));
  checkInitialVelocity(s);
  // The solver values and what the scene's engine supports: the core's one check (the node calls it too).
  if (const auto error = checkScene(s)) throw SceneError(error->key, error->message);
  if (pinned && !s.options.axial_flexibility) {
    const double span =
        s.space == SpaceKind::kSpatial
            ? (spatial::buildTopMotion3(s.bottom_motion)->at(0.0).p - spatial::buildTopMotion3(s.top)->at(0.0).p).norm()
            : (inPlane(s.bottom_point) - buildTopMotion(s.top)->at(0.0).p).norm();
    if (span > s.length)
      throw SceneError("bottom.position", "is " + formatNumber(span) + " m from the top at t = 0 but the line is " +
                                              formatNumber(s.length) + " m long and inextensible");
  }
}

using SectionParser = void (*)(const Section&, Scene&);
struct SectionEntry {
  const char* name;
  SectionParser parse;
};
// Top-level sections, parsed in this order.
const SectionEntry kSections[] = {
    {"line", parseLine},
    {"top", parseTop},
    {"bottom", parseBottom},
    {"initial", parseInitial},
    {"environment", parseEnvironment},
    {"solver", parseSolver},
    {"run", parseRun},
    {"hydrodynamics", parseHydrodynamics},
    {"seabed", parseSeabed},
    {"internal_fluid", parseInternalFluid},
    {"attachments", parseAttachments},
};

}  // namespace

Scene parseScene(const YAML::Node& node) {
  std::vector<std::string> accepted = {"name"};
  for (const auto& entry : kSections) accepted.push_back(entry.name);
  accepted.push_back("space");
  const Section root(node, "", accepted);
  Scene s;
  s.name = root.text("name", "");
  s.space = root.choice("space", SpaceKind::kPlanar);  // first: it decides what a vector may be
  for (const auto& entry : kSections) entry.parse(root, s);
  finishLineSections(s);
  checkAttachmentsFloat(s);  // with the buoyancy modules smeared
  checkCombination(s);
  return s;
}

}  // namespace riser_sim
