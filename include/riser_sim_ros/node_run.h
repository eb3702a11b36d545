// The run the node steps: the core's LineRun (either engine, riser_sim/run/line_run.h) with its top, and a driven
// bottom, fed live from the vessel's (the ROV's) pose samples, and its outputs turned into the node's messages
// (LineMessages, LineMarkers with SectionMarkers, AttachmentMarkers and, in 3D, SeaMarkers; RangeWindow), sized
// once and filled in place. The node and its topics see only this.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/LineState.h"
#include "riser_sim/RangeEnvelope.h"
#include "riser_sim/Tension.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim_ros/attachment_markers.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/range_window.h"
#include "riser_sim_ros/sea_markers.h"
#include "riser_sim_ros/section_layout.h"
#include "riser_sim_ros/section_markers.h"
#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

// What /diagnostics reports of a running line.
struct RunHealth {
  double constraint_error = 0.0, max_constraint_error = 0.0;  // [m]
  double energy = 0.0, energy_drift = 0.0;                    // [J], relative
  riser_sim::ForceNoise noise;                                // last 10 s
  std::string force_warning;                                  // empty: forces resolved
  Eigen::Vector3d hangoff = Eigen::Vector3d::Zero();          // A_0 now, fixed_frame [m]
  riser_sim::MotionGaps gaps, bottom_gaps;                    // of the vessel's (a driven bottom's) samples
};

class NodeRun {
 public:
  // The run of `scene` hanging from s's hang-off, its top fed from sim time t; with `bottom` (3D, pinned) the
  // bottom too, from its attachment point at sim time t_bottom. Throws as riser_sim::buildLineRun
  // (std::invalid_argument, std::runtime_error: statics).
  NodeRun(const riser_sim::Scene& scene, const VesselSample& s, double t, const NodeParams& params,
          const VesselSample* bottom = nullptr, double t_bottom = 0.0);

  bool spatial() const { return run_->spatial(); }
  // The top (the driven bottom) restarts at rest at s's point at sim time t (after the node fixed its time origin).
  void restartMotion(double t, const VesselSample& s);
  void restartBottom(double t, const VesselSample& s);
  // A sample stamped t_sample [s of sim time], applied now. False when the motion refused it.
  bool addSample(double t_sample, const VesselSample& s);
  bool addBottomSample(double t_sample, const VesselSample& s);
  void shiftSampleTimes(double dt) {  // dropped backlog: the samples' times and the stamps move on by dt
    run_->shiftSampleTimes(dt);
    shifted_ += dt;
  }
  bool drivenBottom() const { return run_->live(riser_sim::Holder::kBottom); }
  // One solver step (false once diverged); with ~range_graph on, its outputs are a range-graph sample.
  bool step();
  const std::string& divergenceReason() const { return run_->divergenceReason(); }
  double time() const { return run_->time(); }
  double dt() const { return run_->dt(); }
  std::string stepAboveLimit() const { return run_->stepAboveLimit(); }  // empty, or why dt is above the limit
  std::string startMessage();  // "static equilibrium at hang-off (...) m: top tension ..."
  // The scene with the top fixed at the hang-off (and a driven bottom where it started): what ~modes analyses.
  const riser_sim::Scene& heldScene() const { return run_->heldScene(); }
  RunHealth health();

  // Evaluates the outputs of the current state: false when any is non-finite (then nothing is published).
  bool evaluate();
  // The messages of the last evaluate(), stamped.
  const riser_sim::Tension& tension(const ros::Time& stamp);
  const riser_sim::LineState& state(const ros::Time& stamp);
  const geometry_msgs::WrenchStamped& topWrench(const ros::Time& stamp);
  const geometry_msgs::WrenchStamped* bottomWrench(const ros::Time& stamp);  // null: no pinned bottom
  const std::vector<geometry_msgs::TransformStamped>& transforms(const ros::Time& stamp);
  const visualization_msgs::MarkerArray& markers(const ros::Time& stamp);
  // The range graph over its window, stamped (the current time); null when ~range_graph is off or a value is
  // not finite.
  const riser_sim::RangeEnvelope* rangeEnvelope(const ros::Time& stamp);
  void clearRangeGraph();  // its next sample starts a new window

 private:
  std::unique_ptr<riser_sim::LineRun> run_;
  const riser_sim::RunOutputs* out_ = nullptr;                  // of the last evaluate()
  Eigen::Quaterniond vessel_ = Eigen::Quaterniond::Identity();  // orientation of the latest vessel sample
  Eigen::Quaterniond rov_ = Eigen::Quaterniond::Identity();     // of the latest bottom sample
  bool pinned_;                                                 // a 3D pinned bottom: ~bottom_wrench
  LineMessages msgs_;
  LineMarkers markers_;
  SectionMarkers sections_;             // appended to markers_.msg
  AttachmentMarkers attachments_;       // appended to markers_.msg
  std::unique_ptr<SeaMarkers> sea_;     // 3D: its markers appended to markers_.msg
  std::unique_ptr<RangeWindow> range_;  // ~rates/range_graph > 0
  double shifted_ = 0.0;                // the backlog dropped in this run [s] (the stamps are time() plus it)
};

// The hang-off as the scene's coordinates: "(x 1.000, z -2.000)" planar, "(x, y, z)" in 3D.
std::string describeHangoff(const riser_sim::Scene& scene, const Eigen::Vector3d& p);

}  // namespace riser_sim_ros
