#include "riser_sim_ros/line_messages.h"

#include <algorithm>

namespace riser_sim_ros {

namespace {
void set(geometry_msgs::Vector3& m, const Eigen::Vector3d& v) { m.x = v.x(), m.y = v.y(), m.z = v.z(); }
}  // namespace

LineMessages::LineMessages(int nb, const std::string& fixed_frame, const std::string& tf_prefix, bool body_frame,
                           const std::string& vessel_frame, bool bottom_body, const std::string& bottom_frame)
    : body_frame_(body_frame), bottom_body_(bottom_body) {
  tension.header.frame_id = fixed_frame;
  tension.axial_force.resize(nb);
  tension.arc_length.resize(nb);
  state.header.frame_id = fixed_frame;
  state.points.resize(nb + 1);
  state.elongations.resize(nb);
  state.bending_moments.resize(nb - 1);
  state.curvatures.resize(nb - 1);
  state.bending_moment_vectors.resize(nb - 1);
  top_wrench.header.frame_id = body_frame ? vessel_frame : fixed_frame;
  bottom_wrench.header.frame_id = bottom_body ? bottom_frame : fixed_frame;
  transforms.resize(nb + 1);
  const std::string prefix = tf_prefix.empty() ? "" : tf_prefix + "/";
  for (int i = 0; i <= nb; ++i) {
    transforms[i].header.frame_id = fixed_frame;
    transforms[i].child_frame_id = i < nb ? prefix + "rfe_" + std::to_string(i) : prefix + "end";
  }
}

void LineMessages::setLayout(const SectionLayout& layout, const riser_sim::Scene& scene) {
  state.sections.assign(layout.rfe_section.begin(), layout.rfe_section.end());
  state.attachment_names.clear();
  for (const riser_sim::AttachmentSpec& a : scene.attachments) state.attachment_names.push_back(a.name);
  state.attachment_points.resize(scene.attachments.size());
  state.attachment_forces.resize(scene.attachments.size());
}

void LineMessages::fillTension(const riser_sim::RunOutputs& out, const ros::Time& stamp) {
  tension.header.stamp = stamp;
  std::copy(out.axial_force.begin(), out.axial_force.end(), tension.axial_force.begin());
  std::copy(out.arc_length.begin(), out.arc_length.end(), tension.arc_length.begin());
  tension.top = out.top_tension;
  tension.bottom = out.bottom_tension;
  tension.max = out.max_tension;
}

void LineMessages::fillState(const riser_sim::RunOutputs& out, const ros::Time& stamp) {
  state.header.stamp = stamp;
  for (size_t i = 0; i < out.points.size(); ++i) {
    state.points[i].x = out.points[i].x();
    state.points[i].y = out.points[i].y();
    state.points[i].z = out.points[i].z();
  }
  state.angles.resize(out.angles.size());  // planar: n + 1, 3D: none (the same size every call)
  std::copy(out.angles.begin(), out.angles.end(), state.angles.begin());
  std::copy(out.elongations.begin(), out.elongations.end(), state.elongations.begin());
  std::copy(out.bending_moment.begin(), out.bending_moment.end(), state.bending_moments.begin());
  std::copy(out.curvature.begin(), out.curvature.end(), state.curvatures.begin());
  for (size_t j = 0; j < out.bending_moment_vector.size(); ++j)
    set(state.bending_moment_vectors[j], out.bending_moment_vector[j]);
  for (size_t k = 0; k < state.attachment_points.size(); ++k) {
    const riser_sim::Vec3& p = out.attachment_points[k];
    state.attachment_points[k].x = p.x(), state.attachment_points[k].y = p.y(), state.attachment_points[k].z = p.z();
    set(state.attachment_forces[k], out.attachment_forces[k]);
  }
}

void LineMessages::fillTopWrench(const riser_sim::RunOutputs& out, const Eigen::Quaterniond& vessel,
                                 const ros::Time& stamp) {
  top_wrench.header.stamp = stamp;
  const Eigen::Quaterniond to_frame = body_frame_ ? vessel.conjugate() : Eigen::Quaterniond::Identity();
  set(top_wrench.wrench.force, to_frame * out.top_force);
  set(top_wrench.wrench.torque, to_frame * out.top_moment);
}

void LineMessages::fillBottomWrench(const riser_sim::RunOutputs& out, const Eigen::Quaterniond& body,
                                    const ros::Time& stamp) {
  bottom_wrench.header.stamp = stamp;
  const Eigen::Quaterniond to_frame = bottom_body_ ? body.conjugate() : Eigen::Quaterniond::Identity();
  set(bottom_wrench.wrench.force, to_frame * out.bottom_force);
  set(bottom_wrench.wrench.torque, to_frame * out.bottom_moment);
}

void LineMessages::fillTransforms(const riser_sim::RunOutputs& out, const ros::Time& stamp) {
  const int nb = static_cast<int>(out.frames.size());
  for (int i = 0; i <= nb; ++i) {
    geometry_msgs::TransformStamped& t = transforms[i];
    t.header.stamp = stamp;
    set(t.transform.translation, out.points[i]);
    const Eigen::Quaterniond& q = out.frames[std::min(i, nb - 1)];
    t.transform.rotation.x = q.x();
    t.transform.rotation.y = q.y();
    t.transform.rotation.z = q.z();
    t.transform.rotation.w = q.w();
  }
}

}  // namespace riser_sim_ros
