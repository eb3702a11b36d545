// rviz markers of the sea and seabed of a 3D scene (space: spatial), added to LineMarkers' array and filled
// in place with it, each only when the scene has the term:
// - `current` (ARROW per depth): the current (environment.current, its acceleration and depth profile) at
//   kArrows depths from the surface down to the seabed or a line length, on a vertical beside the line;
//   arrow length = speed x (0.15 L / the largest speed at t = 0);
// - `water_surface` (TRIANGLE_LIST) with waves: the elevation at the current time on a strip grid along
//   the wave heading (long-crested: one elevation per row, no more than kMaxRows per fill), spacing a sixth
//   of the shortest component's wave length; without waves LineMarkers' flat slab;
// - `seabed` (CUBE) when sloped (seabed.slope): the slab turned onto the plane, its z axis the plane's normal,
//   centred on the plane below the line's horizontal centre; level: LineMarkers' slab.
#pragma once
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/spatial/water.h"
#include "riser_sim/planar/water.h"
#include "riser_sim_ros/line_markers.h"

namespace riser_sim_ros {

class SeaMarkers {
 public:
  static constexpr int kArrows = 5;
  static constexpr int kMaxRows = 201;
  // Marker ids after LineMarkers' (their ns tell them apart).
  enum Id { kCurrent = 100, kWaves = 100 + kArrows, kSlopedSeabed };

  // Appends the scene's markers to msg (LineMarkers' array, frame and stamps as its markers).
  SeaMarkers(const riser_sim::Scene& scene, const std::string& fixed_frame, visualization_msgs::MarkerArray& msg);
  // Updates them in msg for the line in `out` (its time and horizontal extent). Allocates nothing.
  void fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const;
  bool empty() const { return current_ < 0 && waves_ < 0 && seabed_ < 0; }

 private:
  double length_;
  double surface_ = 0.0;
  // Current: the water without waves (the current at any t), its depths and arrow scale [s].
  std::unique_ptr<riser_sim::spatial::Water3> current_water_;
  double depths_[kArrows] = {};
  double arrow_scale_ = 0.0;
  // Waves: their planar kinematics along the heading (surface at 0), the heading's unit vector, row spacing.
  std::unique_ptr<riser_sim::WaterKinematics> waves_kin_;
  Eigen::Vector3d heading_ = Eigen::Vector3d::UnitX();
  double spacing_ = 1.0;
  // Sloped seabed: unit normal, n·x on the plane, the slab's orientation.
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();
  double offset_ = 0.0;
  Eigen::Quaterniond tilt_ = Eigen::Quaterniond::Identity();
  int current_ = -1, waves_ = -1, seabed_ = -1;  // index of the first marker in msg, -1: none
};

}  // namespace riser_sim_ros
