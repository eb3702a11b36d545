#include "riser_sim_ros/line_messages3.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/spatial/forces/bending_spring.h"

namespace riser_sim_ros {

namespace {
using riser_sim::spatial::LineOutputs3;
using riser_sim::spatial::Vec3;

bool finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}
void set(geometry_msgs::Vector3& m, const Eigen::Vector3d& v) { m.x = v.x(), m.y = v.y(), m.z = v.z(); }

// The rotation taking unit a onto unit b about a x b (identity for a = b); a and b must not be opposite.
Eigen::Quaterniond minimalRotation(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return Eigen::Quaterniond::FromTwoVectors(a, b);
}

// A frame with x = e and y as close to world y as possible (world x when e is near world y).
Eigen::Quaterniond startFrame(const Eigen::Vector3d& e) {
  const Eigen::Vector3d ref = std::abs(e.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = (ref - ref.dot(e) * e).normalized();
  Eigen::Matrix3d R;
  R << e, y, e.cross(y);
  return Eigen::Quaterniond(R);
}
}  // namespace

BendingJoint bendingJoint(const riser_sim::spatial::BodyKinematics3& a, const riser_sim::spatial::BodyKinematics3& b,
                          double stiffness, double damping, double segment) {
  using riser_sim::spatial::BendingSpring;
  BendingJoint j;
  const Eigen::Vector3d axis = a.e.cross(b.e);
  const double s = axis.norm(), theta = BendingSpring::angle(a.e, b.e);
  j.curvature = theta / segment;
  // The spring's direction is a x b; none at theta = 0 (no moment) or folded (theta = pi: undefined, and
  // the core's spring has no force there either).
  if (s > 0.0 && theta < M_PI - BendingSpring::kFoldedTol) j.moment = (stiffness * theta / s) * axis;
  j.moment += damping * (b.omega() - a.omega());
  return j;
}

bool outputsFinite(const LineOutputs3& out) {
  for (const auto& p : out.points)
    if (!p.allFinite()) return false;
  return finite(out.axial_force) && out.top_force.allFinite() && out.bottom_force.allFinite() &&
         out.top_moment.allFinite() && out.bottom_moment.allFinite() && out.bottom_point.allFinite() &&
         std::isfinite(out.top_tension) && std::isfinite(out.max_tension);
}

void LineFrames::update(const riser_sim::AlignedVector<Vec3>& points, int nb, std::vector<Eigen::Quaterniond>& out) {
  Eigen::Quaterniond q = first_;
  Eigen::Vector3d prev = q * Eigen::Vector3d::UnitX();
  for (int i = 0; i < nb; ++i) {
    const Eigen::Vector3d e = (points[i + 1] - points[i]).normalized();
    // Not yet started, or a turn of more than 120 deg since the last call (a fold): start afresh.
    if (i == 0 && (!started_ || prev.dot(e) < -0.5)) q = startFrame(e);
    else q = (minimalRotation(prev, e) * q).normalized();
    out[i] = q;
    prev = e;
    if (i == 0) first_ = q;
  }
  started_ = true;
}

LineMessages3::LineMessages3(const riser_sim::spatial::SpatialModel& model, const std::string& fixed_frame,
                             const std::string& tf_prefix, bool body_frame, const std::string& vessel_frame,
                             bool bottom_body, const std::string& bottom_frame)
    : body_frame_(body_frame), bottom_body_(bottom_body), stiffness_(model.bendingStiffness()),
      damping_(model.bendingDamping()), segment_(model.line().segmentLength()) {
  const size_t nb = model.bodies();
  tension.header.frame_id = fixed_frame;
  tension.axial_force.resize(nb);
  tension.arc_length.resize(nb);
  for (size_t i = 0; i < nb; ++i) tension.arc_length[i] = model.rfe(i).s_begin + 0.5 * model.rfe(i).length;
  state.header.frame_id = fixed_frame;
  state.points.resize(nb + 1);  // angles: planar only (empty)
  state.elongations.resize(nb);
  state.bending_moments.resize(nb - 1);
  state.curvatures.resize(nb - 1);
  state.bending_moment_vectors.resize(nb - 1);
  top_wrench.header.frame_id = body_frame ? vessel_frame : fixed_frame;
  bottom_wrench.header.frame_id = bottom_body ? bottom_frame : fixed_frame;
  transforms.resize(nb + 1);
  rotations_.resize(nb);
  const std::string prefix = tf_prefix.empty() ? "" : tf_prefix + "/";
  for (size_t i = 0; i <= nb; ++i) {
    transforms[i].header.frame_id = fixed_frame;
    transforms[i].child_frame_id = i < nb ? prefix + "rfe_" + std::to_string(i) : prefix + "end";
  }
}

void LineMessages3::fillTension(const LineOutputs3& out, const ros::Time& stamp) {
  tension.header.stamp = stamp;
  std::copy(out.axial_force.begin(), out.axial_force.end(), tension.axial_force.begin());
  tension.top = out.top_tension;
  tension.bottom = out.axial_force.back();
  tension.max = out.max_tension;
}

void LineMessages3::fillState(const LineOutputs3& out, const riser_sim::spatial::Kinematics3& kin,
                              const ros::Time& stamp) {
  state.header.stamp = stamp;
  for (size_t i = 0; i < out.points.size(); ++i) {
    state.points[i].x = out.points[i].x();
    state.points[i].y = out.points[i].y();
    state.points[i].z = out.points[i].z();
  }
  for (size_t i = 0; i < state.elongations.size(); ++i) state.elongations[i] = kin[i].delta;
  for (size_t i = 1; i < state.elongations.size(); ++i) {
    const BendingJoint j = bendingJoint(kin[i - 1], kin[i], stiffness_, damping_, segment_);
    state.curvatures[i - 1] = j.curvature;
    state.bending_moments[i - 1] = j.moment.norm();
    set(state.bending_moment_vectors[i - 1], j.moment);
  }
}

void LineMessages3::fillTopWrench(const LineOutputs3& out, const Eigen::Quaterniond& vessel, const ros::Time& stamp) {
  top_wrench.header.stamp = stamp;
  const Eigen::Quaterniond to_frame = body_frame_ ? vessel.conjugate() : Eigen::Quaterniond::Identity();
  set(top_wrench.wrench.force, to_frame * out.top_force);
  set(top_wrench.wrench.torque, to_frame * out.top_moment);
}

void LineMessages3::fillBottomWrench(const LineOutputs3& out, const Eigen::Quaterniond& body, const ros::Time& stamp) {
  bottom_wrench.header.stamp = stamp;
  const Eigen::Quaterniond to_frame = bottom_body_ ? body.conjugate() : Eigen::Quaterniond::Identity();
  set(bottom_wrench.wrench.force, to_frame * out.bottom_force);
  set(bottom_wrench.wrench.torque, to_frame * out.bottom_moment);
}

Eigen::Quaterniond materialFrame(const Eigen::Vector3d& e, const Eigen::Vector3d& centre, const Eigen::Vector3d& ref,
                                 double theta) {
  const Eigen::Vector3d x = e.normalized();
  Eigen::Vector3d u = riser_sim::spatial::minimalRotation(centre, x, ref);
  u = (u - u.dot(x) * x).normalized();  // round-off off the normal plane
  const Eigen::Vector3d y = std::cos(theta) * u + std::sin(theta) * x.cross(u);
  Eigen::Matrix3d R;
  R << x, y, x.cross(y);
  return Eigen::Quaterniond(R).normalized();
}

void LineMessages3::fillTransforms(const LineOutputs3& out, const ros::Time& stamp) {
  frames_.update(out.points, static_cast<int>(rotations_.size()), rotations_);
  fillFrames(out, stamp);
}

void LineMessages3::fillTransforms(const LineOutputs3& out, const riser_sim::spatial::Kinematics3& kin,
                                   const double* theta, const riser_sim::spatial::TwistFrames& frames,
                                   const ros::Time& stamp) {
  bool finite = true;
  for (size_t i = 0; i < rotations_.size(); ++i) {
    rotations_[i] = materialFrame(kin[i].e, frames.centre[i], frames.ref[i], i == 0 ? 0.0 : theta[i]);
    finite = finite && rotations_[i].coeffs().allFinite();
  }
  // A chart at its singularity (the top rfe turned 180 deg from the hang-off's axis): the minimal-rotation
  // frames rather than NaN.
  if (!finite) frames_.update(out.points, static_cast<int>(rotations_.size()), rotations_);
  fillFrames(out, stamp);
}

void LineMessages3::fillFrames(const LineOutputs3& out, const ros::Time& stamp) {
  const int nb = static_cast<int>(rotations_.size());
  for (int i = 0; i <= nb; ++i) {
    geometry_msgs::TransformStamped& t = transforms[i];
    t.header.stamp = stamp;
    set(t.transform.translation, out.points[i]);
    const Eigen::Quaterniond& q = rotations_[std::min(i, nb - 1)];
    t.transform.rotation.x = q.x();
    t.transform.rotation.y = q.y();
    t.transform.rotation.z = q.z();
    t.transform.rotation.w = q.w();
  }
}

}  // namespace riser_sim_ros
