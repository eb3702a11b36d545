// riser_sim_node: the riser simulated in real time (ROS time), driven by the vessel's pose.
// See docs/ros_interface.md for topics, frames, parameters and services.
//
// Composition: VesselInput (poses in -> SampleBuffer), RosClockWatch + LoopPacer (ROS time, wall
// pacing), the run (NodeRun: the core's LineRun over either engine, fed the poses, and its messages),
// LineTopics (the data topics, each at its rate),
// NodeDiagnostics (/diagnostics), ResetHandshake (~reset) and ModesServer (~modes).
//
// Threads: ROS callbacks (vessel input, ~reset, tf listener) only copy samples into a SampleBuffer; they
// run on spin()'s AsyncSpinner (the node) or on a nodelet manager's worker threads (RiserSimNodelet).
// The integration loop runs on the thread that calls run() (spin() calls it): it drains
// the buffer, steps the simulator by the number of dt that elapsed in ROS time (capped), and publishes
// whatever is due. Nothing in the stepping loop allocates; messages are sized once. ~modes has its own
// callback queue and thread: it works on a copy of the static state (never the running simulator).
#pragma once
#include <array>
#include <atomic>
#include <memory>
#include <string>

#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>

#include "riser_sim/scene/scene.h"
#include "riser_sim_ros/line_topics.h"
#include "riser_sim_ros/modes_service.h"
#include "riser_sim_ros/node_diagnostics.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/node_run.h"
#include "riser_sim_ros/reset_handshake.h"
#include "riser_sim_ros/ros_clock.h"
#include "riser_sim_ros/scene_param.h"
#include "riser_sim_ros/tf_listener.h"
#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

class RiserSimNode {
 public:
  // Throws ParamError for a bad parameter or scene. The riser's name (diagnostics, log lines, default
  // tf_prefix) is pnh's namespace: the node's name, or a nodelet's name inside its manager.
  RiserSimNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  // Runs the integration loop on the calling thread until stop() or ROS shutdown. Whoever owns nh's and
  // pnh's callback queues must serve them (spin(): an AsyncSpinner; a nodelet: its manager's threads).
  void run();
  // Makes run() return after its current cycle; callable from any thread.
  void stop() { stop_ = true; }
  // The standalone node: run() with an AsyncSpinner (2 threads) serving the global callback queue.
  void spin();
  const std::string& name() const { return name_; }

 private:
  void cycle();
  void onClockJump(const ros::Time& now);
  bool start(const VesselSample& s, const VesselSample* bottom, const ros::Time& now, std::string& message);
  void tryStart(int n, int nb, const ros::Time& now);
  void startFailed(const std::string& message);  // logs a failed start (once, then throttled with a count)
  void integrate(const ros::Time& now);
  void publish();
  void serveReset(const ros::Time& now);
  void fail(const std::string& why);
  bool onReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onRangeReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  double simTime(const ros::Time& t) const { return (t - origin_).toSec() - dropped_; }
  bool spatial() const { return scene_.space == riser_sim::SpaceKind::kSpatial; }
  // A 3D pinned bottom with bottom.motion.type external: driven from ~bottom_pose.
  bool drivenBottom() const {
    return spatial() && scene_.bottom == riser_sim::BottomBoundary::kPinned &&
           scene_.bottom_motion.type == riser_sim::MotionKind::kExternal;
  }

  ros::NodeHandle nh_, pnh_;
  NodeParams params_;
  riser_sim::Scene scene_;
  std::string name_;
  tf2_ros::Buffer tf_buffer_;
  SampleBuffer samples_;
  std::unique_ptr<VesselInput> input_;
  SampleBuffer bottom_samples_;
  std::unique_ptr<VesselInput> bottom_input_;       // a driven bottom only
  std::unique_ptr<CheckedTfListener> tf_listener_;  // after input_: its callbacks use it
  std::array<VesselSample, SampleBuffer::kCapacity> drained_, bottom_drained_;
  RosClockWatch clock_;
  LineTopics topics_;
  std::unique_ptr<NodeDiagnostics> diag_;
  ResetHandshake reset_;
  ros::ServiceServer reset_srv_, range_reset_srv_;
  std::atomic<bool> clear_range_{false};  // ~range_graph/reset asked; the loop clears the window

  std::unique_ptr<NodeRun> line_;
  RunView run_;  // mode, reason, line_, last pose: what /diagnostics reports
  std::atomic<bool> stop_{false};
  ros::Time origin_;      // sim time t = (ROS time - origin_) - dropped_
  double dropped_ = 0.0;  // backlog dropped when the integration fell behind [s]
  ros::Time last_start_attempt_, last_bottom_pose_;
  // Rate limits of repeated warnings, per riser (ROS_WARN_THROTTLE's limit is shared by every riser of
  // a nodelet manager) and on wall time.
  WarnThrottle waiting_warn_{5.0}, no_pose_warn_{5.0}, no_bottom_warn_{5.0}, behind_warn_{5.0};
  // A start that keeps failing: the first failure is logged, then at most one line per kStartErrorPeriod
  // with the number of failures in between (all counted on /diagnostics).
  static constexpr double kStartErrorPeriod = 60.0;  // [s] of wall time
  WallClock::time_point start_error_logged_;
  long start_failures_logged_ = 0;      // run_.failed_starts at the last line
  std::unique_ptr<ModesServer> modes_;  // last: stopped first on destruction
};

}  // namespace riser_sim_ros
