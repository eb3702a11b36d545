// Parameter-server tree (XmlRpcValue) -> YAML::Node, so the node reads its scene from ~scene with the
// same parser as the scene files (riser_sim::parseScene).
#pragma once
#include <stdexcept>
#include <string>

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

namespace riser_sim_ros {

// Converts recursively: struct -> map, array -> sequence, bool/int/double/string -> scalar.
// Throws std::invalid_argument naming the key path (e.g. "line.elements") for base64/datetime/invalid.
YAML::Node toYaml(XmlRpc::XmlRpcValue& value, const std::string& path = "");

// A scene key path as the user wrote it on the parameter server: "line.elements" under "~scene"
// -> "~scene/line/elements" (indices stay: "top.motion.knots[1]" -> "~scene/top/motion/knots[1]").
std::string paramPath(const std::string& ns, const std::string& key);

}  // namespace riser_sim_ros
