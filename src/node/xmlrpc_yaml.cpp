#include "riser_sim_ros/xmlrpc_yaml.h"

#include <cmath>
#include <cstdio>

namespace riser_sim_ros {

namespace {
std::string formatDouble(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", v);  // round-trips exactly
  std::string s(buf);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep it a float ("inf"/"nan" left as is)
  return s;
}
}  // namespace

YAML::Node toYaml(XmlRpc::XmlRpcValue& value, const std::string& path) {
  using XmlRpc::XmlRpcValue;
  const std::string where = path.empty() ? "(root)" : path;
  switch (value.getType()) {
    case XmlRpcValue::TypeBoolean: return YAML::Node(static_cast<bool>(value));
    case XmlRpcValue::TypeInt: return YAML::Node(static_cast<int>(value));
    case XmlRpcValue::TypeDouble: {
      const double d = static_cast<double>(value);
      if (!std::isfinite(d)) return YAML::Node(d > 0 ? ".inf" : (d < 0 ? "-.inf" : ".nan"));
      return YAML::Node(formatDouble(d));
    }
    case XmlRpcValue::TypeString: return YAML::Node(static_cast<std::string>(value));
    case XmlRpcValue::TypeArray: {
      YAML::Node seq(YAML::NodeType::Sequence);
      for (int i = 0; i < value.size(); ++i) seq.push_back(toYaml(value[i], path + "[" + std::to_string(i) + "]"));
      return seq;
    }
    case XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto it = value.begin(); it != value.end(); ++it)
        map[it->first] = toYaml(it->second, path.empty() ? it->first : path + "." + it->first);
      return map;
    }
    default: throw std::invalid_argument(where + ": unsupported parameter type (base64, date or invalid)");
  }
}

std::string paramPath(const std::string& ns, const std::string& key) {
  std::string out = ns;
  if (key.empty()) return out;
  out += '/';
  for (char c : key) out += (c == '.') ? '/' : c;
  return out;
}

}  // namespace riser_sim_ros
