#include "riser_sim_ros/node_run.h"

#include "riser_sim_ros/node_diagnostics.h"

namespace riser_sim_ros {

namespace {
using riser_sim::Holder;

std::unique_ptr<riser_sim::LineRun> build(const riser_sim::Scene& scene, const VesselSample& s, double t,
                                          const NodeParams& params, const VesselSample* bottom, double t_bottom) {
  riser_sim::LineRunInputs in;
  in.top = riser_sim::HolderStart{s.hangoff, s.orientation, t};
  if (bottom) in.bottom = riser_sim::HolderStart{bottom->hangoff, bottom->orientation, t_bottom};
  in.motion = params.motion;
  return riser_sim::buildLineRun(scene, in);
}

// The markers' sizes as LineMarkers takes them from ~markers (0: automatic).
double lineWidth(const riser_sim::Scene& scene, const MarkerParams& m) {
  return m.line_width > 0.0 ? m.line_width : scene.length / 150.0;
}
double nodeScale(const riser_sim::Scene& scene, const MarkerParams& m) {
  return m.node_scale > 0.0 ? m.node_scale : 2.5 * lineWidth(scene, m);
}
double textHeight(const riser_sim::Scene& scene, const MarkerParams& m) {
  return m.text_height > 0.0 ? m.text_height : scene.length / 25.0;
}

bool isPinned3(const riser_sim::Scene& scene) {
  return scene.space == riser_sim::SpaceKind::kSpatial && scene.bottom == riser_sim::BottomBoundary::kPinned;
}

std::string point(const riser_sim::Scene& scene, const Eigen::Vector3d& p, const char* format) {
  if (scene.space == riser_sim::SpaceKind::kSpatial)
    return "(x " + num(p.x(), format) + ", y " + num(p.y(), format) + ", z " + num(p.z(), format) + ")";
  return "(x " + num(p.x(), format) + ", z " + num(p.z(), format) + ")";
}
}  // namespace

NodeRun::NodeRun(const riser_sim::Scene& scene, const VesselSample& s, double t, const NodeParams& params,
                 const VesselSample* bottom, double t_bottom)
    : run_(build(scene, s, t, params, bottom, t_bottom)),
      vessel_(s.orientation),
      rov_(bottom ? bottom->orientation : Eigen::Quaterniond::Identity()),
      pinned_(isPinned3(scene)),
      msgs_(scene.elements + 1, params.fixed_frame, params.tf_prefix, params.wrench_frame == "body",
            params.vessel_frame, bottom && params.wrench_frame == "body", params.bottom_frame),
      markers_(scene.length, scene.elements + 1, scene.end_mass > 0.0, params.fixed_frame, params.markers,
               surfacesOf(scene)),
      sections_(sectionLayout(scene), 4.0 * lineWidth(scene, params.markers), params.fixed_frame, markers_.msg),
      attachments_(scene, 2.0 * nodeScale(scene, params.markers), lineWidth(scene, params.markers),
                   textHeight(scene, params.markers), params.fixed_frame, markers_.msg) {
  if (spatial()) sea_ = std::make_unique<SeaMarkers>(scene, params.fixed_frame, markers_.msg);
  msgs_.setLayout(sectionLayout(scene), scene);
  const auto rate = params.rates.find("range_graph");
  if (rate != params.rates.end() && rate->second > 0.0)
    range_ = std::make_unique<RangeWindow>(run_->outputs(), riser_sim::seabedPlane(scene), params.range_window,
                                           params.fixed_frame);
}

bool NodeRun::step() {
  if (!run_->step()) return false;
  if (range_) range_->add(run_->outputs(), shifted_);
  return true;
}

const riser_sim::RangeEnvelope* NodeRun::rangeEnvelope(const ros::Time& stamp) {
  if (!range_ || !range_->fill(stamp)) return nullptr;
  return &range_->msg;
}

void NodeRun::clearRangeGraph() {
  if (range_) range_->clear();
}

void NodeRun::restartMotion(double t, const VesselSample& s) {
  run_->restartHolder(Holder::kTop, t, s.hangoff, s.orientation);
  vessel_ = s.orientation;
}

void NodeRun::restartBottom(double t, const VesselSample& s) {
  if (!drivenBottom()) return;
  run_->restartHolder(Holder::kBottom, t, s.hangoff, s.orientation);
  rov_ = s.orientation;
}

bool NodeRun::addSample(double t_sample, const VesselSample& s) {
  if (!run_->addSample(Holder::kTop, t_sample, s.hangoff, s.orientation)) return false;
  vessel_ = s.orientation;
  return true;
}

bool NodeRun::addBottomSample(double t_sample, const VesselSample& s) {
  if (!run_->addSample(Holder::kBottom, t_sample, s.hangoff, s.orientation)) return false;
  rov_ = s.orientation;
  return true;
}

std::string NodeRun::startMessage() {
  const riser_sim::RunOutputs& o = run_->outputs();
  const riser_sim::Scene& scene = run_->heldScene();
  const std::string bottom = drivenBottom()
                                 ? ", bottom driven from (" + num(o.bottom_point.x(), "%.3f") + ", " +
                                       num(o.bottom_point.y(), "%.3f") + ", " + num(o.bottom_point.z(), "%.3f") + ") m"
                                 : std::string();
  const Eigen::Vector3d top =
      spatial() ? scene.top.position : riser_sim::inSpace(riser_sim::inPlane(scene.top.position));
  return (run_->start().equilibrium ? "static equilibrium" : run_->start().about) + " at hang-off " +
         point(scene, top, "%.3f") + " m" + bottom + (spatial() ? " (3D)" : "") + ": top tension " +
         num(o.top_tension, "%.1f") + " N; running";
}

RunHealth NodeRun::health() {
  RunHealth h;
  const riser_sim::RunOutputs& o = run_->outputs();
  h.constraint_error = o.constraint_error;
  h.max_constraint_error = run_->maxConstraintError();
  h.energy = o.energy;
  h.energy_drift = o.energy_drift;
  h.noise = run_->forceNoise().recent();
  h.force_warning = run_->forceWarning(h.noise);
  h.hangoff = o.top_point;
  h.gaps = run_->gaps(Holder::kTop);
  h.bottom_gaps = run_->gaps(Holder::kBottom);
  return h;
}

bool NodeRun::evaluate() {
  out_ = &run_->outputs();
  return riser_sim::allFinite(*out_);
}

const riser_sim::Tension& NodeRun::tension(const ros::Time& stamp) {
  msgs_.fillTension(*out_, stamp);
  return msgs_.tension;
}

const riser_sim::LineState& NodeRun::state(const ros::Time& stamp) {
  msgs_.fillState(*out_, stamp);
  return msgs_.state;
}

const geometry_msgs::WrenchStamped& NodeRun::topWrench(const ros::Time& stamp) {
  msgs_.fillTopWrench(*out_, vessel_, stamp);
  return msgs_.top_wrench;
}

const geometry_msgs::WrenchStamped* NodeRun::bottomWrench(const ros::Time& stamp) {
  if (!pinned_) return nullptr;
  msgs_.fillBottomWrench(*out_, rov_, stamp);
  return &msgs_.bottom_wrench;
}

const std::vector<geometry_msgs::TransformStamped>& NodeRun::transforms(const ros::Time& stamp) {
  msgs_.fillTransforms(*out_, stamp);
  return msgs_.transforms;
}

const visualization_msgs::MarkerArray& NodeRun::markers(const ros::Time& stamp) {
  markers_.fill(*out_, stamp);
  sections_.fill(*out_, markers_.msg);
  attachments_.fill(*out_, markers_.msg);
  if (sea_) sea_->fill(*out_, markers_.msg);
  return markers_.msg;
}

std::string describeHangoff(const riser_sim::Scene& scene, const Eigen::Vector3d& p) {
  if (scene.space == riser_sim::SpaceKind::kSpatial)
    return "(" + num(p.x()) + ", " + num(p.y()) + ", " + num(p.z()) + ")";
  return "(" + num(p.x()) + ", " + num(p.z()) + ")";
}

}  // namespace riser_sim_ros
