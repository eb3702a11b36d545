// The node's data messages, sized once for the run and filled in place from its outputs (riser_sim::RunOutputs,
// 3D; a planar scene's are its plane x-z of world). Everything in fixed_frame (world, z up) unless a wrench is
// asked in a body's frame.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>

#include "riser_sim/LineState.h"
#include "riser_sim/Tension.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim_ros/section_layout.h"

namespace riser_sim_ros {

class LineMessages {
 public:
  // nb: rfes. body_frame: the top wrench goes out in vessel_frame (rotated by the inverse vessel orientation),
  // and with bottom_body the bottom wrench in bottom_frame (a driven bottom: the ROV's).
  LineMessages(int nb, const std::string& fixed_frame, const std::string& tf_prefix, bool body_frame = false,
               const std::string& vessel_frame = "", bool bottom_body = false, const std::string& bottom_frame = "");
  // ~state's per-run fields: the section of each rfe and the attachments' names (sizes their points, forces).
  void setLayout(const SectionLayout& layout, const riser_sim::Scene& scene);
  void fillTension(const riser_sim::RunOutputs& out, const ros::Time& stamp);
  // Points, angles (planar), elongations, per joint the curvature and bending moment, the attachments.
  void fillState(const riser_sim::RunOutputs& out, const ros::Time& stamp);
  // Force and moment the line exerts on the hang-off, the moment about the hang-off point (0 on a pinned top);
  // `vessel` rotates vessel-frame vectors into fixed_frame.
  void fillTopWrench(const riser_sim::RunOutputs& out, const Eigen::Quaterniond& vessel, const ros::Time& stamp);
  // Force and moment the line exerts on the pinned bottom's anchor, about the anchor; `body` (the ROV's
  // orientation) is used with bottom_body.
  void fillBottomWrench(const riser_sim::RunOutputs& out, const Eigen::Quaterniond& body, const ros::Time& stamp);
  // <prefix>/rfe_<i> (origin A_i, the rfe's frame: x along it) and <prefix>/end (end of rfe n, rfe n's frame).
  void fillTransforms(const riser_sim::RunOutputs& out, const ros::Time& stamp);

  riser_sim::Tension tension;
  riser_sim::LineState state;
  geometry_msgs::WrenchStamped top_wrench, bottom_wrench;
  std::vector<geometry_msgs::TransformStamped> transforms;

 private:
  bool body_frame_, bottom_body_;
};

}  // namespace riser_sim_ros
