#include "riser_sim_ros/spatial_line_run.h"

#include "riser_sim_ros/modes_service.h"
#include "riser_sim_ros/node_diagnostics.h"

namespace riser_sim_ros {

namespace {
using riser_sim::spatial::ExternalMotion3;
using riser_sim::spatial::SpatialRun;

std::unique_ptr<SpatialRun> build(riser_sim::Scene scene, const Eigen::Vector3d& top, double t,
                                  const NodeParams& params, ExternalMotion3*& motion) {
  scene.top.type = riser_sim::MotionKind::kFixed;
  scene.top.position3 = top;
  riser_sim::spatial::RunInputs3 in;
  in.top = top;
  auto m = std::make_unique<ExternalMotion3>(top, t, params.motion);
  motion = m.get();
  in.motion = std::move(m);
  return std::make_unique<SpatialRun>(scene, std::move(in));
}
}  // namespace

SpatialLineRun::SpatialLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t,
                               const NodeParams& params)
    : top_(s.hangoff), run_(build(scene, s.hangoff, t, params, motion_)), vessel_(s.orientation),
      pinned_(scene.bottom == riser_sim::BottomBoundary::kPinned),
      msgs_(run_->model(), params.fixed_frame, params.tf_prefix, params.wrench_frame == "body", params.vessel_frame),
      markers_(run_->model().line(), params.fixed_frame, params.markers, surfacesOf(scene)) {}

void SpatialLineRun::restartMotion(double t, const VesselSample& s) {
  motion_->reset(t, s.hangoff);
  vessel_ = s.orientation;
}

bool SpatialLineRun::addSample(double t_sample, const VesselSample& s) {
  if (!motion_->addSample(t_sample, s.hangoff, run_->time())) return false;
  vessel_ = s.orientation;
  return true;
}

std::string SpatialLineRun::startMessage() {
  const riser_sim::spatial::InitialState3& init = run_->initial();
  return (init.equilibrium ? "static equilibrium" : init.about) + " at hang-off (x " + num(top_.x(), "%.3f") +
         ", y " + num(top_.y(), "%.3f") + ", z " + num(top_.z(), "%.3f") + ") m (3D): top tension " +
         num(run_->outputs().top_tension, "%.1f") + " N; running";
}

void SpatialLineRun::shareStatics(ModesServer& modes, const ros::Time&) {
  modes.setFailure("~modes is planar only; for space: spatial use riser_sim_cli --modes");
}

RunHealth SpatialLineRun::health() {
  RunHealth h;
  riser_sim::spatial::SpatialSimulator& sim = run_->simulator();
  h.constraint_error = sim.constraintError();
  h.max_constraint_error = run_->maxConstraintError();
  h.energy = sim.energy();
  h.energy_drift = run_->energyDrift();
  h.noise = run_->forceNoise().recent();
  h.force_warning = run_->forceWarning(h.noise);
  h.hangoff = motion_->at(run_->time()).p;
  return h;
}

bool SpatialLineRun::evaluate() {
  out_ = &run_->outputs();
  return outputsFinite(*out_);
}

const riser_sim::Tension& SpatialLineRun::tension(const ros::Time& stamp) {
  msgs_.fillTension(*out_, stamp);
  return msgs_.tension;
}

const riser_sim::LineState& SpatialLineRun::state(const ros::Time& stamp) {
  msgs_.fillState(*out_, stamp);
  return msgs_.state;
}

const geometry_msgs::WrenchStamped& SpatialLineRun::topWrench(const ros::Time& stamp) {
  msgs_.fillTopWrench(*out_, vessel_, stamp);
  return msgs_.top_wrench;
}

const geometry_msgs::WrenchStamped* SpatialLineRun::bottomWrench(const ros::Time& stamp) {
  if (!pinned_) return nullptr;
  msgs_.fillBottomWrench(*out_, stamp);
  return &msgs_.bottom_wrench;
}

const std::vector<geometry_msgs::TransformStamped>& SpatialLineRun::transforms(const ros::Time& stamp) {
  msgs_.fillTransforms(*out_, stamp);
  return msgs_.transforms;
}

const visualization_msgs::MarkerArray& SpatialLineRun::markers(const ros::Time& stamp) {
  markers_.fill(*out_, stamp);
  return markers_.msg;
}

}  // namespace riser_sim_ros
