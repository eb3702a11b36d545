// The node's data messages for a 3D line (space: spatial), sized once and filled in place from
// spatial::LineOutputs3. Everything in fixed_frame (world, z up) unless a wrench is asked in a body's frame.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>

#include "riser_sim/LineState.h"
#include "riser_sim/Tension.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim_ros {

// True when every published quantity of `out` is finite.
bool outputsFinite(const riser_sim::spatial::LineOutputs3& out);

// Frames along a 3D line: frame i has its x axis along rfe i; the others follow by the minimal rotation
// from rfe i - 1's frame, and rfe 0's by the minimal rotation from its frame at the previous call (first
// call: y as close to world y as x allows). So they turn continuously in time and along the line and are
// never singular for vertical or horizontal elements. Not the material frame (twist is not shown).
class LineFrames {
 public:
  // x_i = unit (points[i + 1] - points[i]), i = 0..nb - 1; out gets nb rotations.
  void update(const riser_sim::AlignedVector<riser_sim::spatial::Vec3>& points, int nb, std::vector<Eigen::Quaterniond>& out);

 private:
  Eigen::Quaterniond first_ = Eigen::Quaterniond::Identity();
  bool started_ = false;
};

class LineMessages3 {
 public:
  // body_frame: the top wrench goes out in vessel_frame (rotated by the inverse vessel orientation), and
  // with bottom_body the bottom wrench in bottom_frame (a driven bottom: the ROV's).
  LineMessages3(const riser_sim::spatial::SpatialModel& model, const std::string& fixed_frame,
                const std::string& tf_prefix, bool body_frame, const std::string& vessel_frame,
                bool bottom_body = false, const std::string& bottom_frame = "");
  void fillTension(const riser_sim::spatial::LineOutputs3& out, const ros::Time& stamp);
  void fillState(const riser_sim::spatial::LineOutputs3& out, const ros::Time& stamp);
  // Force and moment the line exerts on the hang-off, the moment about the hang-off point; `vessel`
  // rotates vessel-frame vectors into fixed_frame.
  void fillTopWrench(const riser_sim::spatial::LineOutputs3& out, const Eigen::Quaterniond& vessel,
                     const ros::Time& stamp);
  // Force and moment the line exerts on the pinned bottom's anchor, about the anchor; `body` (the ROV's
  // orientation) is used with bottom_body.
  void fillBottomWrench(const riser_sim::spatial::LineOutputs3& out, const Eigen::Quaterniond& body,
                        const ros::Time& stamp);
  // <prefix>/rfe_<i> (origin A_i, x along rfe i) and <prefix>/end (end of rfe n, rfe n's orientation).
  void fillTransforms(const riser_sim::spatial::LineOutputs3& out, const ros::Time& stamp);

  riser_sim::Tension tension;
  riser_sim::LineState state;
  geometry_msgs::WrenchStamped top_wrench, bottom_wrench;
  std::vector<geometry_msgs::TransformStamped> transforms;

 private:
  std::vector<double> arc_length_;
  bool body_frame_, bottom_body_;
  LineFrames frames_;
  std::vector<Eigen::Quaterniond> rotations_;
};

}  // namespace riser_sim_ros
