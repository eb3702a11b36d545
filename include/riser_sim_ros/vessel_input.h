// Vessel poses in: geometry_msgs/PoseStamped (vessel/pose), nav_msgs/Odometry (vessel/odom), or a tf
// lookup of vessel_frame in fixed_frame. Each pose is checked, turned into the world position of the
// hang-off point (vessel pose * hangoff_offset) and copied into a small mutex-protected buffer that the
// integration thread drains; callbacks never wait for the integration. The same class reads the second
// end's feed of a driven bottom (~bottom_pose, PoseStamped only, offset bottom_offset).
#pragma once
#include <array>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

#include <Eigen/Geometry>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <tf2_ros/buffer.h>

#include "riser_sim_ros/node_params.h"

namespace riser_sim_ros {

struct VesselSample {
  ros::Time stamp;                                    // header stamp of the pose
  ros::Time received;                                 // ROS time when it arrived
  Eigen::Vector3d hangoff = Eigen::Vector3d::Zero();  // hang-off (or bottom attachment) point in fixed_frame [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // vessel (or ROV) frame -> fixed_frame
};

class SampleBuffer {
 public:
  static constexpr int kCapacity = 64;
  // Copies s in; when full the oldest sample is dropped (counted).
  void push(const VesselSample& s);
  // Moves every buffered sample, oldest first, into out; returns how many.
  int drain(std::array<VesselSample, kCapacity>& out);
  // Latest sample pushed since clear() (false when none).
  bool latest(VesselSample& s) const;
  void clear();
  long overflows() const { return overflows_; }

 private:
  mutable std::mutex mutex_;
  std::array<VesselSample, kCapacity> ring_;
  int head_ = 0, count_ = 0;
  VesselSample latest_;
  bool has_latest_ = false;
  long overflows_ = 0;
};

// Checks one pose: frame_id (leading '/' ignored) equals expected_frame, stamp non-zero, all values
// finite, |position| components at most max_position [m], quaternion of norm within 1 % of 1
// (normalised then). Fills `pose`; returns an empty string when valid, else the reason naming the field.
std::string checkPose(const std_msgs::Header& header, const geometry_msgs::Pose& msg, const std::string& expected_frame,
                      Eigen::Isometry3d& pose, double max_position = 1e7);

// Checks a stamp against ROS time `now` and the last accepted stamp `last` (zero: none): not more than
// max_age [s] old, not more than max_lead [s] ahead, newer than `last`. Empty when valid, else the reason.
std::string checkStamp(const ros::Time& stamp, const ros::Time& now, const ros::Time& last, double max_age,
                       double max_lead);

// Rate limit of one warning: at most one per `period` seconds of wall time (steady clock, so a stalled
// or jumping ROS clock does not change it); the calls in between are counted.
class WarnThrottle {
 public:
  explicit WarnThrottle(double period) : period_(period) {}
  // True when a warning may go out now; `suppressed` is then the number of calls held back since the last.
  bool allow(long& suppressed) { return allow(std::chrono::steady_clock::now(), suppressed); }
  bool allow(std::chrono::steady_clock::time_point now, long& suppressed);

 private:
  double period_;
  std::mutex mutex_;
  bool started_ = false;
  std::chrono::steady_clock::time_point last_;
  long suppressed_ = 0;
};

// Paper coordinates of a world point: paper x = world x, paper y = world z; world y is dropped
// (orthogonal projection onto the riser's x-z plane).
inline Eigen::Vector2d toPaper(const Eigen::Vector3d& w) { return Eigen::Vector2d(w.x(), w.z()); }

class VesselInput {
 public:
  // kVessel: the top's feed (vessel_input, hangoff_offset). kBottom: a driven bottom's, bottom_pose on nh
  // (pass the private handle), bottom_offset; PoseStamped only.
  enum class Feed { kVessel, kBottom };
  // `name` (the riser's) starts each log line.
  // planar: the riser lives in the x-z plane (warn when the hang-off leaves it); false for a 3D scene.
  VesselInput(ros::NodeHandle& nh, const NodeParams& params, tf2_ros::Buffer& tf, SampleBuffer& out,
              const std::string& name, bool planar = true, Feed feed = Feed::kVessel);
  // Topic (pose/odom) or "tf <fixed> <- <vessel>" the input listens to, for messages.
  const std::string& source() const { return source_; }
  long accepted() const { return accepted_; }
  long rejected() const { return rejected_; }
  std::string lastRejection() const;
  // Forgets the last stamp (after ROS time jumped backwards).
  void restart();
  // Counts a pose refused elsewhere (a bad tf of the vessel frame) as rejected, with the reason;
  // warns at most once per 2 s.
  void reject(const std::string& why);

 private:
  void onPose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg);
  void onTfTimer(const ros::TimerEvent&);
  void handle(const std_msgs::Header& header, const geometry_msgs::Pose& pose);

  const NodeParams& params_;
  std::string name_;
  std::string kind_;        // pose | odom | tf
  std::string what_;        // "vessel" | "bottom", in log lines
  Eigen::Vector3d offset_;  // hangoff_offset | bottom_offset
  tf2_ros::Buffer& tf_;
  SampleBuffer& out_;
  ros::Subscriber sub_;
  ros::Timer timer_;
  std::string source_;
  mutable std::mutex mutex_;  // callbacks may run on several spinner threads
  ros::Time last_stamp_;
  std::string last_rejection_;
  std::atomic<long> accepted_{0}, rejected_{0};
  bool planar_;
  WarnThrottle reject_warn_{2.0}, tf_warn_{5.0}, plane_warn_{5.0};
};

}  // namespace riser_sim_ros
