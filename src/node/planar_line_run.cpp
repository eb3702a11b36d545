#include "riser_sim_ros/planar_line_run.h"

#include "riser_sim_ros/modes_service.h"
#include "riser_sim_ros/node_diagnostics.h"

namespace riser_sim_ros {

namespace {
riser_sim::Scene fixedTop(riser_sim::Scene scene, const Eigen::Vector2d& top) {
  scene.top.type = riser_sim::MotionKind::kFixed;
  scene.top.position = top;
  return scene;
}

riser_sim::Run build(const riser_sim::Scene& scene, const Eigen::Vector2d& top, double t, const NodeParams& params) {
  riser_sim::RunInputs in;
  in.top = top;
  in.motion = std::make_unique<riser_sim::ExternalMotion>(top, t, params.motion);
  return riser_sim::buildRun(scene, std::move(in));
}
}  // namespace

PlanarLineRun::PlanarLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t, const NodeParams& params)
    : scene_(fixedTop(scene, toPaper(s.hangoff))), run_(build(scene_, toPaper(s.hangoff), t, params)),
      sim_(run_.sim.get()), motion_(static_cast<riser_sim::ExternalMotion*>(&sim_->topMotion())),
      msgs_(*run_.model, params.fixed_frame, params.tf_prefix),
      markers_(*run_.model, params.fixed_frame, params.markers, surfacesOf(scene)) {}

std::string PlanarLineRun::startMessage() {
  const Eigen::Vector2d top = scene_.top.position;
  return (run_.initial.equilibrium ? "static equilibrium" : run_.initial.about) + " at hang-off (x " +
         num(top.x(), "%.3f") + ", z " + num(top.y(), "%.3f") + ") m: top tension " +
         num(sim_->outputs().top_tension, "%.1f") + " N; running";
}

void PlanarLineRun::shareStatics(ModesServer& modes, const ros::Time& stamp) {
  modes.setState(scene_, stamp);  // the top fixed at the hang-off (fixedTop)
}

RunHealth PlanarLineRun::health() {
  RunHealth h;
  h.constraint_error = sim_->constraintError();
  h.max_constraint_error = sim_->maxConstraintError();
  h.energy = sim_->totalEnergy();
  h.energy_drift = sim_->energyDrift();
  h.noise = sim_->forceNoise().recent();
  h.force_warning = sim_->forceWarning(h.noise);
  const riser_sim::PointMotion top = motion_->at(sim_->time());
  h.hangoff = Eigen::Vector3d(top.p.x(), 0.0, top.p.y());
  h.gaps = motion_->gaps();
  return h;
}

bool PlanarLineRun::evaluate() {
  out_ = &sim_->outputs();
  return outputsFinite(*out_);
}

const riser_sim::Tension& PlanarLineRun::tension(const ros::Time& stamp) {
  msgs_.fillTension(*out_, stamp);
  return msgs_.tension;
}

const riser_sim::LineState& PlanarLineRun::state(const ros::Time& stamp) {
  msgs_.fillState(*out_, stamp);
  return msgs_.state;
}

const geometry_msgs::WrenchStamped& PlanarLineRun::topWrench(const ros::Time& stamp) {
  msgs_.fillWrench(*out_, stamp);
  return msgs_.wrench;
}

const std::vector<geometry_msgs::TransformStamped>& PlanarLineRun::transforms(const ros::Time& stamp) {
  msgs_.fillTransforms(*out_, stamp);
  return msgs_.transforms;
}

const visualization_msgs::MarkerArray& PlanarLineRun::markers(const ros::Time& stamp) {
  markers_.fill(*out_, stamp);
  return markers_.msg;
}

}  // namespace riser_sim_ros
