#include "riser_sim_ros/riser_sim_node.h"

#include <cmath>
#include <cstdio>

#include "riser_sim/scene/scene_check.h"
#include "riser_sim_ros/xmlrpc_yaml.h"

namespace riser_sim_ros {

RiserSimNode::RiserSimNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadNodeParams(pnh, pnh.getNamespace())),
      scene_(loadScene(pnh)),
      name_(pnh.getNamespace()),
      clock_(params_.clock_timeout, name_),
      topics_(pnh_, params_, spatial() && scene_.bottom == riser_sim::BottomBoundary::kPinned) {
  if (scene_.top.type != riser_sim::MotionKind::kExternal && scene_.top.type != riser_sim::MotionKind::kFixed)
    ROS_WARN("%s: ~scene/top/motion/type '%s' ignored: the node drives the top from the vessel", name_.c_str(),
             riser_sim::name(scene_.top.type));
  // The loader checked the scene; once more with the core's one check (solver values, then what the scene's
  // engine supports), as a parameter error before any pose arrives.
  if (const auto error = riser_sim::checkScene(scene_))
    throw ParamError(paramPath("scene", error->key), error->message);
  if (!spatial() && params_.wrench_frame == "body") {
    throw ParamError("wrench_frame", "body needs a 3D scene (space: spatial); the planar wrench is in fixed_frame");
  }

  // tf is only read for tf input or poses in another frame: k risers that each listened to /tf would
  // each deserialise every riser's transforms (k^2 work).
  input_ = std::make_unique<VesselInput>(nh_, params_, tf_buffer_, samples_, name_, !spatial());
  if (drivenBottom())
    bottom_input_ = std::make_unique<VesselInput>(pnh_, params_, tf_buffer_, bottom_samples_, name_, false,
                                                  VesselInput::Feed::kBottom);
  else if (pnh_.hasParam("bottom_offset"))
    ROS_WARN(
        "%s: ~bottom_offset ignored: only a 3D scene with a pinned bottom and bottom.motion.type external "
        "has a driven bottom",
        name_.c_str());
  if (params_.vessel_input == "tf" || params_.expected_frame != params_.fixed_frame)
    tf_listener_ = std::make_unique<CheckedTfListener>(
        nh_, tf_buffer_, params_.vessel_input == "tf" ? params_.vessel_frame : "",
        [this](const std::string& why) { input_->reject(why); }, name_);
  diag_ = std::make_unique<NodeDiagnostics>(nh_, name_, scene_.name.empty() ? "riser_sim" : scene_.name,
                                            params_.rates.at("diagnostics"), params_.pose_timeout, *input_, clock_,
                                            bottom_input_.get());
  diag_->setPublishPeriod(topics_.referencePeriod());
  reset_srv_ = pnh_.advertiseService("reset", &RiserSimNode::onReset, this);
  if (params_.rates.at("range_graph") > 0.0)
    range_reset_srv_ = pnh_.advertiseService("range_graph/reset", &RiserSimNode::onRangeReset, this);
  modes_ = std::make_unique<ModesServer>(pnh_, name_, params_.fixed_frame, input_->source());

  ROS_INFO(
      "%s: scene '%s' (%s, L = %.1f m, n = %d, dt = %g s); vessel input %s, hang-off offset [%g, %g, %g] m; "
      "frames %s/rfe_<i> in %s",
      name_.c_str(), scene_.name.c_str(), spatial() ? "3D" : "planar", scene_.length, scene_.elements, scene_.solver.dt,
      input_->source().c_str(), params_.hangoff_offset.x(), params_.hangoff_offset.y(), params_.hangoff_offset.z(),
      params_.tf_prefix.c_str(), params_.fixed_frame.c_str());
  if (bottom_input_)
    ROS_INFO("%s: bottom driven from %s, bottom offset [%g, %g, %g] m; the start waits for its first valid pose",
             name_.c_str(), bottom_input_->source().c_str(), params_.bottom_offset.x(), params_.bottom_offset.y(),
             params_.bottom_offset.z());
}

void RiserSimNode::spin() {
  ros::AsyncSpinner spinner(2);
  spinner.start();
  run();
  spinner.stop();
}

void RiserSimNode::run() {
  LoopPacer pacer(params_.loop_rate);
  while (ros::ok() && !stop_) {
    cycle();
    pacer.wait();
  }
  reset_.answer(false, "shutting down");
}

void RiserSimNode::onClockJump(const ros::Time& now) {
  // A looping bag or a restarted simulator: the simulated past is gone. Back to the start state.
  ROS_WARN("%s: %s: simulation reset, restarting from the statics at the next vessel pose", name_.c_str(),
           clock_.lastJump().c_str());
  // Keep the poses already stamped on the new timeline; drop the rest.
  const auto keep = [&](SampleBuffer& buffer, VesselInput& input) {
    const int n = buffer.drain(drained_);
    buffer.clear();
    input.restart();
    for (int i = 0; i < n; ++i)
      if (drained_[i].stamp <= now + ros::Duration(params_.max_pose_lead)) buffer.push(drained_[i]);
  };
  keep(samples_, *input_);
  if (bottom_input_) keep(bottom_samples_, *bottom_input_);
  last_bottom_pose_ = ros::Time();
  run_.mode = RunMode::kWaiting;
  run_.last_pose = last_start_attempt_ = ros::Time();
  diag_->restart(now);
}

void RiserSimNode::cycle() {
  const WallClock::time_point w0 = WallClock::now();
  const ros::Time now = ros::Time::now();
  const RosClockWatch::Look look = clock_.look(now, w0);
  if (look.jumped_back) onClockJump(now);
  if (look.resumed) diag_->restart(now);
  if (!look.advanced) {
    // Paused: no stepping, no data; ~reset is still answered, diagnostics go out on wall time.
    serveReset(now);
    if (diag_->dueWhileStalled(w0)) diag_->publish(now, run_);
    return;
  }
  serveReset(now);

  const int n = samples_.drain(drained_);
  if (n > 0) {
    if (run_.mode == RunMode::kRunning && (now - run_.last_pose).toSec() > params_.pose_timeout)
      ROS_INFO("%s: valid vessel poses again after %.1f s without: tracking them", name_.c_str(),
               (now - run_.last_pose).toSec());
    run_.last_pose = drained_[n - 1].received;
  }
  const int nb = bottom_input_ ? bottom_samples_.drain(bottom_drained_) : 0;
  if (nb > 0) last_bottom_pose_ = bottom_drained_[nb - 1].received;
  bool period_end = false;
  switch (run_.mode) {
    case RunMode::kWaiting:
    case RunMode::kStartFailed: tryStart(n, nb, now); break;
    case RunMode::kRunning:
      for (int i = 0; i < n; ++i) line_->addSample(simTime(drained_[i].stamp), drained_[i]);
      for (int i = 0; i < nb; ++i) line_->addBottomSample(simTime(bottom_drained_[i].stamp), bottom_drained_[i]);
      if (bottom_input_ && (now - last_bottom_pose_).toSec() > params_.pose_timeout) {
        long held = 0;
        if (no_bottom_warn_.allow(held))
          ROS_WARN("%s: no valid bottom pose for %.1f s (~pose_timeout %.1f s): holding the last one", name_.c_str(),
                   (now - last_bottom_pose_).toSec(), params_.pose_timeout);
      }
      if ((now - run_.last_pose).toSec() > params_.pose_timeout) {
        long held = 0;
        if (no_pose_warn_.allow(held))
          ROS_WARN("%s: no valid vessel pose for %.1f s (~pose_timeout %.1f s): holding the last one", name_.c_str(),
                   (now - run_.last_pose).toSec(), params_.pose_timeout);
      }
      if (clear_range_.exchange(false)) line_->clearRangeGraph();
      integrate(now);
      if (run_.mode == RunMode::kRunning && topics_.due(now)) {
        const WallClock::time_point t0 = WallClock::now();
        if (!line_->evaluate()) {
          fail("non-finite outputs at t = " + num(line_->time()) + " s");
        } else {
          period_end = topics_.publishDue(*line_, origin_ + ros::Duration(line_->time() + dropped_));
          diag_->addPublishWork(seconds(WallClock::now() - t0));
        }
      }
      break;
    case RunMode::kDiverged: break;
  }
  if (diag_->due(now)) diag_->publish(now, run_);
  diag_->addCycleWork(seconds(WallClock::now() - w0), period_end);
}

// Starts at the latest vessel pose (and, for a driven bottom, the latest bottom pose) once both exist.
void RiserSimNode::tryStart(int n, int nb, const ros::Time& now) {
  VesselSample s, b;
  const bool vessel = n > 0 ? (s = drained_[n - 1], true) : samples_.latest(s);
  const bool bottom = !bottom_input_ || (nb > 0 ? (b = bottom_drained_[nb - 1], true) : bottom_samples_.latest(b));
  if ((n > 0 || nb > 0) && vessel && bottom &&
      (run_.mode == RunMode::kWaiting || (now - last_start_attempt_).toSec() >= 1.0)) {
    std::string message;
    if (start(s, bottom_input_ ? &b : nullptr, now, message))
      ROS_INFO("%s: %s", name_.c_str(), message.c_str());
    else
      startFailed(message);
  } else if (run_.mode == RunMode::kWaiting) {
    // Every input that has no valid pose yet.
    run_.missing_vessel = !vessel;
    run_.missing_bottom = !bottom;
    long held = 0;
    if (waiting_warn_.allow(held)) {
      std::string what = vessel ? "" : "vessel pose (" + input_->source() + ")";
      if (!bottom) what += (vessel ? "" : " and ") + std::string("bottom pose (") + bottom_input_->source() + ")";
      ROS_WARN("%s: waiting for the first valid %s", name_.c_str(), what.c_str());
    }
  }
}

void RiserSimNode::startFailed(const std::string& message) {
  const WallClock::time_point w = WallClock::now();
  if (++run_.failed_starts == 1) {
    ROS_ERROR(
        "%s: %s (retrying at the next pose, at most once a second; further failures are counted on "
        "/diagnostics and logged every %.0f s)",
        name_.c_str(), message.c_str(), kStartErrorPeriod);
  } else if (seconds(w - start_error_logged_) >= kStartErrorPeriod) {
    ROS_ERROR("%s: still cannot start: %s (%ld failed attempts since the last message, %ld in all)", name_.c_str(),
              message.c_str(), run_.failed_starts - start_failures_logged_, run_.failed_starts);
  } else {
    return;
  }
  start_error_logged_ = w;
  start_failures_logged_ = run_.failed_starts;
}

bool RiserSimNode::start(const VesselSample& s, const VesselSample* bottom, const ros::Time& now,
                         std::string& message) {
  last_start_attempt_ = now;
  std::unique_ptr<NodeRun> line;
  try {
    line =
        std::make_unique<NodeRun>(scene_, s, simTime(s.stamp), params_, bottom, bottom ? simTime(bottom->stamp) : 0.0);
    const std::string above = line->stepAboveLimit();
    if (!above.empty()) {
      line.reset();
      run_.reason = "could not start: " + above;
    }
  } catch (const std::invalid_argument& e) {  // a setup the loader let through
    run_.reason = std::string("could not start: ") + e.what();
  } catch (const std::runtime_error& e) {  // the statics failed, or the start is not finite
    run_.reason = "initial statics at hang-off " + describeHangoff(scene_, s.hangoff) +
                  (bottom ? " and bottom " + describeHangoff(scene_, bottom->hangoff) : std::string()) +
                  " failed: " + e.what();
    modes_->setFailure(run_.reason);
  } catch (const std::exception& e) {
    run_.reason = std::string("could not start: ") + e.what();
  }
  if (!line) {
    run_.mode = RunMode::kStartFailed;
    message = run_.reason;
    return false;
  }
  modes_->setState(line->heldScene(), now);  // the top fixed at the hang-off, a driven bottom where it started
  origin_ = ros::Time::now();                // after the statics: their cost is not a backlog to catch up
  if (origin_ < now) origin_ = now;
  dropped_ = 0.0;
  // The first sample's time on the new origin (the motion was made before the origin was known: with
  // the old origin the later samples looked older than it and were all refused, the top never moved).
  line->restartMotion(simTime(s.stamp), s);
  if (bottom) line->restartBottom(simTime(bottom->stamp), *bottom);
  last_bottom_pose_ = bottom ? bottom->received : ros::Time();
  run_.line = nullptr;  // the old run goes now
  line_ = std::move(line);
  run_.line = line_.get();
  topics_.start(origin_);
  run_.mode = RunMode::kRunning;
  run_.reason.clear();
  run_.failed_starts = 0;
  diag_->restartWindow(origin_, line_->time());
  diag_->clearTiming();
  message = line_->startMessage();
  return true;
}

void RiserSimNode::integrate(const ros::Time& now) {
  const double dt = line_->dt();
  const double behind = simTime(now) - line_->time();
  long n = static_cast<long>(std::floor(behind / dt + 1e-6));
  if (n <= 0) return;
  if (n > params_.max_steps_per_cycle) n = params_.max_steps_per_cycle;
  const double after = behind - n * dt;
  if (after > params_.max_lag) {
    // Cannot keep up: drop the backlog rather than let the lag grow (reported on /diagnostics).
    dropped_ += after;
    diag_->addDropped(after);
    line_->shiftSampleTimes(after);
    long held = 0;
    if (behind_warn_.allow(held))
      ROS_WARN("%s: integration slower than real time (dt %g s, n = %d): dropped %.3f s of backlog", name_.c_str(), dt,
               scene_.elements, after);
  }
  const WallClock::time_point t0 = WallClock::now();
  for (long i = 0; i < n; ++i) {
    if (!line_->step()) {
      fail(line_->divergenceReason());
      break;
    }
  }
  diag_->addSteps(n, seconds(WallClock::now() - t0));
}

void RiserSimNode::fail(const std::string& why) {
  run_.mode = RunMode::kDiverged;
  run_.reason = why;
  ROS_ERROR(
      "%s: integration diverged: %s. Publishing stopped; call %s/reset to restart from the current "
      "vessel pose",
      name_.c_str(), why.c_str(), name_.c_str());
}

bool RiserSimNode::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  res.success = reset_.request(res.message);
  return true;
}

bool RiserSimNode::onRangeReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  clear_range_ = true;
  res.success = true;
  res.message = "the range graph's window restarts at the next solver step";
  return true;
}

void RiserSimNode::serveReset(const ros::Time& now) {
  if (!reset_.take()) return;
  VesselSample s, b;
  bool ok = false;
  std::string message;
  if (now.isZero()) {
    message = "no ROS time yet (/use_sim_time is set and nothing publishes /clock)";
  } else if (!samples_.latest(s)) {
    message = "no valid vessel pose received yet (" + input_->source() + ")";
  } else if (bottom_input_ && !bottom_samples_.latest(b)) {
    message = "no valid bottom pose received yet (" + bottom_input_->source() + ")";
  } else {
    samples_.drain(drained_);  // older than s: the new start supersedes them
    if (bottom_input_) bottom_samples_.drain(bottom_drained_);
    ok = start(s, bottom_input_ ? &b : nullptr, now, message);
    ROS_INFO("%s: ~reset: %s", name_.c_str(), message.c_str());
  }
  reset_.answer(ok, message);
}

}  // namespace riser_sim_ros
