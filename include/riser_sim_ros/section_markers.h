// rviz markers of the line's sections (line.sections), added to LineMarkers' array and filled in place with
// it: one LINE_STRIP per section (ns `sections`, id kFirstId + k), a translucent sleeve around the line in a
// fixed colour per section index (sectionColour), from the section's first segment to its last. A segment
// j runs from rfe j's axial spring (the top A_0 for j = 0) through A_{j+1} to rfe j+1's spring (the end of
// rfe n for j = n - 1), so the sleeves meet at the springs, where the sections meet.
#pragma once
#include <string>

#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "riser_sim/run/line_run.h"
#include "riser_sim_ros/section_layout.h"

namespace riser_sim_ros {

// The colour of section k: a fixed palette of kPalette colours, repeated past the last.
constexpr int kSectionPalette = 8;
std_msgs::ColorRGBA sectionColour(int k);

class SectionMarkers {
 public:
  static constexpr int kFirstId = 200;
  // Appends one strip per section of `layout` to msg, `width` wide [m].
  SectionMarkers(const SectionLayout& layout, double width, const std::string& fixed_frame,
                 visualization_msgs::MarkerArray& msg);
  // Updates the strips in msg for the line in `out`. Allocates nothing.
  void fill(const riser_sim::RunOutputs& out, visualization_msgs::MarkerArray& msg) const;

 private:
  SectionLayout layout_;
  int first_ = -1;  // index of the first strip in msg
};

}  // namespace riser_sim_ros
