// The run the node steps, behind one interface: the planar core (PlanarLineRun, planar_line_run.h) or
// the 3D core (SpatialLineRun, spatial_line_run.h), chosen by the scene's `space`. Each drives its top
// from the vessel samples, steps, and turns its outputs into the node's messages (sized once, filled in
// place). The node and its topics see only this.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/LineState.h"
#include "riser_sim/Tension.h"
#include "riser_sim/external_motion.h"
#include "riser_sim/force_noise.h"
#include "riser_sim/scene.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/vessel_input.h"

namespace riser_sim_ros {

class ModesServer;

// What /diagnostics reports of a running line.
struct RunHealth {
  double constraint_error = 0.0, max_constraint_error = 0.0;  // [m]
  double energy = 0.0, energy_drift = 0.0;                    // [J], relative
  riser_sim::ForceNoise noise;                                // last 10 s
  std::string force_warning;                                  // empty: forces resolved
  Eigen::Vector3d hangoff = Eigen::Vector3d::Zero();           // A_0 now, fixed_frame [m]
  riser_sim::MotionGaps gaps, bottom_gaps;                     // of the vessel's (a driven bottom's) samples
};

class LineRun {
 public:
  virtual ~LineRun() = default;
  virtual bool spatial() const = 0;
  // The top restarts at rest at s's hang-off at sim time t (after the node fixed its time origin).
  virtual void restartMotion(double t, const VesselSample& s) = 0;
  // A vessel sample stamped t_sample [s of sim time], applied now. False when the motion refused it.
  virtual bool addSample(double t_sample, const VesselSample& s) = 0;
  virtual void shiftSampleTimes(double dt) = 0;
  // A driven bottom (3D, bottom.motion.type external): the second end's samples, as the vessel's.
  virtual bool drivenBottom() const { return false; }
  virtual void restartBottom(double, const VesselSample&) {}
  virtual bool addBottomSample(double, const VesselSample&) { return false; }
  virtual bool step() = 0;  // false once diverged
  virtual const std::string& divergenceReason() const = 0;
  virtual double time() const = 0;
  virtual double dt() const = 0;
  virtual std::string stepAboveLimit() const = 0;  // empty, or why solver.dt is above the stability limit
  virtual std::string startMessage() = 0;           // "static equilibrium at hang-off (...) m: top tension ..."
  // Hands the static state to ~modes (or says why there is none).
  virtual void shareStatics(ModesServer& modes, const ros::Time& stamp) = 0;
  virtual RunHealth health() = 0;

  // Evaluates the outputs of the current state: false when any is non-finite (then nothing is published).
  virtual bool evaluate() = 0;
  // The messages of the last evaluate(), stamped.
  virtual const riser_sim::Tension& tension(const ros::Time& stamp) = 0;
  virtual const riser_sim::LineState& state(const ros::Time& stamp) = 0;
  virtual const geometry_msgs::WrenchStamped& topWrench(const ros::Time& stamp) = 0;
  virtual const geometry_msgs::WrenchStamped* bottomWrench(const ros::Time&) { return nullptr; }  // pinned 3D bottom
  virtual const std::vector<geometry_msgs::TransformStamped>& transforms(const ros::Time& stamp) = 0;
  virtual const visualization_msgs::MarkerArray& markers(const ros::Time& stamp) = 0;
};

// The run of `scene` hanging from s's hang-off, its top an external motion from sim time t; with `bottom`
// (3D, pinned) the bottom too, from its attachment point at sim time t_bottom. Throws as riser_sim::buildRun
// / spatial::SpatialRun do (std::invalid_argument, std::runtime_error: statics).
std::unique_ptr<LineRun> makeLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t,
                                     const NodeParams& params, const VesselSample* bottom = nullptr,
                                     double t_bottom = 0.0);

// The hang-off as the scene's coordinates: "(x 1.000, z -2.000)" planar, "(x, y, z)" in 3D.
std::string describeHangoff(const riser_sim::Scene& scene, const Eigen::Vector3d& p);

}  // namespace riser_sim_ros
