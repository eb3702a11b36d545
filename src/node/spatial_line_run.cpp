#include "riser_sim_ros/spatial_line_run.h"

#include <cmath>

#include "riser_sim_ros/modes_service.h"
#include "riser_sim_ros/node_diagnostics.h"

namespace riser_sim_ros {

namespace {
using riser_sim::spatial::ExternalMotion3;
using riser_sim::spatial::SpatialRun;

std::unique_ptr<SpatialRun> build(riser_sim::Scene scene, const VesselSample& s, double t,
                                  const NodeParams& params, ExternalMotion3*& motion,
                                  std::shared_ptr<ExternalMotion3>& bottom_motion, const VesselSample* bottom,
                                  double t_bottom) {
  scene.top.type = riser_sim::MotionKind::kFixed;
  scene.top.position3 = s.hangoff;
  riser_sim::spatial::RunInputs3 in;
  in.top = s.hangoff;
  // With the attitude: flex joints turn with the vessel and the ROV.
  auto m = std::make_unique<ExternalMotion3>(s.hangoff, s.orientation, t, params.motion);
  motion = m.get();
  in.motion = std::move(m);
  if (bottom) {
    bottom_motion = std::make_shared<ExternalMotion3>(bottom->hangoff, bottom->orientation, t_bottom, params.motion);
    in.bottom_motion = bottom_motion;
  }
  return std::make_unique<SpatialRun>(scene, std::move(in));
}
}  // namespace

SpatialLineRun::SpatialLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t,
                               const NodeParams& params, const VesselSample* bottom, double t_bottom)
    : scene_(scene), top_(s.hangoff), run_(build(scene, s, t, params, motion_, bottom_motion_, bottom, t_bottom)),
      vessel_(s.orientation), rov_(bottom ? bottom->orientation : Eigen::Quaterniond::Identity()),
      pinned_(scene.bottom == riser_sim::BottomBoundary::kPinned),
      msgs_(run_->model(), params.fixed_frame, params.tf_prefix, params.wrench_frame == "body", params.vessel_frame,
            bottom && params.wrench_frame == "body", params.bottom_frame),
      markers_(run_->model().line(), params.fixed_frame, params.markers, surfacesOf3(scene)),
      sea_(scene, params.fixed_frame, markers_.msg),
      kin_(run_->model().bodies()) {}

void SpatialLineRun::restartMotion(double t, const VesselSample& s) {
  motion_->reset(t, s.hangoff, s.orientation);
  vessel_ = s.orientation;
}

bool SpatialLineRun::addSample(double t_sample, const VesselSample& s) {
  if (!motion_->addSample(t_sample, s.hangoff, s.orientation, run_->time())) return false;
  vessel_ = s.orientation;
  return true;
}

void SpatialLineRun::shiftSampleTimes(double dt) {
  motion_->shiftSampleTimes(dt);
  if (bottom_motion_) bottom_motion_->shiftSampleTimes(dt);
}

void SpatialLineRun::restartBottom(double t, const VesselSample& s) {
  if (!bottom_motion_) return;
  bottom_motion_->reset(t, s.hangoff, s.orientation);
  rov_ = s.orientation;
}

bool SpatialLineRun::addBottomSample(double t_sample, const VesselSample& s) {
  if (!bottom_motion_ || !bottom_motion_->addSample(t_sample, s.hangoff, s.orientation, run_->time())) return false;
  rov_ = s.orientation;
  return true;
}

std::string SpatialLineRun::startMessage() {
  const riser_sim::spatial::InitialState3& init = run_->initial();
  const riser_sim::spatial::LineOutputs3& o = run_->outputs();
  const std::string bottom = bottom_motion_ ? ", bottom driven from (" + num(o.bottom_point.x(), "%.3f") + ", " +
                                                  num(o.bottom_point.y(), "%.3f") + ", " +
                                                  num(o.bottom_point.z(), "%.3f") + ") m"
                                            : std::string();
  return (init.equilibrium ? "static equilibrium" : init.about) + " at hang-off (x " + num(top_.x(), "%.3f") +
         ", y " + num(top_.y(), "%.3f") + ", z " + num(top_.z(), "%.3f") + ") m" + bottom + " (3D): top tension " +
         num(o.top_tension, "%.1f") + " N; running";
}

void SpatialLineRun::shareStatics(ModesServer& modes, const ros::Time& stamp) {
  // The modes hold the top at the hang-off and a driven bottom where it started.
  riser_sim::Scene s = scene_;
  s.top.type = riser_sim::MotionKind::kFixed;
  s.top.position3 = top_;
  if (bottom_motion_) {
    s.bottom_motion.type = riser_sim::MotionKind::kFixed;
    s.bottom_point3 = s.bottom_motion.position3 = run_->initial().kin.back().end();
  }
  modes.setState(s, stamp);
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
  h.gaps = motion_->gaps();
  if (bottom_motion_) h.bottom_gaps = bottom_motion_->gaps();
  return h;
}

bool SpatialLineRun::evaluate() {
  out_ = &run_->outputs();
  run_->simulator().kinematics(kin_);  // sized once: fills in place
  for (const auto& b : kin_)
    if (!b.A.allFinite() || !b.e.allFinite() || !b.e_dot.allFinite() || !std::isfinite(b.delta)) return false;
  return outputsFinite(*out_);
}

const riser_sim::Tension& SpatialLineRun::tension(const ros::Time& stamp) {
  msgs_.fillTension(*out_, stamp);
  return msgs_.tension;
}

const riser_sim::LineState& SpatialLineRun::state(const ros::Time& stamp) {
  msgs_.fillState(*out_, kin_, stamp);
  return msgs_.state;
}

const geometry_msgs::WrenchStamped& SpatialLineRun::topWrench(const ros::Time& stamp) {
  msgs_.fillTopWrench(*out_, vessel_, stamp);
  return msgs_.top_wrench;
}

const geometry_msgs::WrenchStamped* SpatialLineRun::bottomWrench(const ros::Time& stamp) {
  if (!pinned_) return nullptr;
  msgs_.fillBottomWrench(*out_, rov_, stamp);
  return &msgs_.bottom_wrench;
}

const std::vector<geometry_msgs::TransformStamped>& SpatialLineRun::transforms(const ros::Time& stamp) {
  const riser_sim::spatial::SpatialSimulator& sim = run_->simulator();
  if (run_->model().hasTorsion())  // θ_i follow q in the state (simulator.h)
    msgs_.fillTransforms(*out_, kin_, sim.state().data() + run_->model().dofs(), sim.lastEvaluation().twist.frames,
                         stamp);
  else
    msgs_.fillTransforms(*out_, stamp);
  return msgs_.transforms;
}

const visualization_msgs::MarkerArray& SpatialLineRun::markers(const ros::Time& stamp) {
  markers_.fill(*out_, stamp);
  sea_.fill(*out_, markers_.msg);
  return markers_.msg;
}

}  // namespace riser_sim_ros
