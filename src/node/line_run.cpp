#include "riser_sim_ros/line_run.h"

#include "riser_sim_ros/node_diagnostics.h"
#include "riser_sim_ros/planar_line_run.h"
#include "riser_sim_ros/spatial_line_run.h"

namespace riser_sim_ros {

std::unique_ptr<LineRun> makeLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t,
                                     const NodeParams& params, const VesselSample* bottom, double t_bottom) {
  if (scene.space == riser_sim::SpaceKind::kSpatial)
    return std::make_unique<SpatialLineRun>(scene, s, t, params, bottom, t_bottom);
  return std::make_unique<PlanarLineRun>(scene, s, t, params);
}

std::string describeHangoff(const riser_sim::Scene& scene, const Eigen::Vector3d& p) {
  if (scene.space == riser_sim::SpaceKind::kSpatial)
    return "(" + num(p.x()) + ", " + num(p.y()) + ", " + num(p.z()) + ")";
  return "(" + num(p.x()) + ", " + num(p.z()) + ")";
}

}  // namespace riser_sim_ros
