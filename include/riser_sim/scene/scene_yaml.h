// Scene files (YAML): the same format for the CLI and for the node's private parameters.
// Every error names the offending key path (e.g. "line.outer_diameter").
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "riser_sim/scene/scene.h"

namespace riser_sim {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& key, const std::string& what)
      : std::runtime_error(key.empty() ? what : key + ": " + what), key_(key) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Size limits of a loaded scene (docs/scene_keys.md, "Limits"): the static initial state is a dense
// Newton solve on ~2n unknowns, the dense implicit Jacobian four p x p matrices (p ~ 4n on absolute).
constexpr int kMaxSceneElements = 2000;          // line.elements
constexpr double kMaxSceneSteps = 1e9;           // run.duration / solver.dt
constexpr double kMaxSceneNumber = 1e15;         // |every number|: larger ones overflow the forces
constexpr size_t kMaxSceneFileBytes = 1u << 20;  // a scene file (1 MiB): yaml-cpp takes ~250x that

// Parses and validates a scene. Throws SceneError.
Scene parseScene(const YAML::Node& root);
// Reads FILE, applies "key.path=value" overrides (value parsed as YAML), parses. Throws SceneError.
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});
// The same for scene text; SOURCE names it in syntax errors ("SOURCE:line:column: ...").
Scene loadSceneText(const std::string& text, const std::string& source, const std::vector<std::string>& overrides = {});
// "unknown key (did you mean 'length'?)" when an accepted key is within two edits of `key`, else
// "unknown key (accepted: a, b, ...)". The scene loader's message; the node's parameters use it too.
std::string unknownKeyMessage(const std::string& key, const std::vector<std::string>& accepted);
// Applies one "key.path=value" override to a YAML tree. Throws SceneError.
void applyOverride(YAML::Node& root, const std::string& assignment);

}  // namespace riser_sim
