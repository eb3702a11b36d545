// /tf and /tf_static into the node's tf2 buffer, each transform checked first. A transform tf2 would
// refuse (NaN, a quaternion off unit norm, an empty or self-referencing frame id) never reaches the
// buffer, so tf2 does not print an error per message (a NaN vessel at 50 Hz was 100 stderr lines a
// second). Refused transforms of the watched frame (the vessel's, for vessel_input: tf) go to a
// callback that counts them as rejected poses; the rest are warned about at most once per 5 s.
#pragma once
#include <functional>
#include <mutex>
#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

// Empty when tf2 would take the transform, else the reason ("translation is not finite (NaN/Inf)",
// "rotation is a zero quaternion (uninitialised?)", ...). Stricter than tf2 on Inf.
std::string checkTransform(const geometry_msgs::TransformStamped& t);

class CheckedTfListener {
 public:
  using Reject = std::function<void(const std::string& why)>;
  // `watched`: child frame whose refused transforms go to on_reject ("" = none); `name` starts log lines.
  CheckedTfListener(ros::NodeHandle& nh, tf2_ros::Buffer& buffer, std::string watched, Reject on_reject,
                    std::string name);

 private:
  void onMessage(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static);

  tf2_ros::Buffer& buffer_;
  std::string watched_, name_;
  Reject on_reject_;
  ros::Subscriber tf_sub_, static_sub_;
  std::mutex mutex_;
  ros::Time last_update_;
  WarnThrottle other_warn_{5.0};
};

}  // namespace riser_sim_ros
