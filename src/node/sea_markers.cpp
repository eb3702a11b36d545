#include "riser_sim_ros/sea_markers.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/spatial/forces/seabed.h"

namespace riser_sim_ros {

namespace {
using Vec3 = Eigen::Vector3d;

bool hasCurrent(const riser_sim::WaterSpec& w) {
  const riser_sim::CurrentSpec& c = w.current;
  return w.enabled && (c.velocity.norm() > 0.0 || c.acceleration.norm() > 0.0 || !c.profile.empty());
}

geometry_msgs::Point point(const Vec3& v) {
  geometry_msgs::Point p;
  p.x = v.x(), p.y = v.y(), p.z = v.z();
  return p;
}

visualization_msgs::Marker make(const std::string& frame, const std::string& ns, int id, int type, double r, double g,
                                double b, double a) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.r = r, m.color.g = g, m.color.b = b, m.color.a = a;
  return m;
}
}  // namespace

SeaMarkers::SeaMarkers(const riser_sim::Scene& scene, const std::string& frame, visualization_msgs::MarkerArray& msg)
    : length_(scene.length), surface_(scene.water.surface) {
  using visualization_msgs::Marker;
  const Vec3 gravity(0.0, 0.0, -scene.gravity);
  if (hasCurrent(scene.water)) {
    riser_sim::WaterSpec still = scene.water;
    still.waves.height = 0.0;
    still.waves.significant_height = 0.0;
    current_water_ = std::make_unique<riser_sim::spatial::Water3>(still, gravity);
    // Surface down to the seabed (or a line length), the deepest arrow just above the bottom of that range.
    double range = length_;
    if (scene.seabed.enabled && scene.seabed.level < surface_) range = std::min(range, surface_ - scene.seabed.level);
    double fastest = 0.0;
    for (int k = 0; k < kArrows; ++k) {
      depths_[k] = range * k / kArrows;
      Vec3 v, a;
      current_water_->at(Vec3(0.0, 0.0, surface_ - depths_[k]), 0.0, v, a);
      fastest = std::max(fastest, v.norm());
    }
    arrow_scale_ = 0.15 * length_ / std::max(fastest, 0.1);  // a current starting from rest: 0.1 m/s scale
    current_ = static_cast<int>(msg.markers.size());
    for (int k = 0; k < kArrows; ++k) {
      Marker m = make(frame, "current", kCurrent + k, Marker::ARROW, 0.2, 0.8, 0.9, 0.9);
      m.scale.x = length_ / 150.0;  // shaft diameter
      m.scale.y = 2.5 * m.scale.x;  // head diameter
      m.scale.z = 3.0 * m.scale.x;  // head length
      m.points.resize(2);
      msg.markers.push_back(m);
    }
  }
  if (scene.water.enabled && scene.water.waves.active() && scene.gravity > 0.0) {
    riser_sim::WaterSpec w = scene.water;  // the waves alone, as Water3 sees them along the heading
    w.current = riser_sim::CurrentSpec();
    w.surface = 0.0;
    w.waves.heading = 0.0;
    waves_kin_ = std::make_unique<riser_sim::WaterKinematics>(w, scene.gravity);
    heading_ = Vec3(std::cos(scene.water.waves.heading), std::sin(scene.water.waves.heading), 0.0);
    double k_max = 0.0;
    for (const auto& c : waves_kin_->components()) k_max = std::max(k_max, c.k);
    spacing_ = k_max > 0.0 ? 2.0 * M_PI / k_max / 6.0 : length_ / 10.0;
    waves_ = static_cast<int>(msg.markers.size());
    Marker m = make(frame, "water_surface", kWaves, Marker::TRIANGLE_LIST, 0.2, 0.45, 0.9, 0.45);
    msg.markers.push_back(m);
  }
  if (scene.seabed.enabled && scene.seabed.slope != 0.0) {
    const riser_sim::spatial::Seabed bed(scene.seabed, gravity.norm() > 0.0 ? gravity : Vec3(0.0, 0.0, -1.0));
    normal_ = bed.normal();
    offset_ = bed.penetration(Vec3::Zero());  // n·(level up) - n·0
    tilt_ = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), normal_);
    seabed_ = static_cast<int>(msg.markers.size());
    Marker m = make(frame, "seabed", kSlopedSeabed, Marker::CUBE, 0.55, 0.42, 0.25, 0.8);
    m.pose.orientation.x = tilt_.x(), m.pose.orientation.y = tilt_.y();
    m.pose.orientation.z = tilt_.z(), m.pose.orientation.w = tilt_.w();
    msg.markers.push_back(m);
  }
  // Sized once here, after the last push_back (a copy does not keep a vector's capacity).
  if (waves_ >= 0) msg.markers[waves_].points.reserve(6 * (kMaxRows - 1));
}

void SeaMarkers::fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const {
  Vec3 lo = out.points[0], hi = out.points[0];
  for (const Vec3& p : out.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 centre(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), 0.0);
  const double span = std::max(hi.x() - lo.x(), hi.y() - lo.y()) + length_;
  if (current_ >= 0) {  // a vertical left of the line (-x), a fifth of a line length clear of it
    const Vec3 base(lo.x() - 0.2 * length_, centre.y(), 0.0);
    for (int k = 0; k < kArrows; ++k) {
      const Vec3 p(base.x(), base.y(), surface_ - depths_[k]);
      Vec3 v, a;
      current_water_->at(p, out.t, v, a);
      auto& m = msg.markers[current_ + k];
      m.points[0] = point(p);
      m.points[1] = point(p + arrow_scale_ * v);
    }
  }
  if (waves_ >= 0) {
    // Rows across the heading (the elevation is constant along a crest), a strip span wide.
    auto& m = msg.markers[waves_];
    const int rows = std::clamp(static_cast<int>(std::ceil(span / spacing_)) + 1, 2, kMaxRows);
    const double step = span / (rows - 1), along0 = heading_.dot(centre) - 0.5 * span;
    const Vec3 across = Vec3::UnitZ().cross(heading_) * (0.5 * span);
    const Vec3 c0 = centre - heading_ * heading_.dot(centre);  // the centre's part across the heading
    m.points.resize(6 * (rows - 1));                           // within the reserved kMaxRows: no allocation
    Vec3 prev_l, prev_r;
    for (int r = 0; r < rows; ++r) {
      const double s = along0 + r * step;
      const Vec3 mid = c0 + s * heading_ + Vec3(0.0, 0.0, surface_ + waves_kin_->elevation(s, out.t));
      const Vec3 left = mid + across, right = mid - across;
      if (r > 0) {
        geometry_msgs::Point* t = &m.points[6 * (r - 1)];
        t[0] = point(prev_l), t[1] = point(prev_r), t[2] = point(right);
        t[3] = point(prev_l), t[4] = point(right), t[5] = point(left);
      }
      prev_l = left, prev_r = right;
    }
  }
  if (seabed_ >= 0) {  // on the plane n·x = offset below the line's horizontal centre
    auto& m = msg.markers[seabed_];
    const double z = (offset_ - normal_.x() * centre.x() - normal_.y() * centre.y()) / normal_.z();
    m.pose.position = point(Vec3(centre.x(), centre.y(), z));
    m.scale.x = m.scale.y = span;
    m.scale.z = 0.01 * length_;
  }
}

}  // namespace riser_sim_ros
