#include "riser_sim_ros/attachment_markers.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/line/attachment.h"

namespace riser_sim_ros {

namespace {
std_msgs::ColorRGBA rgba(double r, double g, double b, double a = 1.0) {
  std_msgs::ColorRGBA c;
  c.r = r, c.g = g, c.b = b, c.a = a;
  return c;
}
geometry_msgs::Point toPoint(const riser_sim::Vec3& v) {
  geometry_msgs::Point p;
  p.x = v.x(), p.y = v.y(), p.z = v.z();
  return p;
}
}  // namespace

bool AttachmentMarkers::buoyant(const riser_sim::Scene& scene, const riser_sim::AttachmentSpec& a) {
  return scene.water.enabled && scene.water.density * a.volume > a.mass;
}

AttachmentMarkers::AttachmentMarkers(const riser_sim::Scene& scene, double min_diameter, double width,
                                     double text_height, const std::string& fixed_frame,
                                     visualization_msgs::MarkerArray& msg)
    : count_(static_cast<int>(scene.attachments.size())),
      first_(static_cast<int>(msg.markers.size())),
      length_(scene.length),
      text_height_(text_height) {
  const double rho = scene.water.enabled ? scene.water.density : 0.0;
  double f_ref = 0.0;  // [N]
  for (const riser_sim::AttachmentSpec& a : scene.attachments)
    f_ref = std::max(f_ref, std::abs(a.mass - rho * a.volume) * scene.gravity);
  arrow_scale_ = f_ref > 0.0 ? 0.1 * length_ / f_ref : 0.0;

  const auto marker = [&](int k, int type, const char* ns) {
    visualization_msgs::Marker m;
    m.header.frame_id = fixed_frame;
    m.ns = ns;
    m.id = kFirstId + k;
    m.type = type;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    return m;
  };
  using visualization_msgs::Marker;
  for (int k = 0; k < count_; ++k) {
    const riser_sim::AttachmentSpec& a = scene.attachments[k];
    Marker m = marker(k, Marker::SPHERE, "attachments");
    const double d = a.volume > 0.0 ? 2.0 * riser_sim::sphereRadius(a.volume) : 0.0;
    m.scale.x = m.scale.y = m.scale.z = std::max(d, min_diameter);
    m.color = buoyant(scene, a) ? rgba(1.0, 0.85, 0.1) : rgba(0.7, 0.2, 0.15);
    msg.markers.push_back(m);
  }
  for (int k = 0; k < count_; ++k) {
    Marker m = marker(k, Marker::ARROW, "attachment_forces");
    m.scale.x = width;  // shaft diameter, head diameter, head length
    m.scale.y = 2.0 * width;
    m.scale.z = 3.0 * width;
    m.color = rgba(0.95, 0.3, 0.9);
    m.points.resize(2);
    msg.markers.push_back(m);
  }
  for (int k = 0; k < count_; ++k) {
    Marker m = marker(k, Marker::TEXT_VIEW_FACING, "attachment_names");
    m.scale.z = 0.6 * text_height;
    m.color = rgba(0.95, 0.95, 0.95);
    m.text = scene.attachments[k].name;
    msg.markers.push_back(m);
  }
}

void AttachmentMarkers::fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const {
  for (int k = 0; k < count_; ++k) {
    const riser_sim::Vec3& p = out.attachment_points[k];
    const riser_sim::Vec3& f = out.attachment_forces[k];
    visualization_msgs::Marker& sphere = msg.markers[first_ + k];
    sphere.pose.position = toPoint(p);
    visualization_msgs::Marker& arrow = msg.markers[first_ + count_ + k];
    const double norm = f.norm(), len = std::min(norm * arrow_scale_, 0.3 * length_);
    arrow.points[0] = toPoint(p);
    arrow.points[1] = toPoint(norm > 0.0 ? riser_sim::Vec3(p + f * (len / norm)) : p);
    visualization_msgs::Marker& name = msg.markers[first_ + 2 * count_ + k];
    name.pose.position = toPoint(p);
    name.pose.position.z += 0.5 * sphere.scale.z + 0.5 * text_height_;
  }
}

}  // namespace riser_sim_ros
