#include "riser_sim_ros/node_diagnostics.h"

#include <cmath>
#include <cstdio>

#include "riser_sim/planar/simulator.h"

namespace riser_sim_ros {

std::string num(double v, const char* format) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof(buf), format, v);
  return buf;
}

namespace {
std::string modeName(const RunView& run) {
  if (run.mode != RunMode::kWaiting) {
    static const char* names[] = {"", "running", "diverged", "could not start"};
    return names[static_cast<int>(run.mode)];
  }
  if (run.missing_vessel && run.missing_bottom) return "waiting for vessel and bottom poses";
  return run.missing_bottom ? "waiting for bottom pose" : "waiting for vessel pose";
}
}  // namespace

NodeDiagnostics::NodeDiagnostics(ros::NodeHandle& nh, const std::string& name, const std::string& hardware_id,
                                 double rate, double pose_timeout, const VesselInput& input, const RosClockWatch& clock,
                                 const VesselInput* bottom)
    : pub_(nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 5)),
      name_(name),
      pose_timeout_(pose_timeout),
      input_(input),
      bottom_(bottom),
      clock_(clock) {
  schedule_.period = periodOf(rate);
  msg_.status.resize(1);
  msg_.status[0].name = name.substr(name.find_first_not_of('/')) + ": riser simulation";
  msg_.status[0].hardware_id = hardware_id;
}

bool NodeDiagnostics::dueWhileStalled(WallClock::time_point wall) {
  if (!clock_.stalled() || schedule_.period <= 0.0) {
    next_stalled_ = WallClock::time_point();
    return false;
  }
  if (next_stalled_ != WallClock::time_point() && wall < next_stalled_) return false;
  next_stalled_ =
      wall + std::chrono::duration_cast<WallClock::duration>(std::chrono::duration<double>(schedule_.period));
  return true;
}

void NodeDiagnostics::restartWindow(const ros::Time& now, double sim_time) {
  win_ros_ = now;
  win_sim_ = sim_time;
  win_compute_ = win_dropped_ = win_step_max_ = 0.0;
  win_steps_ = 0;
}

void NodeDiagnostics::addSteps(long n, double seconds) {
  win_compute_ += seconds;
  win_steps_ += n;
  win_step_max_ = std::max(win_step_max_, seconds / n);
}

void NodeDiagnostics::addDropped(double seconds) {
  win_dropped_ += seconds;
  total_dropped_ += seconds;
}

void NodeDiagnostics::addCycleWork(double seconds, bool period_end) {
  work_acc_ += seconds;
  if (!period_end) return;
  period_work_.add(work_acc_);
  work_acc_ = 0.0;
}

void NodeDiagnostics::clearTiming() {
  period_work_.clear();
  publish_work_.clear();
  work_acc_ = 0.0;
}

void NodeDiagnostics::addValue(const char* key, const std::string& value) {
  diagnostic_msgs::KeyValue k;
  k.key = key;
  k.value = value;
  msg_.status[0].values.push_back(k);
}

std::string NodeDiagnostics::waitingFor(const RunView& run) const {
  const std::string vessel = "vessel pose (" + input_.source() + ")";
  if (!bottom_ || !run.missing_bottom) return vessel;
  const std::string bottom = "bottom pose (" + bottom_->source() + ")";
  return run.missing_vessel ? vessel + " and " + bottom : bottom;
}

std::string NodeDiagnostics::runningMessage(const ros::Time& now, const RunView& run, double pose_age) {
  using diagnostic_msgs::DiagnosticStatus;
  DiagnosticStatus& st = msg_.status[0];
  NodeRun& line = *run.line;
  const double ros_span = (now - win_ros_).toSec();
  const double sim_span = line.time() - win_sim_;
  const double rtf = ros_span > 0.0 ? sim_span / ros_span : NAN;
  const double compute_rtf = win_compute_ > 0.0 ? sim_span / win_compute_ : NAN;
  const double step_mean = win_steps_ > 0 ? win_compute_ / win_steps_ : NAN;
  addValue("real-time factor", num(rtf, "%.3f"));
  addValue("compute real-time factor", num(compute_rtf, "%.2f"));
  addValue("step time mean [us]", num(step_mean * 1e6, "%.2f"));
  addValue("step time max [us]", num(win_step_max_ * 1e6, "%.2f"));
  addValue("steps in window", std::to_string(win_steps_));
  addValue("work per publish period p99 [ms]", num(period_work_.percentile(0.99) * 1e3, "%.3f"));
  addValue("publish period [ms]", num(publish_period_ * 1e3, "%.1f"));
  addValue("publish time mean [ms]", num(publish_work_.mean() * 1e3, "%.3f"));
  addValue("publish time p99 [ms]", num(publish_work_.percentile(0.99) * 1e3, "%.3f"));
  addValue("time dropped in window [s]", num(win_dropped_, "%.3f"));
  addValue("time dropped total [s]", num(total_dropped_, "%.3f"));
  addValue("sim time [s]", num(line.time(), "%.3f"));
  addValue("dt [s]", num(line.dt()));
  const RunHealth h = line.health();
  addValue("constraint error [m]", num(h.constraint_error, "%.3e"));
  addValue("max constraint error [m]", num(h.max_constraint_error, "%.3e"));
  addValue("energy [J]", num(h.energy, "%.6e"));
  const double drift = h.energy_drift;
  addValue("energy balance error (relative)", num(drift, "%.3e"));
  addValue("force noise, top tension (relative, last 10 s)", num(h.noise.top, "%.3e"));
  addValue("force noise, largest axial force (relative, last 10 s)", num(h.noise.max_axial, "%.3e"));
  const std::string& forces = h.force_warning;
  addValue("hang-off x [m]", num(h.hangoff.x(), "%.4f"));
  if (line.spatial()) addValue("hang-off y [m]", num(h.hangoff.y(), "%.4f"));
  addValue("hang-off z [m]", num(h.hangoff.z(), "%.4f"));
  // Pose gaps (external_motion.h: a sample later than max(3 periods, blend + coast)) since the start or ~reset,
  // and the rejoin after the last one.
  const double t = line.time();
  const auto gapValues = [&](const riser_sim::MotionGaps& g, const char* count, const char* longest, const char* last,
                             const char* rejoin) {
    addValue(count, std::to_string(g.count));
    addValue(longest, num(g.longest, "%.3f"));
    addValue(last, num(g.last, "%.3f"));
    addValue(rejoin, g.rejoining(t) ? "rejoining, " + num(g.rejoin_end - t, "%.2f") + " s left" : std::string("no"));
  };
  gapValues(h.gaps, "pose gaps", "longest pose gap [s]", "last pose gap [s]", "rejoining the vessel");
  if (line.drivenBottom())
    gapValues(h.bottom_gaps, "bottom pose gaps", "longest bottom pose gap [s]", "last bottom pose gap [s]",
              "rejoining the bottom");
  std::string message =
      "running: real-time factor " + num(rtf, "%.2f") + " (compute " + num(compute_rtf, "%.1f") + "x real time)";
  if (win_dropped_ > 0.0 || (std::isfinite(rtf) && rtf < 0.95)) {
    st.level = DiagnosticStatus::WARN;
    message = "falling behind real time: " + message + ", dropped " + num(win_dropped_, "%.3f") + " s";
  } else if (std::isfinite(pose_age) && pose_age > pose_timeout_) {
    st.level = DiagnosticStatus::WARN;
    message = "no vessel pose for " + num(pose_age, "%.1f") + " s: holding the last one";
  } else if (h.gaps.rejoining(t) || h.bottom_gaps.rejoining(t)) {
    st.level = DiagnosticStatus::WARN;
    const bool top = h.gaps.rejoining(t);
    const riser_sim::MotionGaps& g = top ? h.gaps : h.bottom_gaps;
    message = std::string("rejoining the ") + (top ? "vessel" : "bottom") + " after a " + num(g.last, "%.1f") +
              " s pose gap (" + num(g.rejoin_end - t, "%.1f") + " s left); " + message;
  } else if (std::abs(drift) > riser_sim::kEnergyDriftWarning) {
    st.level = DiagnosticStatus::WARN;
    message = "energy balance off by " + num(drift, "%.3g") +
              " of m g L: solver.dt does not resolve "
              "the motion, positions and forces may be wrong (smaller solver.dt or midpoint); " +
              message;
  } else if (!forces.empty()) {
    st.level = DiagnosticStatus::WARN;
    message = forces + "; " + message;
  }
  return message;
}

void NodeDiagnostics::publish(const ros::Time& now, const RunView& run) {
  using diagnostic_msgs::DiagnosticStatus;
  DiagnosticStatus& st = msg_.status[0];
  msg_.header.stamp = now;
  st.values.clear();
  const bool stalled = clock_.stalled();
  addValue("mode", stalled ? "paused: ROS time stalled (" + modeName(run) + ")" : modeName(run));
  addValue("vessel input", input_.source());
  addValue("poses accepted", std::to_string(input_.accepted()));
  addValue("poses rejected", std::to_string(input_.rejected()));
  const std::string last_rejection = input_.lastRejection();
  if (!last_rejection.empty()) addValue("last rejection", last_rejection);
  const double pose_age = run.last_pose.isZero() ? NAN : (now - run.last_pose).toSec();
  addValue("last pose age [s]", num(pose_age, "%.3f"));
  if (bottom_) {
    addValue("bottom input", bottom_->source());
    addValue("bottom poses accepted", std::to_string(bottom_->accepted()));
    addValue("bottom poses rejected", std::to_string(bottom_->rejected()));
    const std::string why = bottom_->lastRejection();
    if (!why.empty()) addValue("last bottom rejection", why);
  }

  st.level = DiagnosticStatus::OK;
  std::string message;
  if (run.mode == RunMode::kRunning && run.line) {
    message = runningMessage(now, run, pose_age);
    // Without ROS time advancing there is no real-time factor to claim.
    if (stalled) message = "simulation held at t = " + num(run.line->time(), "%.3f") + " s";
  } else if (run.mode == RunMode::kWaiting) {
    st.level = DiagnosticStatus::WARN;
    message = "waiting for the first valid " + waitingFor(run);
    if (!clock_.lastJump().empty()) message = clock_.lastJump() + ": simulation reset; " + message;
  } else {
    st.level = DiagnosticStatus::ERROR;
    message = (run.mode == RunMode::kDiverged ? "integration diverged: " : "") + run.reason +
              "; publishing stopped, call " + name_ + "/reset";
    addValue("reason", run.reason);
    if (run.mode == RunMode::kStartFailed) addValue("failed start attempts", std::to_string(run.failed_starts));
  }
  if (clock_.jumps() > 0) {
    addValue("ROS time jumps back", std::to_string(clock_.jumps()));
    addValue("last ROS time jump", clock_.lastJump());
  }
  if (stalled) {
    const double still = clock_.stillFor(WallClock::now());
    addValue("ROS time still for [s] (wall)", num(still, "%.1f"));
    if (st.level < DiagnosticStatus::WARN) st.level = DiagnosticStatus::WARN;
    message = "paused: ROS time has not advanced for " + num(still, "%.1f") + " s of wall time (" +
              (now.isZero() ? "no /clock yet" : "/clock stalled") + "); " + message;
  }
  st.message = message;
  pub_.publish(msg_);
  if (run.line) restartWindow(now, run.line->time());
}

}  // namespace riser_sim_ros
