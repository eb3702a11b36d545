#include "riser_sim_ros/modes_service.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "riser_sim/run/modes_report.h"

namespace riser_sim_ros {

void computeModesResponse(const riser_sim::Scene& scene, int count, riser_sim::Modes::Response& res) {
  res.success = false;
  if (count < 1) {  // before any statics
    res.message = "count: must be >= 1, got " + std::to_string(count);
    return;
  }
  riser_sim::ModesReport r;
  try {
    r = riser_sim::sceneModesReport(scene, count);
  } catch (const std::exception& e) {
    res.message = std::string("modal analysis failed: ") + e.what();
    return;
  }
  res.dofs = r.dofs;
  res.equilibrium_residual = r.equilibrium_residual;
  if (count > r.dofs) {
    res.message = "count: must be <= " + std::to_string(r.dofs) + " (the degrees of freedom of this line), got " +
                  std::to_string(count);
    return;
  }
  res.arc_length = r.arc_length;
  res.points.resize(r.points.size());
  for (size_t p = 0; p < r.points.size(); ++p)
    res.points[p].x = r.points[p].x(), res.points[p].y = r.points[p].y(), res.points[p].z = r.points[p].z();
  for (const riser_sim::ModeEntry& m : r.modes) {
    const bool oscillates = m.status == riser_sim::ModeStatus::kOscillating;
    res.periods.push_back(oscillates ? m.period : 0.0);
    res.frequencies.push_back(oscillates ? m.frequency : 0.0);
    res.characters.push_back(m.character);
    res.axial_share.push_back(m.axial_share);
    for (const Eigen::Vector3d& d : m.displacement) {
      res.shape_x.push_back(d.x());
      res.shape_y.push_back(d.y());
      res.shape_z.push_back(d.z());
    }
  }
  for (const auto* v : {&res.periods, &res.frequencies, &res.axial_share, &res.shape_x, &res.shape_y, &res.shape_z})
    for (double x : *v)
      if (!std::isfinite(x)) {
        res.message = "modal analysis gave non-finite values (ill-conditioned state?)";
        res.periods.clear(), res.frequencies.clear(), res.characters.clear(), res.axial_share.clear();
        res.shape_x.clear(), res.shape_y.clear(), res.shape_z.clear();
        return;
      }
  res.message = std::to_string(r.modes.size()) + " modes of " + std::to_string(r.dofs) + ": " + r.header +
                (r.equilibrium_residual > 1e-6 ? " (not an equilibrium: modes not meaningful)" : "");
  res.success = true;
}

ModesServer::ModesServer(ros::NodeHandle pnh, std::string name, std::string frame, std::string waiting_for)
    : name_(std::move(name)), frame_(std::move(frame)), waiting_for_(std::move(waiting_for)) {
  pnh.setCallbackQueue(&queue_);
  srv_ = pnh.advertiseService("modes", &ModesServer::onModes, this);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
}

ModesServer::~ModesServer() {
  spinner_->stop();
  srv_.shutdown();
}

void ModesServer::setState(const riser_sim::Scene& scene, const ros::Time& stamp) {
  auto state = std::make_shared<StaticState>();
  state->scene = scene;
  state->stamp = stamp;
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = std::move(state);
}

void ModesServer::setFailure(const std::string& why) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!state_) failure_ = why;
}

bool ModesServer::onModes(riser_sim::Modes::Request& req, riser_sim::Modes::Response& res) {
  std::shared_ptr<const StaticState> state;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = state_;
    if (!state) {
      res.success = false;
      res.message = failure_.empty()
                        ? "no static state yet: waiting for the first valid vessel pose (" + waiting_for_ + ")"
                        : "no static state: " + failure_;
      return true;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  computeModesResponse(state->scene, req.count, res);
  res.header.stamp = state->stamp;
  res.header.frame_id = frame_;
  ROS_INFO("%s: ~modes (count %d): %s (%.1f ms)", name_.c_str(), req.count, res.message.c_str(),
           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  return true;
}

}  // namespace riser_sim_ros
