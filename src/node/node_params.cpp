#include "riser_sim_ros/node_params.h"

#include <cmath>
#include <sstream>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

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

class Reader {
 public:
  explicit Reader(const ros::NodeHandle& pnh) : pnh_(pnh) {}

  bool has(const std::string& name) const { return pnh_.hasParam(name); }

  double number(const std::string& name, double def) const {
    XmlRpcValue v;
    if (!pnh_.getParam(name, v)) return def;
    double d;
    if (v.getType() == XmlRpcValue::TypeDouble) d = static_cast<double>(v);
    else if (v.getType() == XmlRpcValue::TypeInt) d = static_cast<int>(v);
    else throw ParamError(name, "expected a number, got " + describe(v));
    if (!std::isfinite(d)) throw ParamError(name, "must be finite, got " + show(d));
    return d;
  }
  int integer(const std::string& name, int def) const {
    XmlRpcValue v;
    if (!pnh_.getParam(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeInt) throw ParamError(name, "expected an integer, got " + describe(v));
    return static_cast<int>(v);
  }
  bool boolean(const std::string& name, bool def) const {
    XmlRpcValue v;
    if (!pnh_.getParam(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeBoolean) throw ParamError(name, "expected true or false, got " + describe(v));
    return static_cast<bool>(v);
  }
  std::string text(const std::string& name, const std::string& def) const {
    XmlRpcValue v;
    if (!pnh_.getParam(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeString) throw ParamError(name, "expected a string, got " + describe(v));
    return static_cast<std::string>(v);
  }
  Eigen::Vector3d vec3(const std::string& name, const Eigen::Vector3d& def) const {
    XmlRpcValue v;
    if (!pnh_.getParam(name, v)) return def;
    if (v.getType() != XmlRpcValue::TypeArray || v.size() != 3)
      throw ParamError(name, "expected [x, y, z], got " + describe(v));
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
      XmlRpcValue& e = v[i];
      if (e.getType() == XmlRpcValue::TypeDouble) out[i] = static_cast<double>(e);
      else if (e.getType() == XmlRpcValue::TypeInt) out[i] = static_cast<int>(e);
      else throw ParamError(name + "[" + std::to_string(i) + "]", "expected a number, got " + describe(e));
      if (!std::isfinite(out[i])) throw ParamError(name + "[" + std::to_string(i) + "]", "must be finite");
    }
    return out;
  }

 private:
  const ros::NodeHandle& pnh_;
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
  const Reader r(pnh);
  NodeParams p;
  p.vessel_input = r.text("vessel_input", p.vessel_input);
  if (p.vessel_input != "pose" && p.vessel_input != "odom" && p.vessel_input != "tf")
    throw ParamError("vessel_input", "unknown value '" + p.vessel_input + "' (accepted: pose, odom, tf)");
  p.fixed_frame = stripSlash(r.text("fixed_frame", p.fixed_frame));
  if (p.fixed_frame.empty()) throw ParamError("fixed_frame", "must not be empty");
  p.vessel_frame = stripSlash(r.text("vessel_frame", p.vessel_frame));
  if (p.vessel_input == "tf" && (p.vessel_frame.empty() || p.vessel_frame == p.fixed_frame))
    throw ParamError("vessel_frame", "must name the vessel's tf frame (not empty, not fixed_frame '" +
                                         p.fixed_frame + "') when vessel_input is tf");
  p.expected_frame = stripSlash(r.text("expected_frame", p.fixed_frame));
  if (p.expected_frame.empty()) throw ParamError("expected_frame", "must not be empty");
  p.tf_prefix = stripSlash(r.text("tf_prefix", stripSlash(node_name)));
  if (p.tf_prefix.find(' ') != std::string::npos) throw ParamError("tf_prefix", "must not contain spaces");
  p.hangoff_offset = r.vec3("hangoff_offset", p.hangoff_offset);
  p.pose_timeout = r.number("pose_timeout", p.pose_timeout);
  positive("pose_timeout", p.pose_timeout);
  p.max_out_of_plane = r.number("max_out_of_plane", p.max_out_of_plane);
  nonNegative("max_out_of_plane", p.max_out_of_plane);
  p.max_position = r.number("max_position", p.max_position);
  positive("max_position", p.max_position);
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
      throw ParamError("rates/" + name, "must not exceed ~loop_rate (" + show(p.loop_rate) + " Hz), got " +
                                            show(p.rates[name]));
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
  const std::string err = m.validate();
  if (!err.empty()) {
    const auto colon = err.find(':');
    throw ParamError("motion/" + err.substr(0, colon), err.substr(colon + 2));
  }
  return p;
}

}  // namespace riser_sim_ros
