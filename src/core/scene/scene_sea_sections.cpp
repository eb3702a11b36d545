// Scene sections of the sea and the contents: environment (gravity, water, current, waves),
// hydrodynamics, seabed, internal_fluid. Every error is a SceneError naming the full key path
// (docs/scene_keys.md). A 2-vector [a, b] (planar [x, z_up]) is (a, 0, b); a 3-vector is [x, y, z].
#include <cmath>
#include <string>
#include <vector>

#include "scene_section.h"

namespace riser_sim {
namespace scene_detail {

namespace {

void parseProfile(const Section& cur, bool planar, CurrentSpec& c) {
  const std::string key = cur.key("profile");
  const YAML::Node prof = cur.at("profile");
  const std::string form = planar ? "[depth, vx]" : "[depth, vx] or [depth, vx, vy]";
  if (!prof.IsSequence() || prof.size() == 0)
    throw SceneError(key, "expected a non-empty list of " + form + ", got " + describe(prof));
  for (size_t i = 0; i < prof.size(); ++i) {
    const std::string k = key + "[" + std::to_string(i) + "]";
    const YAML::Node p = prof[i];
    if (!p.IsSequence() || (p.size() != 2 && p.size() != 3))
      throw SceneError(k, "expected " + form + ", got " + describe(p));
    const double d = toNumber(p[0], k + "[0]");
    requireNonNegative(k + "[0]", d);
    if (i > 0 && !(d > c.profile.back().depth)) throw SceneError(k, "depths must increase");
    const double vy = p.size() == 3 ? toNumber(p[2], k + "[2]") : 0.0;
    if (planar && vy != 0.0)
      throw SceneError(k + "[2]", "vy = " + formatNumber(vy) +
                                      " points out of the vertical x-z plane of a planar "
                                      "scene (space: planar, the default); set space: spatial for a 3D scene");
    c.profile.push_back({d, toNumber(p[1], k + "[1]"), vy});
  }
}

void parseCurrent(const Section& env, Scene& s) {
  const bool planar = s.space == SpaceKind::kPlanar;
  const Section cur = env.section("current", {"velocity", "acceleration", "profile"});
  CurrentSpec& c = s.water.current;
  c = CurrentSpec();
  c.velocity = cur.vec3("velocity", planar, Eigen::Vector3d::Zero());
  c.acceleration = cur.vec3("acceleration", planar, Eigen::Vector3d::Zero());
  if (cur.has("profile")) parseProfile(cur, planar, c);
}

// Airy waves past breaking are refused: a height above 1/7 of the deep-water wavelength g T²/(2π) (Michell's
// limit; the wavelength at finite depth is shorter, so this refuses only waves that break at any depth) or
// above 0.78 of the depth (the shallow-water limit).
void checkBreaking(const std::string& key, double H, double T, double depth, double g) {
  const double L0 = g * T * T / (2.0 * M_PI);
  if (L0 > 0.0 && H > L0 / 7.0)
    throw SceneError(key, formatNumber(H) + " m is " + formatNumber(H / L0) + " of the deep-water wavelength " +
                              formatNumber(L0) + " m at the period " + formatNumber(T) +
                              " s: past breaking (H/L <= 1/7); lower the height or raise the period");
  if (H > 0.78 * depth)
    throw SceneError(key, formatNumber(H) + " m is " + formatNumber(H / depth) + " of the water depth " +
                              formatNumber(depth) + " m (environment.waves.depth): past breaking (H/h <= 0.78)");
}

void parseWaves(const Section& env, Scene& s) {
  const Section w = env.section("waves", {"type", "height", "period", "phase", "direction", "heading", "depth", "ramp",
                                          "significant_height", "peak_period", "gamma", "components", "seed"});
  WaveSpec& wave = s.water.waves;
  wave = WaveSpec();
  wave.type = w.choice("type", WaveKind::kRegular);
  const bool regular = wave.type == WaveKind::kRegular;
  // The other type's keys are refused, not ignored.
  for (const char* k :
       regular ? std::vector<const char*>{"significant_height", "peak_period", "gamma", "components", "seed"}
               : std::vector<const char*>{"height", "period", "phase"})
    if (w.has(k))
      throw SceneError(w.key(k), std::string("belongs to waves of type ") + (regular ? "jonswap" : "regular") +
                                     ", not '" + name(wave.type) + "'");
  wave.height = w.number("height", 0.0);
  requireNonNegative(w.key("height"), wave.height);
  wave.period = w.has("height") ? w.number("period") : w.number("period", 10.0);
  requirePositive(w.key("period"), wave.period);
  wave.phase = w.number("phase", 0.0);
  wave.significant_height = w.number("significant_height", 0.0);
  requireNonNegative(w.key("significant_height"), wave.significant_height);
  wave.peak_period = w.has("significant_height") ? w.number("peak_period") : w.number("peak_period", 10.0);
  requirePositive(w.key("peak_period"), wave.peak_period);
  wave.gamma = w.number("gamma", 3.3);
  if (!(wave.gamma >= 1.0 && wave.gamma <= 20.0))
    throw SceneError(w.key("gamma"), "must be in [1, 20], got " + formatNumber(wave.gamma));
  wave.components = w.has("components") ? w.integer("components") : 100;
  if (wave.components < 1 || wave.components > 2000)
    throw SceneError(w.key("components"), "must be in [1, 2000], got " + std::to_string(wave.components));
  const long long seed = w.has("seed") ? toInteger64(w.at("seed"), w.key("seed")) : 1;
  if (seed < 0 || seed > 4294967295LL)
    throw SceneError(w.key("seed"), "must be in [0, 4294967295] (32 bits), got " + std::to_string(seed));
  wave.seed = static_cast<unsigned>(seed);
  wave.direction = w.number("direction", 1.0);
  if (wave.direction != 1.0 && wave.direction != -1.0) throw SceneError(w.key("direction"), "must be 1 or -1");
  wave.heading = w.number("heading", 0.0) * kDegToRad;
  if (s.space == SpaceKind::kPlanar && wave.heading != 0.0)
    throw SceneError(w.key("heading"),
                     "turns the waves out of the vertical x-z plane of a planar scene (space: "
                     "planar, the default; use direction: -1 for waves towards -x); set space: "
                     "spatial for a 3D scene");
  wave.depth = w.number("depth", 1000.0);
  requirePositive(w.key("depth"), wave.depth);
  wave.ramp = w.number("ramp", 0.0);
  requireNonNegative(w.key("ramp"), wave.ramp);
  if (regular)
    checkBreaking(w.key("height"), wave.height, wave.period, wave.depth, s.gravity);
  else
    checkBreaking(w.key("significant_height"), wave.significant_height, wave.peak_period, wave.depth, s.gravity);
}

}  // namespace

void parseEnvironment(const Section& root, Scene& s) {
  const Section env = root.section("environment", {"gravity", "water", "current", "waves"});
  s.gravity = env.number("gravity", 9.81);
  requireNonNegative(env.key("gravity"), s.gravity);
  s.water = WaterSpec();
  s.water.enabled = env.has("water");
  const Section water = env.section("water", {"density", "surface"});
  s.water.density = water.number("density", 1025.0);
  requirePositive(water.key("density"), s.water.density);
  s.water.surface = water.number("surface", 0.0);
  parseCurrent(env, s);
  parseWaves(env, s);
  if (!s.water.enabled && (env.has("current") || env.has("waves")))
    throw SceneError(env.key("water"), "current and waves need a water section");
}

void parseHydrodynamics(const Section& root, Scene& s) {
  const Section h =
      root.section("hydrodynamics", {"drag_tangential", "drag_normal", "inertia_coefficient", "axial_added_mass"});
  s.hydro = HydroSpec();
  s.hydro.enabled = root.has("hydrodynamics");
  s.hydro.drag_tangential = h.number("drag_tangential", 0.0);
  s.hydro.drag_normal = h.number("drag_normal", 0.0);
  s.hydro.inertia_coefficient = h.number("inertia_coefficient", 1.0);
  requireNonNegative(h.key("drag_tangential"), s.hydro.drag_tangential);
  requireNonNegative(h.key("drag_normal"), s.hydro.drag_normal);
  if (!(s.hydro.inertia_coefficient >= 1.0))
    throw SceneError(h.key("inertia_coefficient"), "C_M must be >= 1 (added mass C_M - 1 >= 0)");
  s.hydro.axial_added_mass = h.number("axial_added_mass", 0.0);
  requireNonNegative(h.key("axial_added_mass"), s.hydro.axial_added_mass);
}

void parseSeabed(const Section& root, Scene& s) {
  const Section b = root.section(
      "seabed", {"level", "stiffness_normal", "stiffness_tangential", "damping_normal", "damping_tangential",
                 "friction_axial", "friction_lateral", "friction_velocity", "slope", "slope_heading"});
  s.seabed = SeabedSpec();
  s.seabed.enabled = root.has("seabed");
  if (!s.seabed.enabled) return;
  s.seabed.level = b.number("level");
  s.seabed.stiffness_normal = b.number("stiffness_normal");
  s.seabed.stiffness_tangential = b.number("stiffness_tangential", 0.0);
  s.seabed.damping_normal = b.number("damping_normal", 0.0);
  s.seabed.damping_tangential = b.number("damping_tangential", 0.0);
  requirePositive(b.key("stiffness_normal"), s.seabed.stiffness_normal);
  for (const char* k :
       {"stiffness_tangential", "damping_normal", "damping_tangential", "friction_axial", "friction_lateral"})
    requireNonNegative(b.key(k), b.number(k, 0.0));
  s.seabed.friction_axial = b.number("friction_axial", 0.0);
  s.seabed.friction_lateral = b.number("friction_lateral", 0.0);
  s.seabed.friction_velocity = b.number("friction_velocity", 0.01);
  requirePositive(b.key("friction_velocity"), s.seabed.friction_velocity);
  const bool planar = s.space == SpaceKind::kPlanar;
  for (const char* k : {"friction_axial", "friction_lateral", "friction_velocity"})
    if (planar && b.has(k) && (b.number(k) > 0.0 || std::string(k) == "friction_velocity"))
      throw SceneError(b.key(k),
                       "Coulomb friction is in the 3D core (set space: spatial); the planar seabed holds "
                       "the line with tangential springs anchored at touchdown (stiffness_tangential)");
  // A sloped plane [deg in the file]: slope in [0, 45), heading any.
  const double slope = b.number("slope", 0.0);
  if (!(slope >= 0.0 && slope < 45.0))
    throw SceneError(b.key("slope"), "must be in [0, 45) deg, got " + formatNumber(slope));
  s.seabed.slope = slope * kDegToRad;
  s.seabed.slope_heading = b.number("slope_heading", 0.0) * kDegToRad;
  if (planar && slope != 0.0)
    throw SceneError(b.key("slope"),
                     "a sloped seabed is in the 3D core (set space: spatial); the planar seabed is "
                     "level at seabed.level");
}

void parseInternalFluid(const Section& root, Scene& s) {
  const Section f = root.section("internal_fluid", {"density", "velocity", "acceleration", "model"});
  s.internal_fluid = InternalFlowSpec();
  s.internal_fluid.density = f.number("density", 0.0);
  requireNonNegative(f.key("density"), s.internal_fluid.density);
  s.internal_fluid.velocity = f.number("velocity", 0.0);
  s.internal_fluid.acceleration = f.number("acceleration", 0.0);
  s.internal_fluid.model = f.choice("model", FlowModelKind::kPipeFlow);
}

}  // namespace scene_detail
}  // namespace riser_sim
