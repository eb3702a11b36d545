#include "scene_exercise.h"

#include <cmath>
#include <exception>
#include <memory>
#include <regex>
#include <sstream>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace fuzz {
namespace {

// The loader's own keyless errors: the text as a whole is bad, there is no key to name.
bool keylessKind(const std::string& what) {
  for (const char* m :
       {": YAML syntax error: ", "cannot read scene", "malformed override", "a scene must be a map of sections",
        "cannot apply override", "top-level keys must be plain names"})
    if (what.find(m) != std::string::npos) return true;
  return false;
}

// Errors from building a scene start with the key path: "line.elements: ...", "top.motion.knots[2]: ...".
bool namesKey(const std::string& what) {
  static const std::regex key(R"(^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*(\[[0-9]+\])*: )");
  return std::regex_search(what, key);
}

bool finite(double v) { return std::isfinite(v); }
bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// The first non-finite output, or "".
std::string nonFiniteOutput(const LineOutputs& o) {
  for (const auto& p : o.points)
    if (!p.allFinite()) return "points";
  if (!finite(o.angles)) return "angles";
  if (!finite(o.elongations)) return "elongations";
  if (!finite(o.axial_force)) return "axial_force";
  if (!finite(o.arc_length)) return "arc_length";
  if (!finite(o.bending_moment)) return "bending_moment";
  if (!o.top_force.allFinite() || !o.bottom_force.allFinite()) return "end forces";
  for (double v : {o.t, o.top_tension, o.bottom_tension, o.max_tension, o.kinetic_energy, o.potential_energy, o.work_in,
                   o.constraint_error})
    if (!finite(v)) return "scalar outputs";
  return "";
}

std::string describeException() {
  try {
    throw;
  } catch (const std::exception& e) {
    return std::string("std::exception: ") + e.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

// space: spatial: the 3D builder and a few steps, under the same rules.
Outcome buildSpatial(const Scene& scene) {
  Outcome out;
  std::unique_ptr<spatial::Run3> run;
  try {
    run = std::make_unique<spatial::Run3>(scene);
  } catch (const std::exception& e) {
    out.kind = Outcome::Kind::kBuildRejected;
    out.message = e.what();
    if (!namesKey(out.message)) out.defect = "build error without a key: " + out.message;
    return out;
  } catch (...) {
    out.defect = "build: " + describeException();
    return out;
  }
  out.kind = Outcome::Kind::kBuilt;
  int steps = 0;
  for (;;) {
    const spatial::LineOutputs3& o = run->outputs();
    bool ok = o.top_force.allFinite() && o.bottom_force.allFinite() && finite(o.axial_force);
    for (const auto& p : o.points) ok = ok && p.allFinite();
    for (double v : {o.top_tension, o.max_tension, o.kinetic_energy, o.potential_energy, o.work_in, o.constraint_error})
      ok = ok && finite(v);
    if (!ok) {
      out.defect = "non-finite 3D outputs after " + std::to_string(steps) + " steps";
      return out;
    }
    if (steps == kSteps || !run->step()) break;
    ++steps;
  }
  out.message = "built (3D), " + std::to_string(steps) + " steps" +
                (run->diverged() ? " (diverged: " + run->divergenceReason() + ")" : "");
  return out;
}

Outcome build(const Scene& scene) {
  if (scene.space == SpaceKind::kSpatial) return buildSpatial(scene);
  Outcome out;
  std::unique_ptr<Simulator> sim;
  try {
    sim = buildSimulator(scene);
  } catch (const std::exception& e) {
    out.kind = Outcome::Kind::kBuildRejected;
    out.message = e.what();
    if (!namesKey(out.message)) out.defect = "build error without a key: " + out.message;
    return out;
  } catch (...) {
    out.defect = "build: " + describeException();
    return out;
  }
  out.kind = Outcome::Kind::kBuilt;
  if (!sim->state().allFinite()) {
    out.defect = "built simulator has a non-finite state";
    return out;
  }
  int steps = 0;
  for (;;) {
    const std::string bad = nonFiniteOutput(sim->outputs());
    if (!bad.empty()) {
      out.defect = "non-finite " + bad + " after " + std::to_string(steps) + " steps";
      return out;
    }
    if (steps == kSteps || !sim->step()) break;
    ++steps;
  }
  out.message = "built, " + std::to_string(steps) + " steps" +
                (sim->diverged() ? " (diverged: " + sim->divergenceReason() + ")" : "");
  return out;
}

}  // namespace

SceneInput splitInput(const std::string& data) {
  SceneInput in;
  std::istringstream lines(data);
  std::string line;
  bool first = true;
  while (std::getline(lines, line)) {
    if (line.rfind("--set ", 0) == 0) {
      in.overrides.push_back(line.substr(6));
      continue;
    }
    in.yaml += (first ? "" : "\n") + line;
    first = false;
  }
  return in;
}

Outcome exercise(const std::string& data) {
  const SceneInput in = splitInput(data);
  Outcome out;
  Scene scene;
  try {
    scene = loadSceneText(in.yaml, "fuzz", in.overrides);
  } catch (const SceneError& e) {
    out.message = e.what();
    if (e.key().empty() && !keylessKind(out.message)) out.defect = "SceneError without a key: " + out.message;
    return out;
  } catch (...) {
    out.defect = "load: " + describeException();
    return out;
  }
  if (scene.elements < 1 || scene.elements > kMaxSceneElements) {
    out.defect = "accepted line.elements = " + std::to_string(scene.elements);
    return out;
  }
  if (scene.elements > kMaxBuiltElements) {
    out.kind = Outcome::Kind::kParsed;
    out.message = "parsed (not built: " + std::to_string(scene.elements) + " elements)";
    return out;
  }
  if (scene.solver.integrator == IntegratorKind::kDopri5 && scene.solver.dt > kMaxBuiltDopri5Dt) {
    out.kind = Outcome::Kind::kParsed;
    out.message = "parsed (not built: dopri5 with solver.dt > 1 s)";
    return out;
  }
  return build(scene);
}

}  // namespace fuzz
}  // namespace riser_sim
