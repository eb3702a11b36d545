#include "riser_sim_ros/section_markers.h"

namespace riser_sim_ros {

namespace {
geometry_msgs::Point toPoint(const riser_sim::Vec3& v) {
  geometry_msgs::Point p;
  p.x = v.x(), p.y = v.y(), p.z = v.z();
  return p;
}
}  // namespace

std_msgs::ColorRGBA sectionColour(int k) {
  // Orange, sky blue, green, yellow, blue, vermilion, purple, grey: neighbours differ in hue and lightness.
  static const double palette[kSectionPalette][3] = {{0.90, 0.62, 0.00}, {0.34, 0.71, 0.91}, {0.00, 0.62, 0.45},
                                                     {0.94, 0.89, 0.26}, {0.00, 0.45, 0.70}, {0.84, 0.37, 0.00},
                                                     {0.80, 0.47, 0.65}, {0.60, 0.60, 0.60}};
  const double* c = palette[k % kSectionPalette];
  std_msgs::ColorRGBA out;
  out.r = c[0], out.g = c[1], out.b = c[2], out.a = 0.45;
  return out;
}

SectionMarkers::SectionMarkers(const SectionLayout& layout, double width, const std::string& fixed_frame,
                               visualization_msgs::MarkerArray& msg)
    : layout_(layout), first_(static_cast<int>(msg.markers.size())) {
  for (int k = 0; k < layout_.sections(); ++k) {
    visualization_msgs::Marker m;
    m.header.frame_id = fixed_frame;
    m.ns = "sections";
    m.id = kFirstId + k;
    m.type = visualization_msgs::Marker::LINE_STRIP;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = width;
    m.color = sectionColour(k);
    // Segments a..b-1: their start, the joints A_{a+1}..A_b, their end.
    m.points.resize(layout_.first_segment[k + 1] - layout_.first_segment[k] + 2);
    msg.markers.push_back(m);
  }
}

void SectionMarkers::fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const {
  const int n = static_cast<int>(out.points.size()) - 2;  // A_0..A_n, end
  for (int k = 0; k < layout_.sections(); ++k) {
    visualization_msgs::Marker& m = msg.markers[first_ + k];
    const int a = layout_.first_segment[k], b = layout_.first_segment[k + 1];
    m.points[0] = toPoint(a == 0 ? out.points[0] : out.springs[a]);
    for (int j = a; j < b; ++j) m.points[j - a + 1] = toPoint(out.points[j + 1]);
    m.points[b - a + 1] = toPoint(b == n ? out.points[n + 1] : out.springs[b]);
  }
}

}  // namespace riser_sim_ros
