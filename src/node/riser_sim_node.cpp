#include "riser_sim_ros/riser_sim_node.h"

#include <cmath>
#include <cstdio>
#include <thread>

#include "riser_sim/integrator.h"
#include "riser_sim/modal.h"
#include "riser_sim/run_builder.h"
#include "riser_sim/solver_setup.h"
#include "riser_sim/scene_yaml.h"
#include "riser_sim/statics.h"
#include "riser_sim_ros/modes_service.h"
#include "riser_sim_ros/xmlrpc_yaml.h"

namespace riser_sim_ros {

namespace {

std::string num(double v, const char* format = "%.6g") {
  if (!std::isfinite(v)) return "n/a";  // diagnostics never carry NaN
  char buf[48];
  std::snprintf(buf, sizeof(buf), format, v);
  return buf;
}

const char* modeName(int m) {
  static const char* names[] = {"waiting for vessel pose", "running", "diverged", "statics failed"};
  return names[m];
}

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

riser_sim::Scene loadScene(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue tree;
  if (!pnh.getParam("scene", tree))
    throw ParamError("scene", "missing: load a scene file into the node's private namespace, e.g. <rosparam "
                              "command=\"load\" file=\"$(find riser_sim)/config/scenes/demo_riser.yaml\" ns=\"scene\"/> "
                              "inside the <node> tag");
  YAML::Node yaml;
  try {
    yaml = toYaml(tree);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    throw ParamError(paramPath("scene", what.substr(0, colon)), what.substr(colon + 2));
  }
  try {
    return riser_sim::parseScene(yaml);
  } catch (const riser_sim::SceneError& e) {
    std::string what = e.what();
    if (!e.key().empty() && what.rfind(e.key() + ": ", 0) == 0) what = what.substr(e.key().size() + 2);
    throw ParamError(paramPath("scene", e.key()), what);
  }
}

bool RiserSimNode::Schedule::due(const ros::Time& now) {
  if (period <= 0.0 || now < next) return false;
  next += ros::Duration(period);
  if (next <= now) next = now + ros::Duration(period);  // fell behind by more than a period: skip
  return true;
}

RiserSimNode::RiserSimNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh), pnh_(pnh), params_(loadNodeParams(pnh, pnh.getNamespace())), scene_(loadScene(pnh)),
      name_(pnh.getNamespace()) {
  if (scene_.top.type != "external" && scene_.top.type != "fixed")
    ROS_WARN("%s: ~scene/top/motion/type '%s' ignored: the node drives the top from the vessel", name_.c_str(),
             scene_.top.type.c_str());
  // The loader checked the scene; the solver setup once more with the core's one check, as a parameter error.
  if (const auto error = riser_sim::checkSolverSetup(scene_.solver, scene_.elements, scene_.options.axial_flexibility))
    throw ParamError(paramPath("scene", error->key), error->message);

  // tf is only read for tf input or poses in another frame: k risers that each listened to /tf would
  // each deserialise every riser's transforms (k^2 work).
  if (params_.vessel_input == "tf" || params_.expected_frame != params_.fixed_frame)
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh_);
  input_ = std::make_unique<VesselInput>(nh_, params_, tf_buffer_, samples_, name_);
  tension_pub_ = pnh_.advertise<riser_sim::Tension>("tension", 5);
  state_pub_ = pnh_.advertise<riser_sim::LineState>("state", 5);
  markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 2);
  wrench_pub_ = pnh_.advertise<geometry_msgs::WrenchStamped>("top_wrench", 5);
  diag_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 5);
  reset_srv_ = pnh_.advertiseService("reset", &RiserSimNode::onReset, this);
  {
    // ~modes on its own queue and thread: an eigen-solve never holds up the vessel input or ~reset.
    ros::NodeHandle modes_nh(pnh_);
    modes_nh.setCallbackQueue(&modes_queue_);
    modes_srv_ = modes_nh.advertiseService("modes", &RiserSimNode::onModes, this);
    modes_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &modes_queue_);
    modes_spinner_->start();
  }
  last_advance_ = Clock::now();

  const PublishRates& r = params_.rates;
  auto period = [](double hz) { return hz > 0.0 ? 1.0 / hz : 0.0; };
  tension_s_.period = period(r.tension);
  state_s_.period = period(r.state);
  markers_s_.period = period(r.markers);
  tf_s_.period = period(r.tf);
  wrench_s_.period = period(r.wrench);
  diag_s_.period = period(r.diagnostics);
  for (Schedule* s : {&tension_s_, &state_s_, &markers_s_, &tf_s_, &wrench_s_})
    if (s->period > 0.0 && (!reference_ || s->period < reference_->period)) reference_ = s;

  diag_.status.resize(1);
  diagnostic_msgs::DiagnosticStatus& st = diag_.status[0];
  st.name = name_.substr(name_.find_first_not_of('/')) + ": riser simulation";
  st.hardware_id = scene_.name.empty() ? "riser_sim" : scene_.name;

  ROS_INFO("%s: scene '%s' (L = %.1f m, n = %d, dt = %g s); vessel input %s, hang-off offset [%g, %g, %g] m; "
           "frames %s/rfe_<i> in %s",
           name_.c_str(), scene_.name.c_str(), scene_.length, scene_.elements, scene_.solver.dt, input_->source().c_str(),
           params_.hangoff_offset.x(), params_.hangoff_offset.y(), params_.hangoff_offset.z(),
           params_.tf_prefix.c_str(), params_.fixed_frame.c_str());
}

RiserSimNode::~RiserSimNode() {
  modes_spinner_->stop();
  modes_srv_.shutdown();
}

void RiserSimNode::spin() {
  ros::AsyncSpinner spinner(2);
  spinner.start();
  run();
  spinner.stop();
}

void RiserSimNode::run() {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / params_.loop_rate));
  auto next = Clock::now();
  while (ros::ok() && !stop_) {
    cycle();
    next += period;
    const auto now = Clock::now();
    if (next < now) next = now;
    std::this_thread::sleep_until(next);
  }
  {
    std::lock_guard<std::mutex> lock(reset_mutex_);
    reset_done_ = true;
    reset_ok_ = false;
    reset_message_ = "shutting down";
  }
  reset_cv_.notify_all();
}

bool RiserSimNode::clockAdvanced(const ros::Time& now, Clock::time_point wall) {
  if (!now.isZero() && !last_now_.isZero() && now < last_now_) {
    // A looping bag or a restarted simulator: the simulated past is gone. Back to the start state.
    char buf[200];
    std::snprintf(buf, sizeof(buf), "ROS time jumped back by %.3f s (to %.3f s; bag loop or simulator restart?)",
                  (last_now_ - now).toSec(), now.toSec());
    clock_note_ = buf;
    ++clock_resets_;
    ROS_WARN("%s: %s: simulation reset, restarting from the statics at the next vessel pose", name_.c_str(), buf);
    // Keep the poses already stamped on the new timeline; drop the rest.
    const int n = samples_.drain(drained_);
    samples_.clear();
    input_->restart();
    for (int i = 0; i < n; ++i)
      if (drained_[i].stamp <= now + ros::Duration(params_.max_pose_lead)) samples_.push(drained_[i]);
    mode_ = Mode::kWaiting;
    last_received_ = last_start_attempt_ = ros::Time();
    diag_s_.restart(now);
  }
  const bool advanced = !now.isZero() && now != last_now_;
  if (advanced) {
    if (stalled_) {
      ROS_INFO("%s: ROS time advances again after %.1f s (wall): simulation resumed", name_.c_str(),
               seconds(wall - last_advance_));
      stalled_ = false;
      diag_s_.restart(now);
    }
    last_advance_ = wall;
    last_now_ = now;
  } else if (!stalled_ && seconds(wall - last_advance_) > params_.clock_timeout) {
    stalled_ = true;
    next_stalled_diag_ = wall;
    ROS_WARN("%s: ROS time has not advanced for %.1f s of wall time (%s): simulation paused", name_.c_str(),
             seconds(wall - last_advance_), now.isZero() ? "/use_sim_time set, no /clock yet" : "/clock stalled");
  }
  return advanced;
}

void RiserSimNode::cycle() {
  const Clock::time_point w0 = Clock::now();
  const ros::Time now = ros::Time::now();
  if (!clockAdvanced(now, w0)) {
    // Paused: no stepping, no data; ~reset is still answered, diagnostics go out on wall time.
    serveReset(now);
    if (stalled_ && diag_s_.period > 0.0 && w0 >= next_stalled_diag_) {
      publishDiagnostics(now);
      next_stalled_diag_ = w0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(diag_s_.period));
    }
    return;
  }
  serveReset(now);

  const int n = samples_.drain(drained_);
  if (n > 0) {
    if (mode_ == Mode::kRunning && (now - last_received_).toSec() > params_.pose_timeout)
      ROS_INFO("%s: valid vessel poses again after %.1f s without: tracking them", name_.c_str(), (now - last_received_).toSec());
    last_received_ = drained_[n - 1].received;
  }
  switch (mode_) {
    case Mode::kWaiting:
    case Mode::kStaticsFailed:
      if (n > 0 && (mode_ == Mode::kWaiting || (now - last_start_attempt_).toSec() >= 1.0)) {
        std::string message;
        if (start(drained_[n - 1], now, message)) ROS_INFO("%s: %s", name_.c_str(), message.c_str());
        else ROS_ERROR("%s: %s (retrying at the next pose, at most once a second)", name_.c_str(), message.c_str());
      } else if (mode_ == Mode::kWaiting) {
        long held = 0;
        if (waiting_warn_.allow(held))
          ROS_WARN("%s: waiting for the first valid vessel pose (%s)", name_.c_str(), input_->source().c_str());
      }
      break;
    case Mode::kRunning:
      for (int i = 0; i < n; ++i)
        motion_->addSample(simTime(drained_[i].stamp), toPaper(drained_[i].hangoff), sim_->time());
      if ((now - last_received_).toSec() > params_.pose_timeout) {
        long held = 0;
        if (no_pose_warn_.allow(held))
          ROS_WARN("%s: no valid vessel pose for %.1f s (~pose_timeout %.1f s): holding the last one", name_.c_str(),
                   (now - last_received_).toSec(), params_.pose_timeout);
      }
      integrate(now);
      if (mode_ == Mode::kRunning) publish(now);
      break;
    case Mode::kDiverged:
      break;
  }
  if (diag_s_.due(now)) publishDiagnostics(now);

  work_acc_ += std::chrono::duration<double>(Clock::now() - w0).count();
  if (reference_fired_) {
    period_work_.add(work_acc_);
    work_acc_ = 0.0;
    reference_fired_ = false;
  }
}

bool RiserSimNode::start(const VesselSample& s, const ros::Time& now, std::string& message) {
  last_start_attempt_ = now;
  const Eigen::Vector2d top = toPaper(s.hangoff);
  try {
    riser_sim::Scene sc = scene_;
    sc.top.type = "fixed";
    sc.top.position = top;
    riser_sim::RunInputs in;
    in.top = top;
    auto motion = std::make_unique<riser_sim::ExternalMotion>(top, simTime(s.stamp), params_.motion);
    riser_sim::ExternalMotion* external = motion.get();
    in.motion = std::move(motion);
    riser_sim::Run run;
    try {
      run = riser_sim::buildRun(sc, std::move(in));
    } catch (const std::runtime_error& e) {  // the statics failed, or the start is not finite
      mode_ = Mode::kStaticsFailed;
      reason_ = "initial statics at hang-off (" + num(top.x()) + ", " + num(top.y()) + ") failed: " + e.what();
      message = reason_;
      std::lock_guard<std::mutex> lock(static_mutex_);
      if (!static_state_) static_failure_ = reason_;
      return false;
    }
    auto state = std::make_shared<StaticState>();
    state->scene = sc;
    state->kin = run.initial.kin;
    state->end_force = run.initial.end_force;
    state->stamp = now;
    {
      std::lock_guard<std::mutex> lock(static_mutex_);
      static_state_ = std::move(state);
    }
    origin_ = ros::Time::now();  // after the statics: their cost is not a backlog to catch up
    if (origin_ < now) origin_ = now;
    dropped_ = 0.0;
    // The first sample's time on the new origin (the motion was made before the origin was known: with
    // the old origin the later samples looked older than it and were all refused, the top never moved).
    external->reset(simTime(s.stamp), top);
    motion_ = external;
    std::shared_ptr<const riser_sim::Model> model = run.model;
    sim_ = std::move(run.sim);
    msgs_ = std::make_unique<LineMessages>(*model, params_.fixed_frame, params_.tf_prefix);
    markers_ = std::make_unique<LineMarkers>(*model, params_.fixed_frame, params_.markers, surfacesOf(sc));
  } catch (const std::exception& e) {
    mode_ = Mode::kStaticsFailed;
    reason_ = std::string("could not start: ") + e.what();
    message = reason_;
    return false;
  }
  mode_ = Mode::kRunning;
  reason_.clear();
  for (Schedule* sch : {&tension_s_, &state_s_, &markers_s_, &tf_s_, &wrench_s_}) sch->restart(origin_);
  resetWindow(origin_);
  period_work_.clear();
  publish_work_.clear();
  work_acc_ = 0.0;
  const riser_sim::LineOutputs& out = sim_->outputs();
  message = "static equilibrium at hang-off (x " + num(top.x(), "%.3f") + ", z " + num(top.y(), "%.3f") +
            ") m: top tension " + num(out.top_tension, "%.1f") + " N; running";
  return true;
}

void RiserSimNode::integrate(const ros::Time& now) {
  const double dt = sim_->dt();
  const double behind = simTime(now) - sim_->time();
  long n = static_cast<long>(std::floor(behind / dt + 1e-6));
  if (n <= 0) return;
  if (n > params_.max_steps_per_cycle) n = params_.max_steps_per_cycle;
  const double after = behind - n * dt;
  if (after > params_.max_lag) {
    // Cannot keep up: drop the backlog rather than let the lag grow (reported on /diagnostics).
    dropped_ += after;
    win_dropped_ += after;
    total_dropped_ += after;
    motion_->shiftSampleTimes(after);
    long held = 0;
    if (behind_warn_.allow(held))
      ROS_WARN("%s: integration slower than real time (dt %g s, n = %d): dropped %.3f s of backlog", name_.c_str(), dt,
               scene_.elements, after);
  }
  const Clock::time_point t0 = Clock::now();
  for (long i = 0; i < n; ++i) {
    if (!sim_->step()) {
      fail(sim_->divergenceReason());
      break;
    }
  }
  const double spent = std::chrono::duration<double>(Clock::now() - t0).count();
  win_compute_ += spent;
  win_steps_ += n;
  win_step_max_ = std::max(win_step_max_, spent / n);
}

void RiserSimNode::publish(const ros::Time& now) {
  const bool tension = tension_s_.due(now), state = state_s_.due(now), markers = markers_s_.due(now),
             tf = tf_s_.due(now), wrench = wrench_s_.due(now);
  if (!(tension || state || markers || tf || wrench)) return;
  const Clock::time_point t0 = Clock::now();
  const riser_sim::LineOutputs& out = sim_->outputs();
  if (!outputsFinite(out)) {
    fail("non-finite outputs at t = " + num(sim_->time()) + " s");
    return;
  }
  const ros::Time stamp = origin_ + ros::Duration(sim_->time() + dropped_);
  if (tension) {
    msgs_->fillTension(out, stamp);
    tension_pub_.publish(msgs_->tension);
  }
  if (state) {
    msgs_->fillState(out, stamp);
    state_pub_.publish(msgs_->state);
  }
  if (wrench) {
    msgs_->fillWrench(out, stamp);
    wrench_pub_.publish(msgs_->wrench);
  }
  if (tf) {
    msgs_->fillTransforms(out, stamp);
    tf_pub_.sendTransform(msgs_->transforms);
  }
  if (markers && markers_pub_.getNumSubscribers() > 0) {
    markers_->fill(out, stamp);
    markers_pub_.publish(markers_->msg);
  }
  publish_work_.add(std::chrono::duration<double>(Clock::now() - t0).count());
  if (reference_ && ((reference_ == &tension_s_ && tension) || (reference_ == &state_s_ && state) ||
                     (reference_ == &markers_s_ && markers) || (reference_ == &tf_s_ && tf) ||
                     (reference_ == &wrench_s_ && wrench)))
    reference_fired_ = true;
}

void RiserSimNode::fail(const std::string& why) {
  mode_ = Mode::kDiverged;
  reason_ = why;
  ROS_ERROR("%s: integration diverged: %s. Publishing stopped; call %s/reset to restart from the current "
            "vessel pose", name_.c_str(), why.c_str(), name_.c_str());
}

void RiserSimNode::resetWindow(const ros::Time& now) {
  win_ros_ = now;
  win_sim_ = sim_ ? sim_->time() : 0.0;
  win_compute_ = win_dropped_ = win_step_max_ = 0.0;
  win_steps_ = 0;
}

void RiserSimNode::publishDiagnostics(const ros::Time& now) {
  using diagnostic_msgs::DiagnosticStatus;
  DiagnosticStatus& st = diag_.status[0];
  diag_.header.stamp = now;
  st.values.clear();
  auto kv = [&](const char* key, const std::string& value) {
    diagnostic_msgs::KeyValue k;
    k.key = key;
    k.value = value;
    st.values.push_back(k);
  };
  kv("mode", stalled_ ? std::string("paused: ROS time stalled (") + modeName(static_cast<int>(mode_)) + ")"
                      : std::string(modeName(static_cast<int>(mode_))));
  kv("vessel input", input_->source());
  kv("poses accepted", std::to_string(input_->accepted()));
  kv("poses rejected", std::to_string(input_->rejected()));
  const std::string last_rejection = input_->lastRejection();
  if (!last_rejection.empty()) kv("last rejection", last_rejection);
  const double pose_age = last_received_.isZero() ? NAN : (now - last_received_).toSec();
  kv("last pose age [s]", num(pose_age, "%.3f"));

  st.level = DiagnosticStatus::OK;
  std::string message;
  if (mode_ == Mode::kRunning && sim_) {
    const double ros_span = (now - win_ros_).toSec();
    const double sim_span = sim_->time() - win_sim_;
    const double rtf = ros_span > 0.0 ? sim_span / ros_span : NAN;
    const double compute_rtf = win_compute_ > 0.0 ? sim_span / win_compute_ : NAN;
    const double step_mean = win_steps_ > 0 ? win_compute_ / win_steps_ : NAN;
    kv("real-time factor", num(rtf, "%.3f"));
    kv("compute real-time factor", num(compute_rtf, "%.2f"));
    kv("step time mean [us]", num(step_mean * 1e6, "%.2f"));
    kv("step time max [us]", num(win_step_max_ * 1e6, "%.2f"));
    kv("steps in window", std::to_string(win_steps_));
    kv("work per publish period p99 [ms]", num(period_work_.percentile(0.99) * 1e3, "%.3f"));
    kv("publish period [ms]", num(reference_ ? reference_->period * 1e3 : NAN, "%.1f"));
    kv("publish time mean [ms]", num(publish_work_.mean() * 1e3, "%.3f"));
    kv("publish time p99 [ms]", num(publish_work_.percentile(0.99) * 1e3, "%.3f"));
    kv("time dropped in window [s]", num(win_dropped_, "%.3f"));
    kv("time dropped total [s]", num(total_dropped_, "%.3f"));
    kv("sim time [s]", num(sim_->time(), "%.3f"));
    kv("dt [s]", num(sim_->dt()));
    kv("constraint error [m]", num(sim_->constraintError(), "%.3e"));
    kv("max constraint error [m]", num(sim_->maxConstraintError(), "%.3e"));
    kv("energy [J]", num(sim_->totalEnergy(), "%.6e"));
    kv("energy balance error (relative)", num(sim_->energyDrift(), "%.3e"));
    const riser_sim::PointMotion top = motion_->at(sim_->time());
    kv("hang-off x [m]", num(top.p.x(), "%.4f"));
    kv("hang-off z [m]", num(top.p.y(), "%.4f"));
    char buf[160];
    std::snprintf(buf, sizeof(buf), "running: real-time factor %s (compute %sx real time)", num(rtf, "%.2f").c_str(),
                  num(compute_rtf, "%.1f").c_str());
    message = buf;
    if (win_dropped_ > 0.0 || (std::isfinite(rtf) && rtf < 0.95)) {
      st.level = DiagnosticStatus::WARN;
      message = "falling behind real time: " + message + ", dropped " + num(win_dropped_, "%.3f") + " s";
    } else if (std::isfinite(pose_age) && pose_age > params_.pose_timeout) {
      st.level = DiagnosticStatus::WARN;
      message = "no vessel pose for " + num(pose_age, "%.1f") + " s: holding the last one";
    }
  } else if (mode_ == Mode::kWaiting) {
    st.level = DiagnosticStatus::WARN;
    message = "waiting for the first valid vessel pose (" + input_->source() + ")";
    if (!clock_note_.empty()) message = clock_note_ + ": simulation reset; " + message;
  } else {
    st.level = DiagnosticStatus::ERROR;
    message = (mode_ == Mode::kDiverged ? "integration diverged: " : "") + reason_ + "; publishing stopped, call " +
              name_ + "/reset";
    kv("reason", reason_);
  }
  if (clock_resets_ > 0) {
    kv("ROS time jumps back", std::to_string(clock_resets_));
    kv("last ROS time jump", clock_note_);
  }
  if (stalled_) {
    const double still = seconds(Clock::now() - last_advance_);
    kv("ROS time still for [s] (wall)", num(still, "%.1f"));
    if (st.level < DiagnosticStatus::WARN) st.level = DiagnosticStatus::WARN;
    message = "paused: ROS time has not advanced for " + num(still, "%.1f") + " s of wall time (" +
              (now.isZero() ? "no /clock yet" : "/clock stalled") + "); " + message;
  }
  st.message = message;
  diag_pub_.publish(diag_);
  if (sim_) resetWindow(now);
}

bool RiserSimNode::onModes(riser_sim::Modes::Request& req, riser_sim::Modes::Response& res) {
  std::shared_ptr<const StaticState> state;
  {
    std::lock_guard<std::mutex> lock(static_mutex_);
    state = static_state_;
    if (!state) {
      res.success = false;
      res.message = static_failure_.empty() ? "no static state yet: waiting for the first valid vessel pose (" +
                                                  input_->source() + ")"
                                            : "no static state: " + static_failure_;
      return true;
    }
  }
  const Clock::time_point t0 = Clock::now();
  computeModesResponse(state->scene, state->kin, state->end_force, req.count, res);
  res.header.stamp = state->stamp;
  res.header.frame_id = params_.fixed_frame;
  ROS_INFO("%s: ~modes (count %d): %s (%.1f ms)", name_.c_str(), req.count, res.message.c_str(), seconds(Clock::now() - t0) * 1e3);
  return true;
}

bool RiserSimNode::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> call(reset_call_mutex_);  // one reset at a time
  std::unique_lock<std::mutex> lock(reset_mutex_);
  reset_requested_ = true;
  reset_done_ = false;
  if (!reset_cv_.wait_for(lock, std::chrono::seconds(30), [this] { return reset_done_; })) {
    reset_requested_ = false;
    res.success = false;
    res.message = "timed out waiting for the integration loop";
    return true;
  }
  res.success = reset_ok_;
  res.message = reset_message_;
  return true;
}

void RiserSimNode::serveReset(const ros::Time& now) {
  {
    std::lock_guard<std::mutex> lock(reset_mutex_);
    if (!reset_requested_) return;
    reset_requested_ = false;
  }
  VesselSample s;
  bool ok = false;
  std::string message;
  if (now.isZero()) {
    message = "no ROS time yet (/use_sim_time is set and nothing publishes /clock)";
  } else if (!samples_.latest(s)) {
    message = "no valid vessel pose received yet (" + input_->source() + ")";
  } else {
    samples_.drain(drained_);  // older than s: the new start supersedes them
    ok = start(s, now, message);
    ROS_INFO("%s: ~reset: %s", name_.c_str(), message.c_str());
  }
  {
    std::lock_guard<std::mutex> lock(reset_mutex_);
    reset_done_ = true;
    reset_ok_ = ok;
    reset_message_ = message;
  }
  reset_cv_.notify_all();
}

}  // namespace riser_sim_ros
