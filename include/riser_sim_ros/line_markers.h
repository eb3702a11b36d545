// rviz markers of the line, sized once and filled in place: the line coloured per vertex by axial
// force (LINE_STRIP) with a colour-bar legend of the current range (LINE_STRIP + TEXT), one sphere per
// rfe joint (SPHERE_LIST) and the end mass (SPHERE), the top tension (TEXT), and flat CUBE markers for
// the water surface and the seabed when the scene has them.
#pragma once
#include <optional>
#include <string>

#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim_ros/node_params.h"

namespace riser_sim_ros {

// Horizontal planes drawn when the scene has them (world z [m]); in a 3D scene not the water with waves nor a
// sloped seabed (SeaMarkers draws those).
struct Surfaces {
  std::optional<double> water_level;  // environment.water.surface
  std::optional<double> seabed;       // seabed.level
};
Surfaces surfacesOf(const riser_sim::Scene& scene);

// Colour of x in [lo, hi]: blue (low) -> cyan -> green -> yellow -> red (high).
std_msgs::ColorRGBA tensionColour(double x, double lo, double hi);

class LineMarkers {
 public:
  // Marker ids (each marker also has its own ns: line, nodes, end_mass, top_tension, legend, ...).
  enum Id { kLine = 0, kNodes, kEndMass, kTopText, kLegendBar, kLegendLow, kLegendHigh, kLegendTitle, kWater, kSeabed };

  // The line of `length` [m] in `bodies` rfes, its end mass drawn larger when it has one.
  LineMarkers(double length, int bodies, bool end_mass, const std::string& fixed_frame, const MarkerParams& params,
              const Surfaces& surfaces = {});
  void fill(const riser_sim::RunOutputs& out, const ros::Time& stamp);
  visualization_msgs::MarkerArray msg;

 private:
  visualization_msgs::Marker& marker(int id) { return msg.markers[index_[id]]; }
  int index_[kSeabed + 1] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
  double length_, text_height_;
  Surfaces surfaces_;
  static constexpr int kBarVertices = 11;
};

}  // namespace riser_sim_ros
