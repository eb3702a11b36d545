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

// The bending of joint i between rfes a = i - 1 and b = i: curvature |κ| = θ / d [1/m] (θ the angle between
// e_a and e_b, d the segment length) and the moment vector [N m], EI κ along e_a × e_b (c θ, c = EI/d, the
// core's bending spring) plus the bending damper's c_d (ω_b - ω_a). Finite for any directions.
struct BendingJoint {
  double curvature = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};
BendingJoint bendingJoint(const riser_sim::spatial::BodyKinematics3& a, const riser_sim::spatial::BodyKinematics3& b,
                          double stiffness, double damping, double segment);

// True when every published quantity of `out` is finite.
bool outputsFinite(const riser_sim::spatial::LineOutputs3& out);

// Frames along a 3D line: frame i has its x axis along rfe i; the others follow by the minimal rotation
// from rfe i - 1's frame, and rfe 0's by the minimal rotation from its frame at the previous call (first
// call: y as close to world y as x allows). So they turn continuously in time and along the line and are
// never singular for vertical or horizontal elements. Not the material frame: without torsion there is no
// twist to show (with line.torsion the node uses materialFrame).
class LineFrames {
 public:
  // x_i = unit (points[i + 1] - points[i]), i = 0..nb - 1; out gets nb rotations.
  void update(const riser_sim::AlignedVector<riser_sim::spatial::Vec3>& points, int nb, std::vector<Eigen::Quaterniond>& out);

 private:
  Eigen::Quaterniond first_ = Eigen::Quaterniond::Identity();
  bool started_ = false;
};

// The material frame of an rfe with torsion on (torsion.h): x along e, y the chart reference
// R(centre -> e) ref turned by the spin angle theta about e, z = x × y. rfe 0: the hang-off's axis and
// reference, theta = 0 (held in twist).
Eigen::Quaterniond materialFrame(const Eigen::Vector3d& e, const Eigen::Vector3d& centre, const Eigen::Vector3d& ref,
                                 double theta);

class LineMessages3 {
 public:
  // body_frame: the top wrench goes out in vessel_frame (rotated by the inverse vessel orientation), and
  // with bottom_body the bottom wrench in bottom_frame (a driven bottom: the ROV's).
  LineMessages3(const riser_sim::spatial::SpatialModel& model, const std::string& fixed_frame,
                const std::string& tf_prefix, bool body_frame, const std::string& vessel_frame,
                bool bottom_body = false, const std::string& bottom_frame = "");
  void fillTension(const riser_sim::spatial::LineOutputs3& out, const ros::Time& stamp);
  // Points, elongations Δ_i and per joint the curvature and bending moment (bendingJoint) from the rfes'
  // kinematics `kin` of the same state.
  void fillState(const riser_sim::spatial::LineOutputs3& out, const riser_sim::spatial::Kinematics3& kin,
                 const ros::Time& stamp);
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
  // The same with torsion on: rfe i's frame is its material frame (materialFrame), turning with the twist;
  // theta: the spin angles (n + 1), frames: the simulator's twist charts, kin: the rfes of the same state.
  void fillTransforms(const riser_sim::spatial::LineOutputs3& out, const riser_sim::spatial::Kinematics3& kin,
                      const double* theta, const riser_sim::spatial::TwistFrames& frames, const ros::Time& stamp);

  riser_sim::Tension tension;
  riser_sim::LineState state;
  geometry_msgs::WrenchStamped top_wrench, bottom_wrench;
  std::vector<geometry_msgs::TransformStamped> transforms;

 private:
  void fillFrames(const riser_sim::spatial::LineOutputs3& out, const ros::Time& stamp);  // from rotations_
  std::vector<double> arc_length_;
  bool body_frame_, bottom_body_;
  double stiffness_, damping_, segment_;  // c = EI/d [N m/rad], c_d [N m s/rad], d [m]
  LineFrames frames_;
  std::vector<Eigen::Quaterniond> rotations_;
};

}  // namespace riser_sim_ros
