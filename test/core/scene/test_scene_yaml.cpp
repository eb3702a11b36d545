// Scene files: bad input is rejected with the offending key path, good input parses to the right
// values, overrides edit the tree (every shipped scene parsing and building: test_cli_shipped_scenes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

using namespace riser_sim;

namespace {

// Exact arithmetic on the same double inputs: only the last bits of pow/pi may differ.
constexpr double kRelTol = 1e-12;

Scene parse(const std::string& yaml) { return parseScene(YAML::Load(yaml)); }

// Smallest complete scene: geometry + material.
const char* kMinimal = "{line: {length: 100, elements: 10, outer_diameter: 0.05, youngs_modulus: 1e11, density: 2000}}";

std::string tempPath(const std::string& name) {
  return testing::TempDir() + "/riser_sim_test_scene_yaml_" + std::to_string(getpid()) + "_" + name;
}

struct BadScene {
  const char* yaml;
  const char* key;      // expected SceneError::key()
  const char* message;  // expected part of what()
};

const BadScene kBadScenes[] = {
    // unknown keys, anywhere, with the full path
    {"{line: {lenght: 100, elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.lenght", "did you mean 'length'"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {dtt: 1}}", "solver.dtt",
     "unknown key"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {motion: {kind: fixed}}}",
     "top.motion.kind", "unknown key (accepted: type, amplitude, period, phase, knots, attitude, attitude_phase)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, wind: {speed: 3}}", "wind", "unknown key"},
    // wrong types
    {"{line: {length: 100, elements: ten, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.elements",
     "expected an integer, got 'ten'"},
    {"{line: {length: 100, elements: 2.5, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.elements",
     "expected an integer"},
    {"{line: {length: abc, elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length",
     "expected a number, got 'abc'"},
    {"{line: {length: [1, 2], elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length", "got a list"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, bending: maybe}}", "line.bending",
     "expected true or false"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {position: [1, 2, 3, 4]}}",
     "top.position", "expected [x, z] (planar: x horizontal, z up) or [x, y, z] (z up), got a list of 4 items"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {position: [1, 2, 3]}}",
     "top.position[1]", "y = 2 points out of the vertical x-z plane of a planar scene"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {position: [1, x]}}", "top.position[1]",
     "expected a number"},
    {"{line: 5}", "line", "expected a map of keys"},
    {"[1, 2]", "", "a scene must be a map of sections"},
    // out of range
    {"{line: {length: 0, elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length", "must be > 0, got 0"},
    {"{line: {length: -5, elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length", "must be > 0"},
    {"{line: {length: 100, elements: 0, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.elements", "must be >= 1, got 0"},
    {"{line: {length: 1, elements: 1, outer_diameter: 0.05, inner_diameter: 0.05, youngs_modulus: 1e11, density: 1}}",
     "line.inner_diameter", "must be smaller than line.outer_diameter"},
    {"{line: {length: 1, elements: 1, outer_diameter: 0.05, inner_diameter: -0.01, youngs_modulus: 1e11, density: 1}}",
     "line.inner_diameter", "must be >= 0"},
    {"{line: {length: 1, elements: 1, outer_diameter: 0, youngs_modulus: 1e11, density: 1}}", "line.outer_diameter",
     "must be > 0"},
    {"{line: {length: 1, elements: 1, outer_diameter: 0.05, youngs_modulus: -1, density: 1}}", "line.youngs_modulus",
     "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: -1, EI: 0, mass_per_length: 1}}", "line.EA", "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: -1, mass_per_length: 1}}", "line.EI", "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: -2}}", "line.mass_per_length", "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, end_mass: -1}}", "line.end_mass",
     "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, axial_damping: -1}}", "line.axial_damping",
     "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {dt: 0}}", "solver.dt", "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {dt: -1e-3}}", "solver.dt",
     "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {stabilization: -1}}",
     "solver.stabilization", "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, run: {duration: 0}}", "run.duration",
     "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, environment: {gravity: -9.81}}",
     "environment.gravity", "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {tolerance: 0}}", "initial.tolerance",
     "must be > 0"},
    // NaN / Inf
    {"{line: {length: .nan, elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length",
     "must be a finite number"},
    {"{line: {length: 10, elements: 10, EA: .inf, EI: 0, mass_per_length: 1}}", "line.EA", "must be a finite number"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {dt: -.inf}}", "solver.dt",
     "must be a finite number"},
    // missing required keys / incomplete or mixed property sets
    {"{}", "line", "missing required section"},
    {"{line: {elements: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.length", "missing required key"},
    {"{line: {length: 10, EA: 1e6, EI: 0, mass_per_length: 1}}", "line.elements", "missing required key"},
    {"{line: {length: 10, elements: 10}}", "line", "missing cross-section properties"},
    {"{line: {length: 10, elements: 10, outer_diameter: 0.05}}", "line.youngs_modulus", "missing required key"},
    {"{line: {length: 10, elements: 10, outer_diameter: 0.05, youngs_modulus: 1e11}}", "line.density",
     "missing required key"},
    {"{line: {length: 10, elements: 10, youngs_modulus: 1e11, density: 1}}", "line.outer_diameter",
     "missing required key"},
    {"{line: {length: 10, elements: 10, EA: 1e6, EI: 0}}", "line.mass_per_length", "missing required key"},
    {"{line: {length: 10, elements: 10, EI: 0, mass_per_length: 1}}", "line.EA", "missing required key"},
    {"{line: {length: 10, elements: 10, EA: 1e6, mass_per_length: 1}}", "line.EI", "missing required key"},
    {"{line: {length: 10, elements: 10, outer_diameter: 0.05, youngs_modulus: 1e11, density: 1, EA: 1e6}}", "line.EA",
     "cannot be combined with youngs_modulus"},
    {"{line: {length: 10, elements: 10, EA: 1, EI: 0, mass_per_length: 1, inner_diameter: 0.1}}", "line.outer_diameter",
     "missing required key"},
    // enums
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {motion: {type: wobble}}}",
     "top.motion.type", "unknown value 'wobble' (accepted: fixed, sinusoid, velocity_profile, external)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, bottom: {type: glued}}", "bottom.type",
     "(accepted: free, pinned)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {type: random}}", "initial.type",
     "(accepted: hanging, displaced, between_points, straight)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {end_force: keep}}",
     "initial.end_force", "(accepted: release, hold)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.3, inner_diameter: 0.2}, "
     "internal_fluid: {density: 840, model: closed}}",
     "internal_fluid.model", "(accepted: pipe_flow, paper)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {integrator: euler}}",
     "solver.integrator", "unknown value 'euler' (accepted: rk4, dopri5, rosenbrock2, midpoint, generalized_alpha)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {formulation: relative}}",
     "solver.formulation", "(accepted: absolute, independent, recursive)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {tolerance: 0}}", "solver.tolerance",
     "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {jacobian_interval: -1}}",
     "solver.jacobian_interval", "must be >= 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {rho_inf: 1.5}}", "solver.rho_inf",
     "must be in [0, 1]"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {rho_inf: -0.1}}", "solver.rho_inf",
     "must be in [0, 1]"},
    // per-type requirements
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {motion: {type: sinusoid, period: 27}}}",
     "top.motion.amplitude", "missing required key"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, "
     "top: {motion: {type: sinusoid, amplitude: [1, 0], period: 0}}}",
     "top.motion.period", "must be > 0"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {motion: {type: velocity_profile}}}",
     "top.motion.knots", "missing required key"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, "
     "top: {motion: {type: velocity_profile, knots: [[0, [0, 0]], [0, [1, 0]]]}}}",
     "top.motion.knots[1]", "knot times must increase"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, "
     "top: {motion: {type: velocity_profile, knots: [[0, 1]]}}}",
     "top.motion.knots[0][1]", "expected [x, z]"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, bottom: {type: pinned}}", "bottom.position",
     "missing required key"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {type: between_points}}",
     "initial.type", "needs bottom.type: pinned"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, bottom: {type: pinned, position: [0, -1]}}",
     "bottom.type", "needs initial.type: between_points"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {type: displaced}}", "initial.end_dx",
     "missing required key"},
    {"{line: {length: 10, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, initial: {type: displaced, end_dx: -10}}",
     "initial.end_dx", "must be smaller than line.length"},
    {"{line: {length: 10, elements: 2, EA: 1, EI: 0, mass_per_length: 1, axial_flexibility: false}, "
     "bottom: {type: pinned, position: [8, -8]}, initial: {type: between_points}}",
     "bottom.position", "inextensible"},
    // size limits (docs/scene_keys.md, "Limits"): an error, not an out-of-memory or an endless run
    {"{line: {length: 1, elements: 2001, EA: 1, EI: 0, mass_per_length: 1}}", "line.elements",
     "must be <= 2000, got 2001"},
    {"{line: {length: 1, elements: 1000000000, EA: 1, EI: 0, mass_per_length: 1}}", "line.elements",
     "must be <= 2000, got 1000000000"},
    {"{line: {length: 1, elements: 1001, EA: 1, EI: 0, mass_per_length: 1}, solver: {integrator: rosenbrock2}}",
     "line.elements", "must be <= 499 with a dense rosenbrock2 Jacobian on the absolute formulation"},
    {"{line: {length: 1, elements: 1001, EA: 1, EI: 0, mass_per_length: 1}, "
     "solver: {integrator: midpoint, formulation: recursive, jacobian: dense}}",
     "line.elements", "must be <= 999 with a dense midpoint Jacobian on the recursive formulation"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, solver: {dt: 1e-6}, run: {duration: 1e4}}",
     "run.duration", "is 1e+10 steps of solver.dt (1e-06 s), more than 1e+09"},
    {"{line: {length: 1e300, elements: 1, EA: 1, EI: 0, mass_per_length: 1}}", "line.length",
     "must be within +-1e+15, got 1e+300"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, "
     "top: {motion: {type: sinusoid, amplitude: [-2e15, 0], period: 1}}}",
     "top.motion.amplitude[0]", "must be within +-1e+15, got -2e+15"},
    // positive values whose products round to 0
    {"{line: {length: 1, elements: 1, outer_diameter: 1e-200, youngs_modulus: 1e11, density: 1}}",
     "line.outer_diameter", "leaves a wall area of 0"},
    {"{line: {length: 1, elements: 1, outer_diameter: 1e-155, inner_diameter: 9.999999999999999e-156, "
     "youngs_modulus: 1e11, density: 1}}",
     "line.inner_diameter", "leaves a wall area of 0"},  // same square
    {"{line: {length: 1, elements: 1, outer_diameter: 1e-100, youngs_modulus: 1e11, density: 1e-300}}", "line.density",
     "mass per length rounds to 0"},
    {"{line: {length: 1, elements: 1, outer_diameter: 1e-100, youngs_modulus: 1e-300, density: 1}}",
     "line.youngs_modulus", "EA rounds to 0"},
    // a key that is not a name
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, [a]: 1}}", "line",
     "keys must be plain names, got a list of 1 item"},
    // ignored keys of other variants are still type-checked
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, top: {motion: {type: fixed, period: x}}}",
     "top.motion.period", "expected a number"},
    // an integer beyond int says so, not "expected an integer"
    {"{line: {length: 1, elements: 3000000000, EA: 1, EI: 0, mass_per_length: 1}}", "line.elements",
     "must be an integer within +-2147483647"},
    // JONSWAP seeds are 32-bit unsigned: 2^31 is one, 2^32 is not
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.1}, environment: {water: "
     "{density: 1025}, waves: {type: jonswap, significant_height: 2, peak_period: 9, seed: 4294967296}}}",
     "environment.waves.seed", "must be in [0, 4294967295]"},
    // waves past breaking: H/L = 1.4 in deep water (L0 = g T^2 / 2 pi = 1.56 m at T = 1 s), H/h > 0.78 in shallow
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.1}, environment: {water: "
     "{density: 1025}, waves: {height: 2.2, period: 1}}}",
     "environment.waves.height", "past breaking (H/L <= 1/7)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.1}, environment: {water: "
     "{density: 1025}, waves: {type: jonswap, significant_height: 30, peak_period: 8}}}",
     "environment.waves.significant_height", "past breaking (H/L <= 1/7)"},
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.1}, environment: {water: "
     "{density: 1025}, waves: {height: 4, period: 12, depth: 5}}}",
     "environment.waves.height", "past breaking (H/h <= 0.78)"},
    // Coulomb friction keys, friction_velocity included, belong to the 3D seabed
    {"{line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1}, seabed: {level: -10, stiffness_normal: 1e5, "
     "friction_velocity: 0.05}}",
     "seabed.friction_velocity", "Coulomb friction is in the 3D core"},
};

}  // namespace

TEST(SceneYaml, BadScenesNameTheKey) {
  for (const BadScene& bad : kBadScenes) {
    SCOPED_TRACE(bad.yaml);
    try {
      parse(bad.yaml);
      ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key(), bad.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
      // The message starts with the key path so that a user can find it in the file.
      if (!e.key().empty()) {
        EXPECT_EQ(std::string(e.what()).rfind(e.key() + ": ", 0), 0u) << e.what();
      }
    }
  }
}

// The largest seed, and waves just below breaking (H/L0 = 0.14 < 1/7), load.
TEST(SceneYaml, EdgeOfTheSeaLoads) {
  const std::string line = "line: {length: 1, elements: 1, EA: 1, EI: 0, mass_per_length: 1, outer_diameter: 0.1}\n";
  const Scene a = parse(line +
                        "environment: {water: {density: 1025}, waves: {type: jonswap, significant_height: 2, "
                        "peak_period: 9, seed: 4294967295}}\n");
  EXPECT_EQ(a.water.waves.seed, 4294967295u);
  const double L0 = 9.81 * 100.0 / (2.0 * M_PI);  // T = 10 s
  const Scene b = parse(line + "environment: {water: {density: 1025}, waves: {height: " + std::to_string(0.14 * L0) +
                        ", period: 10}}\n");
  EXPECT_NEAR(b.water.waves.height, 0.14 * L0, 1e-6);
}

TEST(SceneYaml, DuplicateKeyIsAnError) {
  try {
    parse("line:\n  length: 1\n  length: 2\n  elements: 1\n  EA: 1\n  EI: 0\n  mass_per_length: 1\n");
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "line.length");
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos) << e.what();
  }
}

TEST(SceneYaml, MinimalSceneTakesDefaults) {
  const Scene s = parse(kMinimal);
  const SolverSettings solver_defaults;
  EXPECT_EQ(s.name, "");
  EXPECT_EQ(s.length, 100.0);
  EXPECT_EQ(s.elements, 10);
  EXPECT_TRUE(s.options.bending);
  EXPECT_TRUE(s.options.axial_flexibility);
  EXPECT_EQ(s.end_mass, 0.0);
  EXPECT_EQ(s.gravity, 9.81);
  EXPECT_STREQ(name(s.top.type), "fixed");
  EXPECT_EQ(s.top.position, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.bottom, BottomBoundary::kFree);
  EXPECT_STREQ(name(s.initial.type), "hanging");
  EXPECT_EQ(s.initial.tolerance, 1e-9);
  EXPECT_STREQ(name(s.initial.end_force), "release");
  EXPECT_STREQ(name(s.internal_fluid.model), "pipe_flow");  // the classical limit (docs/limitations.md)
  EXPECT_EQ(s.solver.dt, solver_defaults.dt);
  EXPECT_STREQ(name(s.solver.integrator), "rk4");
  EXPECT_STREQ(name(s.solver.formulation), "absolute");
  EXPECT_EQ(s.solver.stabilization, solver_defaults.stabilization);
  EXPECT_EQ(s.solver.max_constraint_error, solver_defaults.max_constraint_error);
  EXPECT_EQ(s.duration, 20.0);
  EXPECT_EQ(s.line.axial_damping, 0.0);
  EXPECT_EQ(s.line.bending_damping, 0.0);
}

TEST(SceneYaml, GeometryGivesPipeProperties) {
  const Scene s = parse(
      "{line: {length: 50, elements: 5, outer_diameter: 0.3, inner_diameter: 0.2, youngs_modulus: 2.1e11,"
      " density: 7850, axial_damping: 3, bending_damping: 4}}");
  const double area = M_PI / 4 * (0.3 * 0.3 - 0.2 * 0.2);
  const double second_moment = M_PI / 64 * (std::pow(0.3, 4) - std::pow(0.2, 4));
  EXPECT_NEAR(s.line.EA, 2.1e11 * area, kRelTol * 2.1e11 * area);
  EXPECT_NEAR(s.line.EI, 2.1e11 * second_moment, kRelTol * 2.1e11 * second_moment);
  EXPECT_NEAR(s.line.mass_per_length, 7850 * area, kRelTol * 7850 * area);
  EXPECT_EQ(s.line.outer_diameter, 0.3);
  EXPECT_EQ(s.line.inner_diameter, 0.2);
  EXPECT_EQ(s.line.axial_damping, 3.0);
  EXPECT_EQ(s.line.bending_damping, 4.0);
}

TEST(SceneYaml, DirectPropertiesKeepTheDiameterForHydrodynamics) {
  const Scene s =
      parse("{line: {length: 10, elements: 4, EA: 5e8, EI: 2e4, mass_per_length: 30, outer_diameter: 0.2}}");
  EXPECT_EQ(s.line.EA, 5e8);
  EXPECT_EQ(s.line.EI, 2e4);
  EXPECT_EQ(s.line.mass_per_length, 30.0);
  EXPECT_EQ(s.line.outer_diameter, 0.2);
  EXPECT_EQ(s.line.inner_diameter, 0.0);
}

TEST(SceneYaml, DirectPropertiesNeedOnlyWhatTheModelUses) {
  // Inextensible chain without bending springs: EA and EI are not needed.
  const Scene s =
      parse("{line: {length: 10, elements: 4, mass_per_length: 3, bending: false, axial_flexibility: false}}");
  EXPECT_FALSE(s.options.bending);
  EXPECT_FALSE(s.options.axial_flexibility);
  EXPECT_EQ(s.line.EA, 0.0);
  EXPECT_EQ(s.line.EI, 0.0);
}

TEST(SceneYaml, MotionsBoundariesAndInitialStates) {
  const std::string line = "line: {length: 10, elements: 4, EA: 1e6, EI: 0, mass_per_length: 1}\n";
  {
    const Scene s = parse(line +
                          "top: {position: [1, 2], motion: {type: sinusoid, amplitude: [10, 0], period: 27,"
                          " phase: 0.5}}");
    EXPECT_STREQ(name(s.top.type), "sinusoid");
    EXPECT_EQ(s.top.position, Eigen::Vector3d(1, 0, 2));  // [x, z]: (x, 0, z)
    EXPECT_EQ(s.top.amplitude, Eigen::Vector3d(10, 0, 0));
    EXPECT_EQ(s.top.period, 27.0);
    EXPECT_EQ(s.top.phase, Eigen::Vector3d::Constant(0.5));  // one phase: every axis's
  }
  {
    const Scene s = parse(line +
                          "top: {motion: {type: velocity_profile, knots: [[0, [0, 0]], [20, [1.5, 0]], "
                          "[40, [0, -0.5]]]}}");
    ASSERT_EQ(s.top.knots.size(), 3u);
    EXPECT_EQ(s.top.knots[1].t, 20.0);
    EXPECT_EQ(s.top.knots[1].v, Eigen::Vector3d(1.5, 0, 0));
    EXPECT_EQ(s.top.knots[2].v, Eigen::Vector3d(0, 0, -0.5));
  }
  {
    const Scene s = parse(line + "bottom: {type: pinned, position: [6, -7]}\ninitial: {type: between_points}");
    EXPECT_EQ(s.bottom, BottomBoundary::kPinned);
    EXPECT_EQ(s.bottom_point, Eigen::Vector3d(6, 0, -7));
    EXPECT_STREQ(name(s.initial.type), "between_points");
  }
  {
    const Scene s = parse(line + "initial: {type: straight, angle: -30, tolerance: 1e-6}");
    EXPECT_NEAR(s.initial.angle, -M_PI / 6, kRelTol);  // degrees in the file, radians in Scene
    EXPECT_EQ(s.initial.tolerance, 1e-6);
  }
  {
    const Scene s = parse(line + "initial: {type: displaced, end_dx: -5}\nenvironment: {gravity: 0}");
    EXPECT_EQ(s.initial.end_dx, -5.0);
    EXPECT_EQ(s.gravity, 0.0);
  }
  {
    const Scene s = parse(line + "initial: {type: displaced, end_dx: -5, end_force: hold}");
    EXPECT_STREQ(name(s.initial.end_force), "hold");
  }
  {
    // Keys of another motion type are accepted and ignored.
    const Scene s = parse(line + "top: {motion: {type: fixed, amplitude: [3, 0], period: 5}}");
    EXPECT_STREQ(name(s.top.type), "fixed");
  }
}

TEST(SceneYaml, OverridesSetAndCreateKeys) {
  YAML::Node root = YAML::Load(kMinimal);
  applyOverride(root, "line.elements=40");
  applyOverride(root, "top.position=[1,2]");           // creates the "top" section
  applyOverride(root, " environment.gravity = 3.7 ");  // spaces around are fine
  applyOverride(root, "solver={dt: 2e-4, integrator: rk4}");
  applyOverride(root, "name=my run");
  const Scene s = parseScene(root);
  EXPECT_EQ(s.elements, 40);
  EXPECT_EQ(s.top.position, Eigen::Vector3d(1, 0, 2));
  EXPECT_EQ(s.gravity, 3.7);
  EXPECT_EQ(s.solver.dt, 2e-4);
  EXPECT_EQ(s.name, "my run");
  // The file's other keys are untouched.
  EXPECT_EQ(s.length, 100.0);
}

TEST(SceneYaml, OverrideOnEmptyTree) {
  YAML::Node root;
  applyOverride(root, "line.length=5");
  EXPECT_EQ(root["line"]["length"].as<double>(), 5.0);
}

TEST(SceneYaml, MalformedOverrides) {
  struct Case {
    const char* assignment;
    const char* key;
    const char* message;
  };
  const Case cases[] = {
      {"line.elements", "", "expected key.path=value"},
      {"=3", "", "expected key.path=value"},
      {"line..elements=3", "line..elements", "malformed override"},
      {"line.elements.=3", "line.elements.", "malformed override"},
      {"line.elem ents=3", "line.elem ents", "malformed override"},
      {"line.elements=", "line.elements", "has no value"},
      {"line.elements=[1", "line.elements", "cannot parse override value"},
      {"line.length.x=1", "line.length", "is a value, not a section"},
      // aliases: a cycle, and 8^6 leaves from 50 nodes ("billion laughs")
      {"line=&a [*a]", "line", "override value is too large"},
      {"line={a: &a [1,1,1,1,1,1,1,1], b: &b [*a,*a,*a,*a,*a,*a,*a,*a], c: &c [*b,*b,*b,*b,*b,*b,*b,*b], "
       "d: &d [*c,*c,*c,*c,*c,*c,*c,*c], e: &e [*d,*d,*d,*d,*d,*d,*d,*d], f: [*e,*e,*e,*e,*e,*e,*e,*e]}",
       "line", "override value is too large"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.assignment);
    YAML::Node root = YAML::Load(kMinimal);
    try {
      applyOverride(root, c.assignment);
      ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key(), c.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
}

TEST(SceneYaml, OverrideErrorsNameTheKey) {
  const std::string path = tempPath("override.yaml");
  std::ofstream(path) << kMinimal;
  try {
    loadSceneFile(path, {"line.elements=0"});
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "line.elements");
    EXPECT_EQ(std::string(e.what()), "line.elements: must be >= 1, got 0");
  }
  std::filesystem::remove(path);
}

TEST(SceneYaml, LoadFileReportsMissingFileAndSyntaxErrors) {
  try {
    loadSceneFile("/nonexistent/riser_sim/scene.yaml");
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open scene file '/nonexistent/riser_sim/scene.yaml'"),
              std::string::npos)
        << e.what();
  }
  const std::string path = tempPath("syntax.yaml");
  std::ofstream(path) << "name: broken\nline:\n  length: 10\n  elements: [4\n  EA: 1\n";
  try {
    loadSceneFile(path);
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("YAML syntax error"), std::string::npos) << what;
    EXPECT_NE(what.find(path + ":"), std::string::npos) << what;  // file:line:column
  }
  std::filesystem::remove(path);
}

// The size limit is on the bytes read: a scene padded with a comment to exactly kMaxSceneFileBytes loads,
// one byte more is refused naming the file and the limit.
TEST(SceneYaml, LoadFileSizeLimit) {
  const std::string path = tempPath("padded.yaml");
  const std::string scene = std::string(kMinimal) + "\n#";
  ASSERT_LT(scene.size() + 1, kMaxSceneFileBytes);
  for (const size_t size : {kMaxSceneFileBytes, kMaxSceneFileBytes + 1}) {
    SCOPED_TRACE(size);
    std::ofstream(path) << scene << std::string(size - scene.size() - 1, 'x') << "\n";
    ASSERT_EQ(std::filesystem::file_size(path), size);
    if (size <= kMaxSceneFileBytes) {
      EXPECT_NO_THROW(loadSceneFile(path));
      continue;
    }
    try {
      loadSceneFile(path);
      FAIL() << "no SceneError";
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()), "scene file '" + path +
                                           "' is larger than 1 MiB (1048576 bytes), the limit "
                                           "for a scene file");
    }
  }
  std::filesystem::remove(path);
}

TEST(SceneYaml, NameDefaultsToTheFileStem) {
  const std::string path = tempPath("stem_test.yaml");
  std::ofstream(path) << kMinimal;
  const Scene s = loadSceneFile(path);
  EXPECT_EQ(s.name, std::filesystem::path(path).stem().string());
  std::filesystem::remove(path);
}

TEST(SceneYaml, PaperTable1Scene) {
  const Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_table1.yaml");
  // Paper section 2: L = 100 m, m_s = 1000 kg, E = 1e11 Pa, rho = 2000 kg/m^3, R = 0.025 m, c^b = 0.
  const double area = M_PI * 0.025 * 0.025;
  EXPECT_EQ(s.name, "paper_table1");
  EXPECT_EQ(s.length, 100.0);
  EXPECT_EQ(s.elements, 10);
  EXPECT_EQ(s.end_mass, 1000.0);
  EXPECT_NEAR(s.line.EA, 1e11 * area, kRelTol * 1e11 * area);
  EXPECT_NEAR(s.line.mass_per_length, 2000 * area, kRelTol * 2000 * area);
  EXPECT_FALSE(s.options.bending);
  EXPECT_TRUE(s.options.axial_flexibility);
  EXPECT_STREQ(name(s.initial.type), "displaced");
  EXPECT_EQ(s.initial.end_dx, -50.0);
  EXPECT_STREQ(name(s.top.type), "fixed");
  EXPECT_EQ(s.top.position, Eigen::Vector3d::Zero());
  EXPECT_STREQ(name(s.solver.integrator), "rk4");
  EXPECT_EQ(s.solver.dt, 1e-4);
  EXPECT_EQ(s.duration, 20.0);
}

// catkin_add_gtest links gtest without gtest_main here; a main of our own works either way.
int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

// Values the loader would stop can still reach buildSimulator from code (or combine beyond double
// range within the limits): the run is refused rather than started from non-finite forces.
TEST(SceneYaml, BuildRefusesNonFiniteInitialForces) {
  Scene s = parse("{line: {length: 10, elements: 4, EA: 1e6, EI: 0, mass_per_length: 1}}");
  s.top.type = MotionKind::kSinusoid;
  s.top.amplitude = Eigen::Vector3d(1e300, 0.0, 0.0);
  s.top.period = 1e-300;  // acceleration amplitude ~1e300 * (2 pi 1e300)^2 = inf
  try {
    buildSimulator(s);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("initial: the initial state or its forces are not finite", 0), 0u)
        << e.what();
  }
}
