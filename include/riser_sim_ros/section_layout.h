// Where the line's sections (line.sections, riser_sim/line/line_sections.h) fall on the RFEM discretisation: the
// segments of each section and the section of each rfe, from the scene once per run.
#pragma once
#include <vector>

#include "riser_sim/scene/scene.h"

namespace riser_sim_ros {

struct SectionLayout {
  std::vector<int> first_segment;  // per section k: its first segment; one more entry: n (K + 1 entries)
  // Per rfe i = 0..n: the section of segment min(i, n - 1), the segment that starts at rfe i's axial spring
  // (rfe 0 is the first half of segment 0, rfe n the second half of segment n - 1: riser_sim/planar/model.h).
  std::vector<int> rfe_section;
  int sections() const { return static_cast<int>(first_segment.size()) - 1; }
};

// The layout of the scene's line as the core resolves it (riser_sim::resolveLine). Throws std::logic_error
// when its segments do not add up to scene.elements (the run's n).
SectionLayout sectionLayout(const riser_sim::Scene& scene);

}  // namespace riser_sim_ros
