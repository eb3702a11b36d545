// Internals of the scene loader (scene_sections.cpp, scene_sea_sections.cpp): formatting for messages, typed
// conversions of one YAML node (every message names the key path), and Section, a YAML map whose keys are checked.
#pragma once
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace scene_detail {

inline constexpr double kDegToRad = M_PI / 180.0;

inline std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

inline std::string formatNumber(double v) {
  std::ostringstream os;
  os.precision(9);
  os << v;
  return os.str();
}

// "got ..." part of a type error.
inline std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing (null)";
  if (node.IsSequence()) return "a list of " + std::to_string(node.size()) + (node.size() == 1 ? " item" : " items");
  if (node.IsMap()) return "a map";
  return "'" + node.Scalar() + "'";
}

// " (line L, column C)" of a node read from text, "" for one built in code or copied from an override.
inline std::string where(const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  if (m.is_null() || m.line < 0) return "";
  return " (line " + std::to_string(m.line + 1) + ", column " + std::to_string(m.column + 1) + ")";
}

inline size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// ---- typed conversions of one node; `key` is its full path, used in every message ----

inline double toNumber(const YAML::Node& node, const std::string& key) {
  double v = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, v))
    throw SceneError(key, "expected a number, got " + describe(node));
  if (!std::isfinite(v)) throw SceneError(key, "must be a finite number, got " + describe(node));
  if (std::abs(v) > kMaxSceneNumber)
    throw SceneError(key, "must be within +-" + formatNumber(kMaxSceneNumber) + ", got " + formatNumber(v));
  return v;
}

inline int toInteger(const YAML::Node& node, const std::string& key) {
  int v = 0;
  long long wide = 0;
  if (node.IsScalar() && !YAML::convert<int>::decode(node, v) && YAML::convert<long long>::decode(node, wide))
    throw SceneError(key, "must be an integer within +-2147483647, got " + describe(node));
  if (!node.IsScalar() || !YAML::convert<int>::decode(node, v))
    throw SceneError(key, "expected an integer, got " + describe(node));
  return v;
}

// An integer of any size a scene holds (seeds: 32 bits unsigned).
inline long long toInteger64(const YAML::Node& node, const std::string& key) {
  long long v = 0;
  if (!node.IsScalar() || !YAML::convert<long long>::decode(node, v))
    throw SceneError(key, "expected an integer, got " + describe(node));
  return v;
}

inline bool toBool(const YAML::Node& node, const std::string& key) {
  bool v = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, v))
    throw SceneError(key, "expected true or false, got " + describe(node));
  return v;
}

inline std::string toText(const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) throw SceneError(key, "expected a string, got " + describe(node));
  return node.Scalar();
}

inline Vec2 toVec2(const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() != 2) throw SceneError(key, "expected [x, y], got " + describe(node));
  return Vec2(toNumber(node[0], key + "[0]"), toNumber(node[1], key + "[1]"));
}

// A point or vector of the scene: [a, b] keeps its planar meaning [x, z_up] and is (a, 0, b) in 3D;
// [x, y, z] is 3D (z up). In a planar scene a y != 0 is out of the plane: refused, naming the key.
inline Eigen::Vector3d toVec3(const YAML::Node& node, const std::string& key, bool planar) {
  if (!node.IsSequence() || (node.size() != 2 && node.size() != 3))
    throw SceneError(key, "expected [x, z] (planar: x horizontal, z up) or [x, y, z] (z up), got " + describe(node));
  if (node.size() == 2) return Eigen::Vector3d(toNumber(node[0], key + "[0]"), 0.0, toNumber(node[1], key + "[1]"));
  const Eigen::Vector3d v(toNumber(node[0], key + "[0]"), toNumber(node[1], key + "[1]"),
                          toNumber(node[2], key + "[2]"));
  if (planar && v.y() != 0.0)
    throw SceneError(key + "[1]", "y = " + formatNumber(v.y()) +
                                      " points out of the vertical x-z plane of a planar "
                                      "scene (space: planar, the default); set space: spatial for a 3D scene");
  return v;
}

// ---- value checks ----

inline void requirePositive(const std::string& key, double v) {
  if (!(v > 0.0)) throw SceneError(key, "must be > 0, got " + formatNumber(v));
}
inline void requireNonNegative(const std::string& key, double v) {
  if (!(v >= 0.0)) throw SceneError(key, "must be >= 0, got " + formatNumber(v));
}

// One map of the scene tree ("line", "top.motion", ...). Rejects keys it does not accept on
// construction, so a typo is reported as such rather than as a missing key.
class Section {
 public:
  Section(const YAML::Node& node, std::string path, std::vector<std::string> accepted)
      : node_(node), path_(std::move(path)), accepted_(std::move(accepted)) {
    if (!node_.IsDefined() || node_.IsNull()) return;  // absent or empty: every key takes its default
    if (!node_.IsMap())
      throw SceneError(path_, path_.empty() ? "a scene must be a map of sections, got " + describe(node_)
                                            : "expected a map of keys, got " + describe(node_));
    std::vector<std::string> seen;
    for (const auto& kv : node_) {
      if (!kv.first.IsScalar() || kv.first.Scalar().empty())  // "! : 5" is a scalar key ''
        throw SceneError(path_, std::string(path_.empty() ? "top-level keys" : "keys") + " must be plain names, got " +
                                    describe(kv.first) + where(kv.first));
      const std::string k = kv.first.Scalar();
      if (std::find(seen.begin(), seen.end(), k) != seen.end()) throw SceneError(key(k), "duplicate key");
      seen.push_back(k);
      if (std::find(accepted_.begin(), accepted_.end(), k) == accepted_.end())
        throw SceneError(key(k), unknownKeyMessage(k, accepted_));
    }
  }

  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  bool has(const std::string& k) const { return node_.IsMap() && node_[k].IsDefined(); }
  YAML::Node at(const std::string& k) const {
    if (!has(k)) throw SceneError(key(k), "missing required key");
    return node_[k];
  }
  Section section(const std::string& k, std::vector<std::string> accepted) const {
    return Section(has(k) ? node_[k] : YAML::Node(), key(k), std::move(accepted));
  }

  double number(const std::string& k) const { return toNumber(at(k), key(k)); }
  double number(const std::string& k, double def) const { return has(k) ? number(k) : def; }
  int integer(const std::string& k) const { return toInteger(at(k), key(k)); }
  bool boolean(const std::string& k, bool def) const { return has(k) ? toBool(at(k), key(k)) : def; }
  std::string text(const std::string& k, const std::string& def) const { return has(k) ? toText(at(k), key(k)) : def; }
  Vec2 vec2(const std::string& k) const { return toVec2(at(k), key(k)); }
  Vec2 vec2(const std::string& k, const Vec2& def) const { return has(k) ? vec2(k) : def; }
  Eigen::Vector3d vec3(const std::string& k, bool planar) const { return toVec3(at(k), key(k), planar); }
  Eigen::Vector3d vec3(const std::string& k, bool planar, const Eigen::Vector3d& def) const {
    return has(k) ? vec3(k, planar) : def;
  }
  // A string from a fixed list.
  // One of the enum's names (choices.h), parsed once here.
  template <class E>
  E choice(const std::string& k, E def) const {
    const std::string v = text(k, name(def));
    if (const auto e = parseChoice<E>(v)) return *e;
    throw SceneError(key(k), "unknown value '" + v + "' (accepted: " + choiceNames<E>() + ")");
  }
  std::string choice(const std::string& k, const std::string& def, const std::vector<std::string>& allowed) const {
    const std::string v = text(k, def);
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      throw SceneError(key(k), "unknown value '" + v + "' (accepted: " + join(allowed) + ")");
    return v;
  }

 private:
  YAML::Node node_;
  std::string path_;
  std::vector<std::string> accepted_;
};

// The sea's sections (scene_sea_sections.cpp): environment (gravity, water, current, waves), hydrodynamics,
// seabed, internal_fluid.
void parseEnvironment(const Section& root, Scene& s);
void parseHydrodynamics(const Section& root, Scene& s);
void parseSeabed(const Section& root, Scene& s);
void parseInternalFluid(const Section& root, Scene& s);
// The attachments (scene_attachments.cpp): after the line, the sea and the seabed.
void parseAttachments(const Section& root, Scene& s);
// Throws SceneError naming the attachment that lifts most (attachments[k].volume) when, with a free end, the
// attachments' buoyancy is at least the weight in water of the line with them (its buoyant sections included:
// after finishLineSections).
void checkAttachmentsFloat(const Scene& s);

// line.sections and line.bend_stiffener (scene_line_sections.cpp): read at the end of the line block;
// finishLineSections smears buoyancy modules once the hydrodynamics block is read.
void parseLineSections(const Section& line, Scene& s);
void finishLineSections(Scene& s);

// The ends' sections (scene_end_sections.cpp): top, bottom.
void parseTop(const Section& root, Scene& s);
void parseBottom(const Section& root, Scene& s);

}  // namespace scene_detail
}  // namespace riser_sim
