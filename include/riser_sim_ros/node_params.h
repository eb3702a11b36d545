// riser_sim_node's own private parameters (everything outside ~scene), read and validated once.
// Every error names the parameter: "~rates/tension: must be >= 0 (0 = off), got -1".
#pragma once
#include <map>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <ros/node_handle.h>

#include "riser_sim/motion/external_motion.h"

namespace riser_sim_ros {

class ParamError : public std::runtime_error {
 public:
  ParamError(const std::string& name, const std::string& what) : std::runtime_error("~" + name + ": " + what) {}
};

struct MarkerParams {
  double line_width = 0.0;   // [m], 0 = L / 150
  double node_scale = 0.0;   // sphere diameter [m], 0 = 2.5 line widths
  double text_height = 0.0;  // [m], 0 = L / 25
};

// The largest hang-off or bottom offset: a point on the vessel (the ROV) [m]. Its lever arm turns the body's
// attitude into the point's motion, so an offset far beyond any hull makes every roll a huge displacement.
constexpr double kMaxOffset = 1000.0;

struct NodeParams {
  std::string vessel_input = "pose";  // pose | odom | tf
  std::string fixed_frame = "world";
  std::string vessel_frame = "vessel";  // tf input: child frame looked up in fixed_frame
  std::string expected_frame;           // header.frame_id of pose/odom input; default fixed_frame
  std::string tf_prefix;                // default: node name without the leading slash
  Eigen::Vector3d hangoff_offset =
      Eigen::Vector3d::Zero();         // hang-off point in the vessel frame [m], |.| <= kMaxOffset
  std::string wrench_frame = "fixed";  // 3D wrenches: fixed (fixed_frame) | body (vessel_frame, bottom_frame)
  // A driven bottom (3D, bottom.motion.type external): ~bottom_pose's attachment point in the ROV frame [m]
  // and the frame_id of a body-frame ~bottom_wrench.
  Eigen::Vector3d bottom_offset = Eigen::Vector3d::Zero();
  std::string bottom_frame = "rov";
  double pose_timeout = 1.0;      // no valid pose for this long: warn and hold [s]
  double max_out_of_plane = 1.0;  // warn when the hang-off's world y exceeds this [m]
  double max_position = 1e7;      // poses (and hang-off / bottom points) with a coordinate beyond this are ignored [m]
  double max_pose_age = 1.0;      // poses stamped more than this before ROS time are ignored [s]
  double max_pose_lead = 0.5;     // poses stamped more than this after ROS time are ignored [s]
  double clock_timeout = 1.0;     // ROS time still for this long (wall time): paused, said on /diagnostics [s]
  double tf_poll_rate = 50.0;     // tf input: lookup rate [Hz]
  // ~rates/<name> [Hz], 0 = off: the data topics of line_topics.h (dataTopicRates()) and "diagnostics".
  std::map<std::string, double> rates;
  double loop_rate = 500.0;       // integration loop wake-ups per wall second [Hz]
  int max_steps_per_cycle = 500;  // cap of solver steps per wake-up
  double max_lag = 0.5;           // backlog (ROS time not yet simulated) dropped beyond this [s]
  MarkerParams markers;
  double range_window = 60.0;               // ~range_graph/window: the rolling window of ~range_graph [s]
  riser_sim::ExternalMotionOptions motion;  // ~motion/*: smoothing of the vessel samples
};

// Reads and validates the private parameters of `pnh`; `node_name` gives the default tf_prefix.
// Throws ParamError.
NodeParams loadNodeParams(const ros::NodeHandle& pnh, const std::string& node_name);

}  // namespace riser_sim_ros
