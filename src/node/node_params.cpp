#include "riser_sim_ros/node_params.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include "riser_sim/scene/scene_yaml.h"

#include "riser_sim_ros/line_topics.h"

namespace riser_sim_ros {

namespace {

using XmlRpc::XmlRpcValue;

std::string show(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string describe(XmlRpcValue& v) {
  switch (v.getType()) {
    case XmlRpcValue::TypeBoolean: return static_cast<bool>(v) ? "true" : "false";
    case XmlRpcValue::TypeInt: return std::to_string(static_cast<int>(v));
    case XmlRpcValue::TypeDouble: return show(static_cast<double>(v));
    case XmlRpcValue::TypeString: return "'" + static_cast<std::string>(v) + "'";
    case XmlRpcValue::TypeArray: return "a list of " + std::to_string(v.size());
    case XmlRpcValue::TypeStruct: return "a map";
    default: return "an unsupported value";
  }
}

// A scalar given as a string ('1e8': YAML 1.1, which rosparam uses, reads it as a string) converts as
// the scene loader converts it (yaml-cpp, YAML 1.2), so both accept the same forms.
template <class T>
bool decodeString(XmlRpcValue& v, T& out) {
  return v.getType() == XmlRpcValue::TypeString &&
         YAML::convert<T>::decode(YAML::Node(static_cast<std::string>(v)), out);
}

bool decodeNumber(XmlRpcValue& v, double& out) {
  if (v.getType() == XmlRpcValue::TypeDouble)
    out = static_cast<double>(v);
  else if (v.getType() == XmlRpcValue::TypeInt)
    out = static_cast<int>(v);
  else
    return decodeString(v, out);
  return true;
}

// Reads the private parameters and remembers every name it was asked for: those are the accepted
// ones (checkUnknown()).
class Reader {
 public:
  explicit Reader(const ros::NodeHandle& pnh) : pnh_(pnh) {}

  double number(const std::string& name, double def) {
    XmlRpcValue v;
    if (!get(name, v)) return def;
    double d;
    if (!decodeNumber(v, d)) throw ParamError(name, "expected a number, got " + describe(v));
    if (!std::isfinite(d)) throw ParamError(name, "must be finite, got " + show(d));
    return d;
  }
  int integer(const std::string& name, int def) {
    XmlRpcValue v;
    if (!get(name, v)) return def;
    int i;
    if (v.getType() == XmlRpcValue::TypeInt)
      i = static_cast<int>(v);
    else if (!decodeString(v, i))
      throw ParamError(name, "expected an integer, got " + describe(v));
    return i;
  }
  bool boolean(const std::string& name, bool def) {
    XmlRpcValue v;
    if (!get(name, v)) return def;
    bool b;
    if (v.getType() == XmlRpcValue::TypeBoolean)
      b = static_cast<bool>(v);
    else if (!decodeString(v, b))
      throw ParamError(name, "expected true or false, got " + describe(v));
    return b;
  }
  std::string text(const std::string& name, const std::string& def) {
    XmlRpcValue v;
    if (!get(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeString) throw ParamError(name, "expected a string, got " + describe(v));
    return static_cast<std::string>(v);
  }
  Eigen::Vector3d vec3(const std::string& name, const Eigen::Vector3d& def) {
    XmlRpcValue v;
    if (!get(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeArray || v.size() != 3)
      throw ParamError(name, "expected [x, y, z], got " + describe(v));
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
      const std::string element = name + "[" + std::to_string(i) + "]";
      if (!decodeNumber(v[i], out[i])) throw ParamError(element, "expected a number, got " + describe(v[i]));
      if (!std::isfinite(out[i])) throw ParamError(element, "must be finite");
    }
    return out;
  }
  // Names read from elsewhere (~scene: loadScene).
  void accept(const std::string& name) { known_.push_back(name); }

  // Every parameter in the private namespace must be one that was read: a misspelt one would be
  // ignored silently. Throws ParamError naming it, with the closest accepted name or the list.
  void checkUnknown() const {
    XmlRpcValue tree;
    if (!pnh_.getParam(pnh_.getNamespace(), tree) || tree.getType() != XmlRpcValue::TypeStruct) return;
    checkGroup(tree, "");
  }

 private:
  bool get(const std::string& name, XmlRpcValue& v) {
    known_.push_back(name);
    return pnh_.getParam(name, v);
  }
  // The accepted names directly under `group` ("" or "rates/"): leaves, and sub-groups as "motion/".
  std::vector<std::string> acceptedIn(const std::string& group) const {
    std::vector<std::string> out;
    for (const std::string& k : known_) {
      if (k.compare(0, group.size(), group) != 0) continue;
      std::string rest = k.substr(group.size());
      const auto slash = rest.find('/');
      if (slash != std::string::npos) rest = rest.substr(0, slash + 1);
      if (std::find(out.begin(), out.end(), rest) == out.end()) out.push_back(rest);
    }
    return out;
  }
  void checkGroup(XmlRpcValue& tree, const std::string& group) const {
    const std::vector<std::string> accepted = acceptedIn(group);
    for (auto it = tree.begin(); it != tree.end(); ++it) {
      const std::string& key = it->first;
      if (std::find(accepted.begin(), accepted.end(), key) != accepted.end()) continue;  // a leaf
      if (std::find(accepted.begin(), accepted.end(), key + "/") != accepted.end() &&
          it->second.getType() == XmlRpcValue::TypeStruct) {
        checkGroup(it->second, group + key + "/");
        continue;
      }
      std::string message = riser_sim::unknownKeyMessage(key, accepted);
      message.replace(0, std::string("unknown key").size(), "unknown parameter");
      if (message.find("did you mean") != std::string::npos) {
        std::string list;
        for (const std::string& a : accepted) list += (list.empty() ? "" : ", ") + a;
        message += "; accepted" + (group.empty() ? std::string() : " under ~" + group) + ": " + list;
      }
      throw ParamError(group + key, message);
    }
  }

  const ros::NodeHandle& pnh_;
  std::vector<std::string> known_;
};

void positive(const std::string& name, double v) {
  if (!(v > 0.0)) throw ParamError(name, "must be > 0, got " + show(v));
}
void nonNegative(const std::string& name, double v, const std::string& note = "") {
  if (!(v >= 0.0)) throw ParamError(name, "must be >= 0" + note + ", got " + show(v));
}
std::string stripSlash(std::string s) {
  while (!s.empty() && s.front() == '/') s.erase(0, 1);
  return s;
}

}  // namespace

NodeParams loadNodeParams(const ros::NodeHandle& pnh, const std::string& node_name) {
  Reader r(pnh);
  NodeParams p;
  p.vessel_input = r.text("vessel_input", p.vessel_input);
  if (p.vessel_input != "pose" && p.vessel_input != "odom" && p.vessel_input != "tf")
    throw ParamError("vessel_input", "unknown value '" + p.vessel_input + "' (accepted: pose, odom, tf)");
  p.fixed_frame = stripSlash(r.text("fixed_frame", p.fixed_frame));
  if (p.fixed_frame.empty()) throw ParamError("fixed_frame", "must not be empty");
  p.vessel_frame = stripSlash(r.text("vessel_frame", p.vessel_frame));
  if (p.vessel_input == "tf" && (p.vessel_frame.empty() || p.vessel_frame == p.fixed_frame))
    throw ParamError("vessel_frame", "must name the vessel's tf frame (not empty, not fixed_frame '" + p.fixed_frame +
                                         "') when vessel_input is tf");
  p.expected_frame = stripSlash(r.text("expected_frame", p.fixed_frame));
  if (p.expected_frame.empty()) throw ParamError("expected_frame", "must not be empty");
  p.tf_prefix = stripSlash(r.text("tf_prefix", stripSlash(node_name)));
  if (p.tf_prefix.find(' ') != std::string::npos) throw ParamError("tf_prefix", "must not contain spaces");
  p.hangoff_offset = r.vec3("hangoff_offset", p.hangoff_offset);
  p.wrench_frame = r.text("wrench_frame", p.wrench_frame);
  if (p.wrench_frame != "fixed" && p.wrench_frame != "body")
    throw ParamError("wrench_frame", "unknown value '" + p.wrench_frame + "' (accepted: fixed, body)");
  p.bottom_offset = r.vec3("bottom_offset", p.bottom_offset);
  p.bottom_frame = stripSlash(r.text("bottom_frame", p.bottom_frame));
  if (p.bottom_frame.empty()) throw ParamError("bottom_frame", "must not be empty");
  p.pose_timeout = r.number("pose_timeout", p.pose_timeout);
  positive("pose_timeout", p.pose_timeout);
  p.max_out_of_plane = r.number("max_out_of_plane", p.max_out_of_plane);
  nonNegative("max_out_of_plane", p.max_out_of_plane);
  p.max_position = r.number("max_position", p.max_position);
  positive("max_position", p.max_position);
  for (const auto& [name, offset] :
       {std::make_pair("hangoff_offset", p.hangoff_offset), std::make_pair("bottom_offset", p.bottom_offset)}) {
    const double bound = std::min(kMaxOffset, p.max_position);
    if (offset.norm() > bound)
      throw ParamError(name, "|[" + show(offset.x()) + ", " + show(offset.y()) + ", " + show(offset.z()) +
                                 "]| = " + show(offset.norm()) + " m is beyond " + show(bound) +
                                 " m: the offset is a point on the body (its lever arm turns the body's attitude "
                                 "into the point's motion); give it in metres in the body's frame");
  }
  p.max_pose_age = r.number("max_pose_age", p.max_pose_age);
  positive("max_pose_age", p.max_pose_age);
  p.max_pose_lead = r.number("max_pose_lead", p.max_pose_lead);
  nonNegative("max_pose_lead", p.max_pose_lead);
  p.clock_timeout = r.number("clock_timeout", p.clock_timeout);
  positive("clock_timeout", p.clock_timeout);
  p.tf_poll_rate = r.number("tf_poll_rate", p.tf_poll_rate);
  positive("tf_poll_rate", p.tf_poll_rate);

  const char* off = " (0 = off)";
  std::vector<std::string> rate_names;
  for (const TopicRate& t : dataTopicRates()) {
    const double def = t.default_as && p.rates.at(t.default_as) > 0.0 ? p.rates.at(t.default_as) : t.hz;
    rate_names.push_back(t.name);
    p.rates[t.name] = r.number("rates/" + rate_names.back(), def);
    nonNegative("rates/" + rate_names.back(), p.rates[t.name], off);
  }
  rate_names.push_back("diagnostics");
  p.rates["diagnostics"] = r.number("rates/diagnostics", 1.0);
  nonNegative("rates/diagnostics", p.rates["diagnostics"], off);

  p.loop_rate = r.number("loop_rate", p.loop_rate);
  positive("loop_rate", p.loop_rate);
  for (const std::string& name : rate_names)
    if (p.rates[name] > p.loop_rate)
      throw ParamError("rates/" + name,
                       "must not exceed ~loop_rate (" + show(p.loop_rate) + " Hz), got " + show(p.rates[name]));
  p.max_steps_per_cycle = r.integer("max_steps_per_cycle", p.max_steps_per_cycle);
  if (p.max_steps_per_cycle < 1)
    throw ParamError("max_steps_per_cycle", "must be >= 1, got " + std::to_string(p.max_steps_per_cycle));
  p.max_lag = r.number("max_lag", p.max_lag);
  positive("max_lag", p.max_lag);

  p.markers.line_width = r.number("markers/line_width", p.markers.line_width);
  nonNegative("markers/line_width", p.markers.line_width, " (0 = automatic)");
  p.markers.node_scale = r.number("markers/node_scale", p.markers.node_scale);
  nonNegative("markers/node_scale", p.markers.node_scale, " (0 = automatic)");
  p.markers.text_height = r.number("markers/text_height", p.markers.text_height);
  nonNegative("markers/text_height", p.markers.text_height, " (0 = automatic)");

  p.range_window = r.number("range_graph/window", p.range_window);
  positive("range_graph/window", p.range_window);

  riser_sim::ExternalMotionOptions& m = p.motion;
  m.fit_window = r.number("motion/fit_window", m.fit_window);
  m.fit_max_samples = r.integer("motion/fit_max_samples", m.fit_max_samples);
  m.default_period = r.number("motion/default_period", m.default_period);
  m.min_period = r.number("motion/min_period", m.min_period);
  m.max_period = r.number("motion/max_period", m.max_period);
  m.min_blend = r.number("motion/min_blend", m.min_blend);
  m.predict = r.boolean("motion/predict", m.predict);
  m.max_prediction = r.number("motion/max_prediction", m.max_prediction);
  m.coast_time = r.number("motion/coast_time", m.coast_time);
  m.stop_time = r.number("motion/stop_time", m.stop_time);
  m.start_blend = r.number("motion/start_blend", m.start_blend);
  m.rejoin_max_acceleration = r.number("motion/rejoin_max_acceleration", m.rejoin_max_acceleration);
  m.rejoin_max_velocity = r.number("motion/rejoin_max_velocity", m.rejoin_max_velocity);
  m.rejoin_max_angular_acceleration =
      r.number("motion/rejoin_max_angular_acceleration", m.rejoin_max_angular_acceleration);
  m.rejoin_max_angular_velocity = r.number("motion/rejoin_max_angular_velocity", m.rejoin_max_angular_velocity);
  const std::string err = m.validate();
  if (!err.empty()) {
    const auto colon = err.find(':');
    throw ParamError("motion/" + err.substr(0, colon), err.substr(colon + 2));
  }
  r.accept("scene");  // read by loadScene
  r.checkUnknown();
  return p;
}

}  // namespace riser_sim_ros
