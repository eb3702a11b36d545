#include "riser_sim_ros/modes_service.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "riser_sim/modal.h"
#include "riser_sim/model.h"
#include "riser_sim/run_builder.h"

namespace riser_sim_ros {

void computeModesResponse(const riser_sim::Scene& scene, const riser_sim::Kinematics& kin,
                          const riser_sim::Vec2& end_force, int count, riser_sim::Modes::Response& res) {
  res.success = false;
  if (count < 1) {
    res.message = "count: must be >= 1, got " + std::to_string(count);
    return;
  }
  riser_sim::ModalOptions o;
  o.modes = count;
  riser_sim::ModalResult r;
  std::string about = std::string(riser_sim::name(scene.initial.type)) + " static state";
  try {
    if (scene.initial.type == riser_sim::InitialKind::kStraight) {
      r = riser_sim::sceneModes(scene, o);  // solves the hanging statics (a straight line is none)
      about = "hanging equilibrium (initial.type straight is not one)";
    } else {
      r = riser_sim::computeModes(*riser_sim::buildModel(scene), kin, end_force, o);
    }
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
  const size_t np = r.points.size();
  res.arc_length = r.arc_length;
  res.points.resize(np);
  for (size_t p = 0; p < np; ++p) {
    res.points[p].x = r.points[p].x();  // paper (x, y) -> world (x, 0, z)
    res.points[p].z = r.points[p].y();
  }
  for (const riser_sim::Mode& m : r.modes) {
    res.periods.push_back(m.period);
    res.frequencies.push_back(m.frequency);
    res.characters.push_back(m.character);
    res.axial_share.push_back(m.axial_fraction);
    for (const riser_sim::Vec2& d : m.displacement) {
      res.shape_x.push_back(d.x());
      res.shape_z.push_back(d.y());
      res.shape_y.push_back(0.0);
    }
  }
  for (const auto* v : {&res.periods, &res.frequencies, &res.axial_share, &res.shape_x, &res.shape_z})
    for (double x : *v)
      if (!std::isfinite(x)) {
        res.message = "modal analysis gave non-finite values (ill-conditioned state?)";
        res.periods.clear(), res.frequencies.clear(), res.characters.clear(), res.axial_share.clear();
        res.shape_x.clear(), res.shape_z.clear(), res.shape_y.clear();
        return;
      }
  char buf[320];
  std::snprintf(buf, sizeof(buf),
                "%d modes of %d about the %s; end load (%g, %g) N kept as a dead load; undamped (drag and damping "
                "left out); equilibrium residual %.2e%s",
                static_cast<int>(r.modes.size()), r.dofs, about.c_str(), end_force.x(), end_force.y(),
                r.equilibrium_residual, r.equilibrium_residual > 1e-6 ? " (not an equilibrium: modes not meaningful)" : "");
  res.message = buf;
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

void ModesServer::setState(const riser_sim::Scene& scene, const riser_sim::Kinematics& kin,
                           const riser_sim::Vec2& end_force, const ros::Time& stamp) {
  auto state = std::make_shared<StaticState>();
  state->scene = scene;
  state->kin = kin;
  state->end_force = end_force;
  state->stamp = stamp;
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = std::move(state);
}

void ModesServer::setState3(const riser_sim::Scene& scene, const riser_sim::spatial::InitialState3& initial,
                            const ros::Time& stamp) {
  auto state = std::make_shared<StaticState>();
  state->scene = scene;
  state->initial3 = std::make_shared<riser_sim::spatial::InitialState3>(initial);
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
      res.message = failure_.empty() ? "no static state yet: waiting for the first valid vessel pose (" + waiting_for_ + ")"
                                     : "no static state: " + failure_;
      return true;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  if (state->initial3) computeModesResponse3(state->scene, *state->initial3, req.count, res);
  else computeModesResponse(state->scene, state->kin, state->end_force, req.count, res);
  res.header.stamp = state->stamp;
  res.header.frame_id = frame_;
  ROS_INFO("%s: ~modes (count %d): %s (%.1f ms)", name_.c_str(), req.count, res.message.c_str(),
           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  return true;
}

}  // namespace riser_sim_ros
