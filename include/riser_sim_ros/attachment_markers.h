// rviz markers of the line's point attachments (attachments: clump weights, buoys, floats; riser_sim/
// attachment.h), added to LineMarkers' array and filled in place with it, per attachment k (id kFirstId + k):
// - `attachments` (SPHERE) at its centre: diameter that of a sphere of its displaced volume, at least
//   min_diameter; yellow when buoyant (a buoy or float: ρ_w V > m, the water's density), red-brown otherwise
//   (a clump weight, or any attachment without water);
// - `attachment_forces` (ARROW) from its centre along the force on it (RunOutputs::attachment_forces), length
//   |F| / F_ref x L / 10, F_ref the largest |m - ρ_w V| g of the scene's attachments (its net weight at rest),
//   at most 0.3 L;
// - `attachment_names` (TEXT) its name above it.
#pragma once
#include <string>
#include <vector>

#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim_ros {

class AttachmentMarkers {
 public:
  static constexpr int kFirstId = 300;
  // Appends the scene's attachments' markers to msg; `width` is the line's width [m] (the arrows' shafts),
  // text_height the names' [m].
  AttachmentMarkers(const riser_sim::Scene& scene, double min_diameter, double width, double text_height,
                    const std::string& fixed_frame, visualization_msgs::MarkerArray& msg);
  // Updates them in msg from out.attachment_points / attachment_forces. Allocates nothing.
  void fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const;
  int count() const { return count_; }
  // Buoyant: ρ_w V > m (water present).
  static bool buoyant(const riser_sim::Scene& scene, const riser_sim::AttachmentSpec& a);

 private:
  int count_ = 0;
  int first_ = -1;  // index of the first sphere in msg; then the arrows, then the names
  double length_, arrow_scale_ = 0.0, text_height_;  // arrow_scale_: [m/N]
};

}  // namespace riser_sim_ros
