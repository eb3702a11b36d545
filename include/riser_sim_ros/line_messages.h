// The node's data messages, sized once for the model and filled in place from LineOutputs.
// World frame (REP 103, z up): paper (x, y) -> world (x, 0, y).
#pragma once
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>

#include "riser_sim/LineState.h"
#include "riser_sim/Tension.h"
#include "riser_sim/model.h"
#include "riser_sim/outputs.h"

namespace riser_sim_ros {

// True when every published quantity of `out` is finite.
bool outputsFinite(const riser_sim::LineOutputs& out);

// Quaternion (x, y, z, w) of a rotation about world y that turns world x onto the paper direction φ
// in the x-z plane (x towards z): angle -φ about y.
geometry_msgs::Quaternion planeRotation(double phi);

class LineMessages {
 public:
  LineMessages(const riser_sim::Model& model, const std::string& fixed_frame, const std::string& tf_prefix);
  void fillTension(const riser_sim::LineOutputs& out, const ros::Time& stamp);
  void fillState(const riser_sim::LineOutputs& out, const ros::Time& stamp);
  // Force the riser exerts on the vessel at the hang-off point, in fixed_frame; the torque is the moment
  // about the hang-off point (as in 3D): 0, the planar top is pinned.
  void fillWrench(const riser_sim::LineOutputs& out, const ros::Time& stamp);
  // <prefix>/rfe_<i>, i = 0..n (origin A_i, x along the rfe) and <prefix>/end (end point of rfe n).
  void fillTransforms(const riser_sim::LineOutputs& out, const ros::Time& stamp);

  riser_sim::Tension tension;
  riser_sim::LineState state;
  geometry_msgs::WrenchStamped wrench;
  std::vector<geometry_msgs::TransformStamped> transforms;

 private:
  double segment_;  // d = L/n: the joints' spacing, curvature = turn / d [m]
};

}  // namespace riser_sim_ros
