#include "riser_sim_ros/line_messages.h"

#include <Eigen/Geometry>
#include <cmath>

namespace riser_sim_ros {

namespace {
template <class V>
bool finite(const V& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
}  // namespace

bool outputsFinite(const riser_sim::LineOutputs& out) {
  for (const auto& p : out.points)
    if (!p.allFinite()) return false;
  return finite(out.angles) && finite(out.elongations) && finite(out.axial_force) && finite(out.bending_moment) &&
         out.top_force.allFinite() && std::isfinite(out.top_tension) && std::isfinite(out.bottom_tension) &&
         std::isfinite(out.max_tension);
}

geometry_msgs::Quaternion planeRotation(double phi) {
  geometry_msgs::Quaternion q;
  q.x = 0.0;
  q.y = std::sin(-0.5 * phi);
  q.z = 0.0;
  q.w = std::cos(-0.5 * phi);
  return q;
}

LineMessages::LineMessages(const riser_sim::Model& model, const std::string& fixed_frame,
                           const std::string& tf_prefix)
    : segment_(model.segmentLength()) {
  const size_t nb = model.bodies();
  tension.header.frame_id = fixed_frame;
  tension.axial_force.resize(nb);
  tension.arc_length.resize(nb);
  state.header.frame_id = fixed_frame;
  state.points.resize(nb + 1);
  state.angles.resize(nb);
  state.elongations.resize(nb);
  state.bending_moments.resize(nb - 1);
  state.curvatures.resize(nb - 1);
  state.bending_moment_vectors.resize(nb - 1);
  wrench.header.frame_id = fixed_frame;
  transforms.resize(nb + 1);
  const std::string prefix = tf_prefix.empty() ? "" : tf_prefix + "/";
  for (size_t i = 0; i <= nb; ++i) {
    transforms[i].header.frame_id = fixed_frame;
    transforms[i].child_frame_id = i < nb ? prefix + "rfe_" + std::to_string(i) : prefix + "end";
  }
}

void LineMessages::fillTension(const riser_sim::LineOutputs& out, const ros::Time& stamp) {
  tension.header.stamp = stamp;
  std::copy(out.axial_force.begin(), out.axial_force.end(), tension.axial_force.begin());
  std::copy(out.arc_length.begin(), out.arc_length.end(), tension.arc_length.begin());
  tension.top = out.top_tension;
  tension.bottom = out.bottom_tension;
  tension.max = out.max_tension;
}

void LineMessages::fillState(const riser_sim::LineOutputs& out, const ros::Time& stamp) {
  state.header.stamp = stamp;
  for (size_t i = 0; i < out.points.size(); ++i) {
    state.points[i].x = out.points[i].x();
    state.points[i].y = 0.0;
    state.points[i].z = out.points[i].y();
  }
  std::copy(out.angles.begin(), out.angles.end(), state.angles.begin());
  std::copy(out.elongations.begin(), out.elongations.end(), state.elongations.begin());
  std::copy(out.bending_moment.begin(), out.bending_moment.end(), state.bending_moments.begin());
  // In the x-z plane a turn from +x towards +z is about -y: the moment vector is (0, -M, 0).
  for (size_t i = 1; i < out.angles.size(); ++i) {
    state.curvatures[i - 1] = std::abs(out.angles[i] - out.angles[i - 1]) / segment_;
    state.bending_moment_vectors[i - 1].x = 0.0;
    state.bending_moment_vectors[i - 1].y = -out.bending_moment[i - 1];
    state.bending_moment_vectors[i - 1].z = 0.0;
  }
}

void LineMessages::fillWrench(const riser_sim::LineOutputs& out, const ros::Time& stamp) {
  wrench.header.stamp = stamp;
  // The planar top is pinned (free rotation): the force acts at the hang-off, no moment about it.
  wrench.wrench.force.x = out.top_force.x();
  wrench.wrench.force.y = 0.0;
  wrench.wrench.force.z = out.top_force.y();
  wrench.wrench.torque.x = 0.0;
  wrench.wrench.torque.y = 0.0;
  wrench.wrench.torque.z = 0.0;
}

void LineMessages::fillTransforms(const riser_sim::LineOutputs& out, const ros::Time& stamp) {
  const size_t nb = out.angles.size();
  for (size_t i = 0; i <= nb; ++i) {
    geometry_msgs::TransformStamped& t = transforms[i];
    t.header.stamp = stamp;
    t.transform.translation.x = out.points[i].x();
    t.transform.translation.y = 0.0;
    t.transform.translation.z = out.points[i].y();
    t.transform.rotation = planeRotation(out.angles[std::min(i, nb - 1)]);
  }
}

}  // namespace riser_sim_ros
