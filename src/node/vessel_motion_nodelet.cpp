// riser_sim/VesselMotionNodelet: a vessel surging (and heaving) as in the paper, for risers in the same
// nodelet manager (launch/many_risers.launch, bench/many_risers.py). Publishes vessel/pose
// (geometry_msgs/PoseStamped, frame ~frame_id) at ~rate Hz of ROS time as shared pointers, so riser
// nodelets in the same manager receive it without serialisation:
//   x = origin_x + e(t) surge/amplitude cos(2 pi t / surge/period)     (paper: x_0 = 10 cos(2 pi t / 27))
//   z = origin_z + e(t) heave/amplitude cos(2 pi t / heave/period)
// e(t) rises 0 -> 1 over ~fade_in along u^3 (10 - 15 u + 6 u^2) (as scripts/vessel_motion.py).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <boost/make_shared.hpp>
#include <geometry_msgs/PoseStamped.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>

#include "riser_sim_ros/node_params.h"

namespace riser_sim_ros {

class VesselMotionNodelet : public nodelet::Nodelet {
 private:
  double get(const std::string& key, double def, bool positive) {
    double v = def;
    if (getPrivateNodeHandle().hasParam(key) && !getPrivateNodeHandle().getParam(key, v))
      throw ParamError(key, "expected a number");
    if (!std::isfinite(v) || (positive ? v <= 0.0 : v < 0.0))
      throw ParamError(key, std::string(positive ? "must be > 0" : "must be >= 0") + ", got " + std::to_string(v));
    return v;
  }

  void onInit() override {
    try {
      rate_ = get("rate", 100.0, true);
      surge_a_ = get("surge/amplitude", 10.0, false);
      surge_T_ = get("surge/period", 27.0, true);
      heave_a_ = get("heave/amplitude", 0.0, false);
      heave_T_ = get("heave/period", 10.0, true);
      fade_in_ = get("fade_in", 5.0, false);
      getPrivateNodeHandle().param<std::string>("frame_id", frame_id_, "world");
      std::vector<double> origin{0.0, 0.0, 0.0};
      if (getPrivateNodeHandle().hasParam("origin") &&
          (!getPrivateNodeHandle().getParam("origin", origin) || origin.size() != 3))
        throw ParamError("origin", "expected [x, y, z]");
      origin_x_ = origin[0], origin_y_ = origin[1], origin_z_ = origin[2];
    } catch (const std::exception& e) {
      NODELET_FATAL("%s: %s", getName().c_str(), e.what());
      throw;
    }
    pub_ = getNodeHandle().advertise<geometry_msgs::PoseStamped>("vessel/pose", 10);
    timer_ = getNodeHandle().createTimer(ros::Duration(1.0 / rate_), &VesselMotionNodelet::tick, this);
    NODELET_INFO("%s: %s at %g Hz: surge %g m / %g s, heave %g m / %g s, fade-in %g s", getName().c_str(),
                 pub_.getTopic().c_str(), rate_, surge_a_, surge_T_, heave_a_, heave_T_, fade_in_);
  }

  void tick(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    if (now.isZero()) return;  // /use_sim_time without /clock yet
    if (t0_.isZero() || now < t0_) t0_ = now;
    const double t = (now - t0_).toSec();
    const double u = fade_in_ > 0.0 ? std::min(t / fade_in_, 1.0) : 1.0;
    const double e = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
    auto msg = boost::make_shared<geometry_msgs::PoseStamped>();  // handed over, never touched again
    msg->header.stamp = now;
    msg->header.frame_id = frame_id_;
    msg->pose.position.x = origin_x_ + e * surge_a_ * std::cos(2.0 * M_PI * t / surge_T_);
    msg->pose.position.y = origin_y_;
    msg->pose.position.z = origin_z_ + e * heave_a_ * std::cos(2.0 * M_PI * t / heave_T_);
    msg->pose.orientation.w = 1.0;
    pub_.publish(msg);
  }

  double rate_ = 100.0, surge_a_ = 10.0, surge_T_ = 27.0, heave_a_ = 0.0, heave_T_ = 10.0, fade_in_ = 5.0;
  double origin_x_ = 0.0, origin_y_ = 0.0, origin_z_ = 0.0;
  std::string frame_id_;
  ros::Publisher pub_;
  ros::Timer timer_;
  ros::Time t0_;
};

}  // namespace riser_sim_ros

PLUGINLIB_EXPORT_CLASS(riser_sim_ros::VesselMotionNodelet, nodelet::Nodelet)
