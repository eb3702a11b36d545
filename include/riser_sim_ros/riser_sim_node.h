// riser_sim_node: the riser simulated in real time (ROS time), driven by the vessel's pose.
// See docs/ros_interface.md for topics, frames, parameters and services.
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
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "riser_sim/external_motion.h"
#include "riser_sim/kinematics.h"
#include "riser_sim/scene.h"
#include "riser_sim/simulator.h"
#include "riser_sim/Modes.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/timing_stats.h"
#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

// Loads ~scene (XmlRpc tree -> YAML -> riser_sim::parseScene). Throws ParamError naming the key,
// e.g. "~scene/line/elements: must be >= 1, got 0".
riser_sim::Scene loadScene(const ros::NodeHandle& pnh);

class RiserSimNode {
 public:
  // Throws ParamError for a bad parameter or scene. The riser's name (diagnostics, log lines, default
  // tf_prefix) is pnh's namespace: the node's name, or a nodelet's name inside its manager.
  RiserSimNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~RiserSimNode();
  // Runs the integration loop on the calling thread until stop() or ROS shutdown. Whoever owns nh's and
  // pnh's callback queues must serve them (spin(): an AsyncSpinner; a nodelet: its manager's threads).
  void run();
  // Makes run() return after its current cycle; callable from any thread.
  void stop() { stop_ = true; }
  // The standalone node: run() with an AsyncSpinner (2 threads) serving the global callback queue.
  void spin();
  const std::string& name() const { return name_; }

 private:
  enum class Mode { kWaiting, kRunning, kDiverged, kStaticsFailed };
  struct Schedule {  // publishing at a fixed rate of ROS time
    double period = 0.0;  // [s], 0 = off
    ros::Time next;
    bool due(const ros::Time& now);
    void restart(const ros::Time& now) { next = now; }
  };
  using Clock = std::chrono::steady_clock;
  // What ~modes analyses: the scene with the top fixed at the hang-off, and its static state.
  struct StaticState {
    riser_sim::Scene scene;
    riser_sim::Kinematics kin;
    riser_sim::Vec2 end_force = riser_sim::Vec2::Zero();
    ros::Time stamp;
  };

  void cycle();
  // Watches ROS time: false when it has not advanced (nothing to step). Resets the simulation when it
  // went backwards; marks the clock stalled after ~clock_timeout of wall time without progress.
  bool clockAdvanced(const ros::Time& now, Clock::time_point wall);
  bool start(const VesselSample& s, const ros::Time& now, std::string& message);
  void integrate(const ros::Time& now);
  void publish(const ros::Time& now);
  void publishDiagnostics(const ros::Time& now);
  void serveReset(const ros::Time& now);
  void fail(const std::string& why);
  bool onReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onModes(riser_sim::Modes::Request& req, riser_sim::Modes::Response& res);
  double simTime(const ros::Time& t) const { return (t - origin_).toSec() - dropped_; }
  void resetWindow(const ros::Time& now);

  ros::NodeHandle nh_, pnh_;
  NodeParams params_;
  riser_sim::Scene scene_;
  std::string name_;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  tf2_ros::TransformBroadcaster tf_pub_;
  SampleBuffer samples_;
  std::unique_ptr<VesselInput> input_;
  std::array<VesselSample, SampleBuffer::kCapacity> drained_;

  std::unique_ptr<riser_sim::Simulator> sim_;
  riser_sim::ExternalMotion* motion_ = nullptr;  // owned by sim_
  std::unique_ptr<LineMessages> msgs_;
  std::unique_ptr<LineMarkers> markers_;
  ros::Publisher tension_pub_, state_pub_, markers_pub_, wrench_pub_, diag_pub_;
  ros::ServiceServer reset_srv_, modes_srv_;
  diagnostic_msgs::DiagnosticArray diag_;

  std::atomic<bool> stop_{false};
  Mode mode_ = Mode::kWaiting;
  bool stalled_ = false;           // ROS time has not advanced for ~clock_timeout (wall)
  Clock::time_point last_advance_, next_stalled_diag_;
  long clock_resets_ = 0;          // times ROS time went backwards
  std::string clock_note_;         // the last backwards jump, for /diagnostics
  std::string reason_;             // why diverged / statics failed
  ros::Time origin_;               // sim time t = (ROS time - origin_) - dropped_
  double dropped_ = 0.0;           // backlog dropped when the integration fell behind [s]
  ros::Time last_now_, last_received_, last_start_attempt_;
  Schedule tension_s_, state_s_, markers_s_, tf_s_, wrench_s_, diag_s_;
  Schedule* reference_ = nullptr;  // fastest data publisher: its period is "one publish period"
  // Rate limits of repeated warnings, per riser (ROS_WARN_THROTTLE's limit is shared by every riser of
  // a nodelet manager) and on wall time.
  WarnThrottle waiting_warn_{5.0}, no_pose_warn_{5.0}, behind_warn_{5.0};

  // Statistics over the current diagnostics window.
  ros::Time win_ros_;
  double win_sim_ = 0.0, win_compute_ = 0.0, win_dropped_ = 0.0, win_step_max_ = 0.0;
  long win_steps_ = 0;
  double total_dropped_ = 0.0;
  double work_acc_ = 0.0;          // wall time of the loop's work since the last reference publish [s]
  bool reference_fired_ = false;
  TimingStats period_work_{1024};  // [s] per reference publish period
  TimingStats publish_work_{1024}; // [s] building + sending messages, per cycle that published

  // ~reset handshake between the service thread and the integration loop.
  std::mutex reset_call_mutex_, reset_mutex_;
  std::condition_variable reset_cv_;
  bool reset_requested_ = false, reset_done_ = false, reset_ok_ = false;
  std::string reset_message_;

  // Static state for ~modes (set by start(), read by the ~modes thread).
  std::mutex static_mutex_;
  std::shared_ptr<const StaticState> static_state_;
  std::string static_failure_;     // why there is no static state yet
  ros::CallbackQueue modes_queue_;
  std::unique_ptr<ros::AsyncSpinner> modes_spinner_;  // last: stopped first on destruction
};

}  // namespace riser_sim_ros
