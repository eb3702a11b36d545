// Helpers shared by the node's rostests: waiting on conditions (no fixed sleeps), a scripted vessel
// pose publisher, recorders that keep the latest message and count arrivals, and NaN checks.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/LineState.h"
#include "riser_sim/Tension.h"

namespace riser_sim_test {

// Polls cond every 5 ms of wall time until it holds or timeout [s of wall time] passes.
inline bool waitFor(const std::function<bool()>& cond, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (cond()) return true;
    ros::WallDuration(0.005).sleep();
  }
  return cond();
}

// Waits until `seconds` of ROS time have passed (a window to count messages in).
inline bool waitRosTime(double seconds, double timeout) {
  const ros::Time end = ros::Time::now() + ros::Duration(seconds);
  return waitFor([&] { return ros::Time::now() >= end; }, timeout);
}

// Waits until every frame can be transformed to `world` (latest data), for up to timeout [s of wall time].
inline bool waitForFrames(const tf2_ros::Buffer& buffer, const std::vector<std::string>& frames, double timeout) {
  return waitFor(
      [&] {
        for (const std::string& f : frames)
          if (!buffer.canTransform("world", f, ros::Time(0))) return false;
        return true;
      },
      timeout);
}

// Keeps every message of type M (with its ROS receipt time) on a topic.
template <class M>
class Recorder {
 public:
  Recorder(ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe<M>(topic, 100, [this](const typename M::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      msgs_.push_back(*m);
      times_.push_back(ros::Time::now());
    });
  }
  size_t count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return msgs_.size();
  }
  M last() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return msgs_.back();
  }
  std::vector<M> all() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return msgs_;
  }
  // Messages received in [from, to) of ROS time.
  size_t countBetween(const ros::Time& from, const ros::Time& to) const {
    std::lock_guard<std::mutex> lock(mutex_);
    size_t n = 0;
    for (const auto& t : times_) n += (t >= from && t < to);
    return n;
  }
  bool waitCount(size_t n, double timeout) const {
    return waitFor([&] { return count() >= n; }, timeout);
  }

 private:
  ros::Subscriber sub_;
  mutable std::mutex mutex_;
  std::vector<M> msgs_;
  std::vector<ros::Time> times_;
};

// Publishes vessel/pose (PoseStamped) at `rate` Hz of ROS time: position f(t) with t the ROS time in
// seconds since start(), identity orientation.
class PosePublisher {
 public:
  using Path = std::function<void(double t, geometry_msgs::Pose& pose)>;
  PosePublisher(ros::NodeHandle& nh, const std::string& topic, double rate, Path path,
                const std::string& frame = "world")
      : pub_(nh.advertise<geometry_msgs::PoseStamped>(topic, 10)), path_(std::move(path)), frame_(frame) {
    timer_ = nh.createTimer(
        ros::Duration(1.0 / rate), [this](const ros::TimerEvent&) { send(); }, false, false);
  }
  void start() {
    t0_ = ros::Time::now();
    timer_.start();
  }
  void stop() { timer_.stop(); }
  size_t subscribers() const { return pub_.getNumSubscribers(); }
  static double timeOf(const ros::Time& t0, const ros::Time& stamp) { return (stamp - t0).toSec(); }
  const ros::Time& startTime() const { return t0_; }
  // Publishes one arbitrary message now (for malformed input).
  void publishRaw(const geometry_msgs::PoseStamped& m) { pub_.publish(m); }

 private:
  void send() {
    geometry_msgs::PoseStamped m;
    m.header.stamp = ros::Time::now();
    m.header.frame_id = frame_;
    m.pose.orientation.w = 1.0;
    path_((m.header.stamp - t0_).toSec(), m.pose);
    pub_.publish(m);
  }
  ros::Publisher pub_;
  ros::Timer timer_;
  Path path_;
  std::string frame_;
  ros::Time t0_;
};

inline bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
inline bool finite(const geometry_msgs::Point& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
inline bool finite(const riser_sim::Tension& m) {
  return finite(m.axial_force) && finite(m.arc_length) && std::isfinite(m.top) && std::isfinite(m.bottom) &&
         std::isfinite(m.max);
}
inline bool finite(const riser_sim::LineState& m) {
  for (const auto& p : m.points)
    if (!finite(p)) return false;
  return finite(m.angles) && finite(m.elongations) && finite(m.bending_moments);
}
inline bool finite(const geometry_msgs::WrenchStamped& m) {
  const auto& f = m.wrench.force;
  const auto& t = m.wrench.torque;
  return std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z) && std::isfinite(t.x) && std::isfinite(t.y) &&
         std::isfinite(t.z);
}
inline bool finite(const visualization_msgs::MarkerArray& m) {
  for (const auto& mk : m.markers) {
    for (const auto& p : mk.points)
      if (!finite(p)) return false;
    if (!finite(mk.pose.position)) return false;
    if (mk.text.find("nan") != std::string::npos || mk.text.find("inf") != std::string::npos) return false;
  }
  return true;
}

inline bool finite(const tf2_msgs::TFMessage& m) {
  for (const auto& t : m.transforms) {
    const auto& p = t.transform.translation;
    const auto& q = t.transform.rotation;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(q.x) ||
        !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
      return false;
  }
  return true;
}

// Value of `key` in the first status whose name starts with `name_prefix` ("" when absent).
inline std::string diagValue(const diagnostic_msgs::DiagnosticArray& a, const std::string& name_prefix,
                             const std::string& key) {
  for (const auto& s : a.status)
    if (s.name.rfind(name_prefix, 0) == 0)
      for (const auto& kv : s.values)
        if (kv.key == key) return kv.value;
  return "";
}

}  // namespace riser_sim_test
