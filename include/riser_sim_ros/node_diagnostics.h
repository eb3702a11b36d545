// The node's /diagnostics: one DiagnosticStatus per riser with its mode, vessel input, real-time
// factors, step and publish timing, the integration's error bounds and the clock's state. Statistics
// cover the window since the last publish. Published at ~rates/diagnostics of ROS time, and on wall
// time while ROS time is stalled.
#pragma once
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>

#include "riser_sim_ros/node_run.h"
#include "riser_sim_ros/ros_clock.h"
#include "riser_sim_ros/timing_stats.h"
#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

enum class RunMode { kWaiting, kRunning, kDiverged, kStartFailed };

// v printed with `format`; "n/a" for NaN/Inf (diagnostics never carry NaN).
std::string num(double v, const char* format = "%.6g");

// The run as the integration loop holds it.
struct RunView {
  RunMode mode = RunMode::kWaiting;
  std::string reason;                                  // why diverged / statics failed
  NodeRun* line = nullptr;                             // null before the first start (energy is computed lazily)
  ros::Time last_pose;                                 // ROS time the last valid pose arrived (zero: none)
  bool missing_vessel = true, missing_bottom = false;  // waiting: the inputs without a valid pose yet
  long failed_starts = 0;                              // start attempts that failed since the last start
};

class NodeDiagnostics {
 public:
  NodeDiagnostics(ros::NodeHandle& nh, const std::string& name, const std::string& hardware_id, double rate,
                  double pose_timeout, const VesselInput& input, const RosClockWatch& clock,
                  const VesselInput* bottom = nullptr);  // bottom: a driven bottom's feed
  // Due at the rate in ROS time; restart(now): due at now.
  bool due(const ros::Time& now) { return schedule_.due(now); }
  void restart(const ros::Time& now) { schedule_.restart(now); }
  // Due on wall time while ROS time is stalled.
  bool dueWhileStalled(WallClock::time_point wall);

  // Window statistics.
  void restartWindow(const ros::Time& now, double sim_time);
  void addSteps(long n, double seconds);
  void addDropped(double seconds);
  void addPublishWork(double seconds) { publish_work_.add(seconds); }
  // Wall time of one loop cycle; `period_end`: the reference topic went out (one publish period ends).
  void addCycleWork(double seconds, bool period_end);
  void clearTiming();
  void setPublishPeriod(double seconds) { publish_period_ = seconds; }

  void publish(const ros::Time& now, const RunView& run);

 private:
  void addValue(const char* key, const std::string& value);
  std::string runningMessage(const ros::Time& now, const RunView& run, double pose_age);
  std::string waitingFor(const RunView& run) const;  // "vessel pose (<source>)", the bottom's, or both

  ros::Publisher pub_;
  std::string name_;
  double pose_timeout_;
  const VesselInput& input_;
  const VesselInput* bottom_;
  const RosClockWatch& clock_;
  Schedule schedule_;
  WallClock::time_point next_stalled_;
  diagnostic_msgs::DiagnosticArray msg_;
  double publish_period_ = 0.0;

  ros::Time win_ros_;
  double win_sim_ = 0.0, win_compute_ = 0.0, win_dropped_ = 0.0, win_step_max_ = 0.0;
  long win_steps_ = 0;
  double total_dropped_ = 0.0;
  double work_acc_ = 0.0;           // wall time of the loop's work since the last reference publish [s]
  TimingStats period_work_{1024};   // [s] per reference publish period
  TimingStats publish_work_{1024};  // [s] building + sending messages, per cycle that published
};

}  // namespace riser_sim_ros
