#include "riser_sim_ros/tf_listener.h"

#include <cmath>
#include <sstream>

namespace riser_sim_ros {

namespace {
std::string stripSlash(const std::string& s) {
  size_t i = 0;
  while (i < s.size() && s[i] == '/') ++i;
  return s.substr(i);
}
}  // namespace

std::string checkTransform(const geometry_msgs::TransformStamped& t) {
  const std::string parent = stripSlash(t.header.frame_id), child = stripSlash(t.child_frame_id);
  if (child.empty()) return "child_frame_id is empty";
  if (parent.empty()) return "header.frame_id is empty";
  if (parent == child) return "header.frame_id and child_frame_id are both '" + child + "'";
  const auto& p = t.transform.translation;
  const auto& q = t.transform.rotation;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "translation is not finite (NaN/Inf)";
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
    return "rotation is not finite (NaN/Inf)";
  const double n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (n2 < 1e-18) return "rotation is a zero quaternion (uninitialised?)";
  if (!(std::abs(n2 - 1.0) < 10e-6)) {  // tf2's own limit (BufferCore::setTransform)
    std::ostringstream os;
    os << "rotation is not a unit quaternion (norm " << std::sqrt(n2) << ")";
    return os.str();
  }
  return "";
}

CheckedTfListener::CheckedTfListener(ros::NodeHandle& nh, tf2_ros::Buffer& buffer, std::string watched,
                                     Reject on_reject, std::string name)
    : buffer_(buffer), watched_(stripSlash(watched)), name_(std::move(name)), on_reject_(std::move(on_reject)) {
  // As tf2_ros::TransformListener: queue 100; /tf_static latched by its publishers.
  tf_sub_ = nh.subscribe<tf2_msgs::TFMessage>(
      "/tf", 100, [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onMessage(e, false); });
  static_sub_ = nh.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", 100, [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onMessage(e, true); });
}

void CheckedTfListener::onMessage(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static) {
  {
    // As tf2_ros::TransformListener: ROS time going back (a looping bag) empties the buffer.
    const ros::Time now = ros::Time::now();
    std::lock_guard<std::mutex> lock(mutex_);
    if (now < last_update_) {
      ROS_WARN("%s: ROS time jumped back: tf buffer cleared", name_.c_str());
      buffer_.clear();
    }
    last_update_ = now;
  }
  const std::string authority = event.getPublisherName();
  for (const geometry_msgs::TransformStamped& t : event.getConstMessage()->transforms) {
    const std::string why = checkTransform(t);
    if (why.empty()) {
      try {
        buffer_.setTransform(t, authority, is_static);
      } catch (const tf2::TransformException& e) {
        ROS_ERROR_THROTTLE(5.0, "%s: tf %s -> %s from %s not stored: %s", name_.c_str(), t.header.frame_id.c_str(),
                           t.child_frame_id.c_str(), authority.c_str(), e.what());
      }
      continue;
    }
    const std::string what = "tf " + t.header.frame_id + " -> " + t.child_frame_id + " from " + authority + ": " + why;
    if (!watched_.empty() && stripSlash(t.child_frame_id) == watched_) {
      on_reject_(what);
      continue;
    }
    long held = 0;
    if (other_warn_.allow(held))
      ROS_WARN("%s: %s; ignored (%ld more such transforms ignored since the last warning)", name_.c_str(), what.c_str(),
               held);
  }
}

}  // namespace riser_sim_ros
