#include "riser_sim_ros/line_markers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace riser_sim_ros {

namespace {
std_msgs::ColorRGBA rgba(double r, double g, double b, double a = 1.0) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

geometry_msgs::Point point(double x, double z) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = 0.0;
  p.z = z;
  return p;
}

// Tension in kN with a sensible number of digits.
void formatKn(char* buf, size_t n, const char* label, double newton) {
  const double kn = newton / 1e3;
  const double a = std::abs(kn);
  std::snprintf(buf, n, a >= 100 ? "%s%.0f kN" : (a >= 10 ? "%s%.1f kN" : "%s%.2f kN"), label, kn);
}
}  // namespace

Surfaces surfacesOf(const riser_sim::Scene& scene) {
  // A 3D scene's waves and sloped seabed are SeaMarkers' (sea_markers.h).
  const bool spatial = scene.space == riser_sim::SpaceKind::kSpatial;
  Surfaces s;
  if (scene.water.enabled && !(spatial && scene.water.waves.active() && scene.gravity > 0.0))
    s.water_level = scene.water.surface;
  if (scene.seabed.enabled && !(spatial && scene.seabed.slope != 0.0)) s.seabed = scene.seabed.level;
  return s;
}

std_msgs::ColorRGBA tensionColour(double x, double lo, double hi) {
  const double s = hi > lo ? std::clamp((x - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  // Piecewise linear through blue, cyan, green, yellow, red.
  static const double stops[5][3] = {
      {0.1, 0.2, 1.0}, {0.0, 0.9, 1.0}, {0.1, 0.9, 0.1}, {1.0, 0.9, 0.0}, {1.0, 0.1, 0.1}};
  const double f = s * 4.0;
  const int k = std::min(static_cast<int>(f), 3);
  const double w = f - k;
  return rgba(stops[k][0] + w * (stops[k + 1][0] - stops[k][0]), stops[k][1] + w * (stops[k + 1][1] - stops[k][1]),
              stops[k][2] + w * (stops[k + 1][2] - stops[k][2]));
}

LineMarkers::LineMarkers(double length, int bodies, bool end_mass, const std::string& fixed_frame,
                         const MarkerParams& params, const Surfaces& surfaces)
    : length_(length), surfaces_(surfaces) {
  const int nb = bodies;
  const double width = params.line_width > 0.0 ? params.line_width : length_ / 150.0;
  const double sphere = params.node_scale > 0.0 ? params.node_scale : 2.5 * width;
  text_height_ = params.text_height > 0.0 ? params.text_height : length_ / 25.0;

  auto add = [&](int id, int type, const std::string& ns) {
    visualization_msgs::Marker m;
    m.header.frame_id = fixed_frame;
    m.ns = ns;
    m.id = id;
    m.type = type;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color = rgba(1, 1, 1);
    index_[id] = static_cast<int>(msg.markers.size());
    msg.markers.push_back(m);
  };
  using visualization_msgs::Marker;
  add(kLine, Marker::LINE_STRIP, "line");
  marker(kLine).scale.x = width;
  marker(kLine).points.resize(nb + 1);
  marker(kLine).colors.resize(nb + 1);

  add(kNodes, Marker::SPHERE_LIST, "nodes");
  marker(kNodes).scale.x = marker(kNodes).scale.y = marker(kNodes).scale.z = sphere;
  marker(kNodes).color = rgba(0.85, 0.85, 0.85);
  marker(kNodes).points.resize(nb);  // A_0 .. A_n

  add(kEndMass, Marker::SPHERE, "end_mass");
  const double end_size = end_mass ? 2.0 * sphere : sphere;
  marker(kEndMass).scale.x = marker(kEndMass).scale.y = marker(kEndMass).scale.z = end_size;
  marker(kEndMass).color = rgba(0.9, 0.5, 0.1);

  add(kTopText, Marker::TEXT_VIEW_FACING, "top_tension");
  marker(kTopText).scale.z = text_height_;

  add(kLegendBar, Marker::LINE_STRIP, "legend");
  marker(kLegendBar).scale.x = 3.0 * width;
  marker(kLegendBar).points.resize(kBarVertices);
  marker(kLegendBar).colors.resize(kBarVertices);
  for (int k = 0; k < kBarVertices; ++k) marker(kLegendBar).colors[k] = tensionColour(k, 0, kBarVertices - 1);
  add(kLegendLow, Marker::TEXT_VIEW_FACING, "legend");
  add(kLegendHigh, Marker::TEXT_VIEW_FACING, "legend");
  add(kLegendTitle, Marker::TEXT_VIEW_FACING, "legend");
  for (int id : {kLegendLow, kLegendHigh, kLegendTitle}) marker(id).scale.z = 0.7 * text_height_;
  for (int id : {kLegendLow, kLegendHigh, kLegendTitle}) marker(id).color = rgba(0.95, 0.95, 0.95);
  marker(kLegendTitle).text = "axial force";

  if (surfaces_.water_level) {
    add(kWater, Marker::CUBE, "water_surface");
    marker(kWater).color = rgba(0.2, 0.45, 0.9, 0.35);
  }
  if (surfaces_.seabed) {
    add(kSeabed, Marker::CUBE, "seabed");
    marker(kSeabed).color = rgba(0.55, 0.42, 0.25, 0.8);
  }
}

void LineMarkers::fill(const riser_sim::RunOutputs& out, const ros::Time& stamp) {
  const auto world = [&](int i) {
    geometry_msgs::Point p;
    p.x = out.points[i].x(), p.y = out.points[i].y(), p.z = out.points[i].z();
    return p;
  };
  const std::vector<double>& axial_force = out.axial_force;
  for (auto& m : msg.markers) m.header.stamp = stamp;
  const int nb = static_cast<int>(axial_force.size());
  double lo = axial_force[0], hi = axial_force[0];
  for (double f : axial_force) lo = std::min(lo, f), hi = std::max(hi, f);
  const double eps = 1e-6 * std::max({std::abs(lo), std::abs(hi), 1.0});
  if (hi - lo < eps) lo -= eps, hi += eps;

  // Line: vertex i (A_i) takes the mean force of the rfes that meet there; the end point takes rfe n's.
  auto& line = marker(kLine);
  const geometry_msgs::Point p0 = world(0);
  double xmin = p0.x, xmax = xmin, ymin = p0.y, ymax = ymin, zmax = p0.z;
  for (int i = 0; i <= nb; ++i) {
    const geometry_msgs::Point p = world(i);
    line.points[i] = p;
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    zmax = std::max(zmax, p.z);
    const double f =
        i == 0 ? axial_force[0] : (i == nb ? axial_force[nb - 1] : 0.5 * (axial_force[i - 1] + axial_force[i]));
    line.colors[i] = tensionColour(f, lo, hi);
  }
  auto& nodes = marker(kNodes);
  for (int i = 0; i < nb; ++i) nodes.points[i] = line.points[i];
  marker(kEndMass).pose.position = line.points[nb];

  char buf[64];
  auto& top = marker(kTopText);
  top.pose.position = p0;
  top.pose.position.z += 1.2 * text_height_;
  formatKn(buf, sizeof(buf), "top tension ", out.top_tension);
  top.text = buf;

  // Legend: a vertical colour bar right of the line, a third of the line length tall, its top a tenth
  // of the length below the hang-off so its title clears the top-tension text.
  const double cy = 0.5 * (ymin + ymax);
  const auto at = [cy](double x, double z) {
    geometry_msgs::Point p = point(x, z);
    p.y = cy;
    return p;
  };
  const double bx = xmax + 0.15 * length_, bz_top = zmax - 0.1 * length_, bz_low = bz_top - length_ / 3.0;
  auto& bar = marker(kLegendBar);
  for (int k = 0; k < kBarVertices; ++k) bar.points[k] = at(bx, bz_low + (bz_top - bz_low) * k / (kBarVertices - 1.0));
  auto& low = marker(kLegendLow);
  low.pose.position = at(bx + 0.12 * length_, bz_low);
  formatKn(buf, sizeof(buf), "", lo);
  low.text = buf;
  auto& high = marker(kLegendHigh);
  high.pose.position = at(bx + 0.12 * length_, bz_top);
  formatKn(buf, sizeof(buf), "", hi);
  high.text = buf;
  marker(kLegendTitle).pose.position = at(bx, bz_top + 0.9 * text_height_);

  // Surfaces: thin slabs spanning the line's horizontal extent plus half a line length each side.
  const double span = (xmax - xmin) + length_, cx = 0.5 * (xmin + xmax);
  auto slab = [&](int id, double z) {
    auto& m = marker(id);
    m.pose.position = at(cx, z);
    m.scale.x = span;
    m.scale.y = (ymax - ymin) + 0.5 * length_;
    m.scale.z = 0.01 * length_;
  };
  if (surfaces_.water_level) slab(kWater, *surfaces_.water_level);
  if (surfaces_.seabed) slab(kSeabed, *surfaces_.seabed);
}

}  // namespace riser_sim_ros
