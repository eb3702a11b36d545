// Scene files and "key.path=value" overrides: bounded reading, override application, then
// parseScene (scene_sections.cpp). Every error is a SceneError naming the key path or the file.
#include "riser_sim/scene/scene_yaml.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "riser_sim/integrators/integrator.h"
#include "riser_sim/scene/solver_setup.h"

namespace riser_sim {
namespace {

// A copy of an override value without the parser's marks (they would point into the --set text).
// Aliases can make the tree a cycle (&a [*a]) or exponentially large: the copy is bounded.
constexpr int kMaxOverrideNodes = 10000, kMaxOverrideDepth = 64;
YAML::Node plainCopy(const YAML::Node& n, const std::string& path, int& budget, int depth = 0) {
  if (--budget < 0 || depth > kMaxOverrideDepth)
    throw SceneError(path, "override value is too large (more than " + std::to_string(kMaxOverrideNodes) +
                               " nodes or " + std::to_string(kMaxOverrideDepth) + " levels; aliases?)");
  if (n.IsScalar()) return YAML::Node(n.Scalar());
  if (n.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const auto& item : n) out.push_back(plainCopy(item, path, budget, depth + 1));
    return out;
  }
  if (n.IsMap()) {
    YAML::Node out(YAML::NodeType::Map);
    for (const auto& kv : n) out[kv.first.Scalar()] = plainCopy(kv.second, path, budget, depth + 1);
    return out;
  }
  return YAML::Node(YAML::NodeType::Null);
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// Removes the key parts from root; a key (or section) that is not there is an error naming it.
void removeKey(YAML::Node& root, const std::vector<std::string>& parts, const std::string& path) {
  const auto absent = [&](const std::string& key) {
    return SceneError(key, "is not in the scene: nothing to remove (" + path + "=null)");
  };
  if (!root.IsMap()) throw absent(parts.front());
  YAML::Node cur = root;
  std::string prefix;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    prefix += (i ? "." : "") + parts[i];
    YAML::Node next = cur[parts[i]];
    if (!next.IsDefined() || !next.IsMap()) throw absent(prefix);
    cur.reset(next);
  }
  if (!cur[parts.back()].IsDefined()) throw absent(path);
  cur.remove(parts.back());
}

}  // namespace

void applyOverride(YAML::Node& root, const std::string& assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw SceneError("", "malformed override '" + assignment + "': expected key.path=value");
  const std::string path = trim(assignment.substr(0, eq));
  const std::string text = trim(assignment.substr(eq + 1));
  std::vector<std::string> parts;
  std::string part;
  std::istringstream ps(path);
  while (std::getline(ps, part, '.')) parts.push_back(part);
  if (path.empty() || path.back() == '.') parts.push_back("");
  for (const auto& p : parts)
    if (p.empty() ||
        p.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      throw SceneError(path, "malformed override '" + assignment +
                                 "': expected key.path=value with keys made of "
                                 "letters, digits and _");
  if (text.empty()) throw SceneError(path, "override '" + assignment + "' has no value");
  if (text == "null" || text == "~") {  // key=null: the key is absent (removed from the tree)
    removeKey(root, parts, path);
    return;
  }
  YAML::Node value;
  try {
    int budget = kMaxOverrideNodes;
    value = plainCopy(YAML::Load(text), path, budget);
  } catch (const YAML::Exception& e) {
    throw SceneError(path, "cannot parse override value '" + text + "': " + e.msg);
  }

  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) throw SceneError("", "cannot apply override '" + assignment + "': the scene is not a map");
  YAML::Node cur = root;  // shares root's tree; moved down with reset() (operator= would overwrite)
  std::string prefix;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    prefix += (i ? "." : "") + parts[i];
    YAML::Node next = cur[parts[i]];
    if (!next.IsDefined() || next.IsNull()) {
      cur[parts[i]] = YAML::Node(YAML::NodeType::Map);
      next.reset(cur[parts[i]]);
    } else if (!next.IsMap()) {
      throw SceneError(prefix, "is a value, not a section: cannot set " + path);
    }
    cur.reset(next);
  }
  cur[parts.back()] = value;
}

Scene loadSceneText(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError("", source + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                             ": YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw SceneError("", "cannot read scene '" + source + "': " + e.msg);
  }
  for (const auto& o : overrides) applyOverride(root, o);
  return parseScene(root);
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(path)) throw SceneError("", "scene file '" + path + "' is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("", "cannot open scene file '" + path + "': " + std::strerror(errno));
  // Bounded read: an endless input (/dev/zero, a pipe) must not grow memory until the process is killed.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof(chunk)) || in.gcount() > 0) {
    text.append(chunk, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxSceneFileBytes)
      throw SceneError("", "scene file '" + path + "' is larger than " + std::to_string(kMaxSceneFileBytes >> 20) +
                               " MiB (" + std::to_string(kMaxSceneFileBytes) + " bytes), the limit for a scene file");
  }
  if (in.bad()) throw SceneError("", "cannot read scene file '" + path + "': " + std::strerror(errno));
  Scene s = loadSceneText(text, path, overrides);
  if (s.name.empty()) s.name = std::filesystem::path(path).stem().string();
  return s;
}

}  // namespace riser_sim
