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

std::string checkPose(const std_msgs::Header& header, const geometry_msgs::Pose& msg, const std::string& expected_frame,
                      Eigen::Isometry3d& pose, double max_position) {
  const std::string frame = stripSlash(header.frame_id);
  if (frame != expected_frame) return "header.frame_id is '" + header.frame_id + "', expected '" + expected_frame + "'";
  if (header.stamp.isZero()) return "header.stamp is zero";
  const Eigen::Vector3d p(msg.position.x, msg.position.y, msg.position.z);
  if (!p.allFinite()) return "position is not finite (NaN/Inf)";
  if (p.lpNorm<Eigen::Infinity>() > max_position)
    return "position (" + fmt(p.x()) + ", " + fmt(p.y()) + ", " + fmt(p.z()) + ") m is beyond ~max_position " +
           fmt(max_position) + " m";
  const Eigen::Quaterniond q(msg.orientation.w, msg.orientation.x, msg.orientation.y, msg.orientation.z);
  if (!q.coeffs().allFinite()) return "orientation is not finite (NaN/Inf)";
  const double norm = q.norm();
  if (norm < 1e-9) return "orientation is a zero quaternion (uninitialised?)";
  if (std::abs(norm - 1.0) > 0.01) return "orientation is not a unit quaternion (norm " + fmt(norm) + ")";
  pose = Eigen::Translation3d(p) * q.normalized();
  return "";
}

std::string checkStamp(const ros::Time& stamp, const ros::Time& now, const ros::Time& last, double max_age,
                       double max_lead) {
  const double age = (now - stamp).toSec();
  if (age > max_age)
    return "header.stamp " + fmt(stamp.toSec()) + " is " + fmt(age) + " s older than ROS time (~max_pose_age " +
           fmt(max_age) + " s; clock skew between machines?)";
  if (-age > max_lead)
    return "header.stamp " + fmt(stamp.toSec()) + " is " + fmt(-age) + " s ahead of ROS time (~max_pose_lead " +
           fmt(max_lead) + " s; clock skew between machines?)";
  if (!last.isZero() && stamp <= last)
    return stamp == last ? "header.stamp " + fmt(stamp.toSec()) + " repeats the last one"
                         : "header.stamp " + fmt(stamp.toSec()) + " is out of order, " + fmt((last - stamp).toSec()) +
                               " s older than the last accepted";
  return "";
}

bool WarnThrottle::allow(std::chrono::steady_clock::time_point now, long& suppressed) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (started_ && std::chrono::duration<double>(now - last_).count() < period_) {
    ++suppressed_;
    return false;
  }
  started_ = true;
  last_ = now;
  suppressed = suppressed_;
  suppressed_ = 0;
  return true;
}

VesselInput::VesselInput(ros::NodeHandle& nh, const NodeParams& params, tf2_ros::Buffer& tf, SampleBuffer& out,
                         const std::string& name, bool planar, Feed feed)
    : params_(params),
      name_(name),
      kind_(feed == Feed::kBottom ? "pose" : params.vessel_input),
      what_(feed == Feed::kBottom ? "bottom" : "vessel"),
      offset_(feed == Feed::kBottom ? params.bottom_offset : params.hangoff_offset),
      tf_(tf),
      out_(out),
      planar_(planar && feed == Feed::kVessel) {
  if (feed == Feed::kBottom) {
    sub_ = nh.subscribe("bottom_pose", 20, &VesselInput::onPose, this, ros::TransportHints().tcpNoDelay());
    source_ = sub_.getTopic();
  } else if (kind_ == "pose") {
    sub_ = nh.subscribe("vessel/pose", 20, &VesselInput::onPose, this, ros::TransportHints().tcpNoDelay());
    source_ = sub_.getTopic();
  } else if (kind_ == "odom") {
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
    long held = 0;
    if (tf_warn_.allow(held))
      ROS_WARN("%s: waiting for tf %s <- %s: %s", name_.c_str(), params_.fixed_frame.c_str(),
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
  long suppressed = 0;
  if (reject_warn_.allow(suppressed)) {
    if (suppressed > 0)
      ROS_WARN(
          "%s: %s pose from %s ignored: %s (and %ld more ignored since the last warning; count "
          "and last reason on /diagnostics)",
          name_.c_str(), what_.c_str(), source_.c_str(), why.c_str(), suppressed);
    else
      ROS_WARN("%s: %s pose from %s ignored: %s", name_.c_str(), what_.c_str(), source_.c_str(), why.c_str());
  }
}

void VesselInput::handle(const std_msgs::Header& header, const geometry_msgs::Pose& msg) {
  Eigen::Isometry3d pose;
  std::string why =
      checkPose(header, msg, kind_ == "tf" ? params_.fixed_frame : params_.expected_frame, pose, params_.max_position);
  if (!why.empty()) return reject(why);
  if (kind_ != "tf" && params_.expected_frame != params_.fixed_frame) {
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
  s.hangoff = pose * offset_;
  s.orientation = Eigen::Quaterniond(pose.rotation());
  if (!s.hangoff.allFinite()) return reject("attachment point is not finite (pose * " + what_ + " offset)");
  if (s.hangoff.lpNorm<Eigen::Infinity>() > params_.max_position)
    return reject("attachment point (" + fmt(s.hangoff.x()) + ", " + fmt(s.hangoff.y()) + ", " + fmt(s.hangoff.z()) +
                  ") m (pose * " + what_ + " offset) is beyond ~max_position " + fmt(params_.max_position) + " m");
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // ROS time went back before the last accepted stamp (a bag loop): that stamp belongs to the old
    // timeline. The integration loop resets the simulation when it sees the jump.
    if (!last_stamp_.isZero() && s.received + ros::Duration(params_.max_pose_lead) < last_stamp_)
      last_stamp_ = ros::Time();
    why = checkStamp(header.stamp, s.received, last_stamp_, params_.max_pose_age, params_.max_pose_lead);
    if (why.empty()) last_stamp_ = header.stamp;
  }
  if (!why.empty()) return reject(why);
  long held = 0;
  if (planar_ && std::abs(s.hangoff.y()) > params_.max_out_of_plane && plane_warn_.allow(held))
    ROS_WARN(
        "%s: hang-off point is %.2f m out of the riser's x-z plane (world y; ~max_out_of_plane %.2f m); it is "
        "projected onto the plane (y dropped)",
        name_.c_str(), s.hangoff.y(), params_.max_out_of_plane);
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
