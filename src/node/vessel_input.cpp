#include "riser_sim_ros/vessel_input.h"

#include <cmath>
#include <sstream>

namespace riser_sim_ros {

void SampleBuffer::push(const VesselSample& s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (count_ == kCapacity) {  // drop the oldest
    head_ = (head_ + 1) % kCapacity;
    --count_;
    ++overflows_;
  }
  ring_[(head_ + count_) % kCapacity] = s;
  ++count_;
  latest_ = s;
  has_latest_ = true;
}

int SampleBuffer::drain(std::array<VesselSample, kCapacity>& out) {
  std::lock_guard<std::mutex> lock(mutex_);
  const int n = count_;
  for (int i = 0; i < n; ++i) out[i] = ring_[(head_ + i) % kCapacity];
  head_ = (head_ + n) % kCapacity;
  count_ = 0;
  return n;
}

bool SampleBuffer::latest(VesselSample& s) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (has_latest_) s = latest_;
  return has_latest_;
}

void SampleBuffer::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  head_ = count_ = 0;
  has_latest_ = false;
}

namespace {
std::string stripSlash(const std::string& s) {
  size_t i = 0;
  while (i < s.size() && s[i] == '/') ++i;
  return s.substr(i);
}
std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}
}  // namespace

std::string checkPose(const std_msgs::Header& header, const geometry_msgs::Pose& msg,
                      const std::string& expected_frame, Eigen::Isometry3d& pose) {
  const std::string frame = stripSlash(header.frame_id);
  if (frame != expected_frame)
    return "header.frame_id is '" + header.frame_id + "', expected '" + expected_frame + "'";
  if (header.stamp.isZero()) return "header.stamp is zero";
  const Eigen::Vector3d p(msg.position.x, msg.position.y, msg.position.z);
  if (!p.allFinite()) return "position is not finite (NaN/Inf)";
  const Eigen::Quaterniond q(msg.orientation.w, msg.orientation.x, msg.orientation.y, msg.orientation.z);
  if (!q.coeffs().allFinite()) return "orientation is not finite (NaN/Inf)";
  const double norm = q.norm();
  if (norm < 1e-9) return "orientation is a zero quaternion (uninitialised?)";
  if (std::abs(norm - 1.0) > 0.01) return "orientation is not a unit quaternion (norm " + fmt(norm) + ")";
  pose = Eigen::Translation3d(p) * q.normalized();
  return "";
}

VesselInput::VesselInput(ros::NodeHandle& nh, const NodeParams& params, tf2_ros::Buffer& tf, SampleBuffer& out)
    : params_(params), tf_(tf), out_(out) {
  if (params.vessel_input == "pose") {
    sub_ = nh.subscribe("vessel/pose", 20, &VesselInput::onPose, this, ros::TransportHints().tcpNoDelay());
    source_ = sub_.getTopic();
  } else if (params.vessel_input == "odom") {
    sub_ = nh.subscribe("vessel/odom", 20, &VesselInput::onOdom, this, ros::TransportHints().tcpNoDelay());
    source_ = sub_.getTopic();
  } else {
    timer_ = nh.createTimer(ros::Duration(1.0 / params.tf_poll_rate), &VesselInput::onTfTimer, this);
    source_ = "tf " + params.fixed_frame + " <- " + params.vessel_frame;
  }
}

void VesselInput::onPose(const geometry_msgs::PoseStamped::ConstPtr& msg) { handle(msg->header, msg->pose); }

void VesselInput::onOdom(const nav_msgs::Odometry::ConstPtr& msg) { handle(msg->header, msg->pose.pose); }

void VesselInput::onTfTimer(const ros::TimerEvent&) {
  geometry_msgs::TransformStamped tr;
  try {
    tr = tf_.lookupTransform(params_.fixed_frame, params_.vessel_frame, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "riser_sim: waiting for tf %s <- %s: %s", params_.fixed_frame.c_str(),
                      params_.vessel_frame.c_str(), e.what());
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (tr.header.stamp == last_stamp_) return;  // polled faster than the transform is updated
  }
  geometry_msgs::Pose pose;
  pose.position.x = tr.transform.translation.x;
  pose.position.y = tr.transform.translation.y;
  pose.position.z = tr.transform.translation.z;
  pose.orientation = tr.transform.rotation;
  handle(tr.header, pose);
}

void VesselInput::reject(const std::string& why) {
  ++rejected_;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_rejection_ = why;
  }
  ROS_WARN_THROTTLE(2.0, "riser_sim: vessel pose from %s ignored: %s", source_.c_str(), why.c_str());
}

void VesselInput::handle(const std_msgs::Header& header, const geometry_msgs::Pose& msg) {
  Eigen::Isometry3d pose;
  std::string why = checkPose(header, msg, params_.vessel_input == "tf" ? params_.fixed_frame : params_.expected_frame,
                              pose);
  if (!why.empty()) return reject(why);
  if (params_.vessel_input != "tf" && params_.expected_frame != params_.fixed_frame) {
    // Poses given in another frame: bring them into fixed_frame with the latest transform.
    try {
      const auto t = tf_.lookupTransform(params_.fixed_frame, params_.expected_frame, ros::Time(0)).transform;
      const Eigen::Isometry3d world_from_expected =
          Eigen::Translation3d(t.translation.x, t.translation.y, t.translation.z) *
          Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized();
      pose = world_from_expected * pose;
    } catch (const tf2::TransformException& e) {
      return reject(std::string("no transform ") + params_.fixed_frame + " <- " + params_.expected_frame + ": " +
                    e.what());
    }
  }
  VesselSample s;
  s.stamp = header.stamp;
  s.received = ros::Time::now();
  s.hangoff = pose * params_.hangoff_offset;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!last_stamp_.isZero() && header.stamp <= last_stamp_) {
      const bool dup = header.stamp == last_stamp_;
      const std::string reason = dup ? "duplicate stamp " + fmt(header.stamp.toSec())
                                     : "out-of-order stamp " + fmt(header.stamp.toSec()) + " s, " +
                                           fmt((last_stamp_ - header.stamp).toSec()) + " s older than the last";
      last_rejection_ = reason;
      ++rejected_;
      ROS_WARN_THROTTLE(2.0, "riser_sim: vessel pose from %s ignored: %s", source_.c_str(), reason.c_str());
      return;
    }
    last_stamp_ = header.stamp;
  }
  if (std::abs(s.hangoff.y()) > params_.max_out_of_plane)
    ROS_WARN_THROTTLE(5.0,
                      "riser_sim: hang-off point is %.2f m out of the riser's x-z plane (world y; ~max_out_of_plane "
                      "%.2f m); it is projected onto the plane (y dropped)",
                      s.hangoff.y(), params_.max_out_of_plane);
  ++accepted_;
  out_.push(s);
}

std::string VesselInput::lastRejection() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_rejection_;
}

void VesselInput::restart() {
  std::lock_guard<std::mutex> lock(mutex_);
  last_stamp_ = ros::Time();
}

}  // namespace riser_sim_ros
