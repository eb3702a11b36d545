#include "riser_sim_ros/section_layout.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "riser_sim/line/line_sections.h"

namespace riser_sim_ros {

SectionLayout sectionLayout(const riser_sim::Scene& scene) {
  const std::vector<riser_sim::LineSection> sections = riser_sim::lineSections(scene);
  const std::vector<int> segment = riser_sim::resolveLine(sections, scene.stiffeners).section;
  const int n = static_cast<int>(segment.size());
  if (n != scene.elements || n < 1)
    throw std::logic_error("sectionLayout: the sections resolve to " + std::to_string(n) +
                           " segments, the scene has line.elements " + std::to_string(scene.elements));
  SectionLayout layout;
  const int k_count = static_cast<int>(sections.size());
  layout.first_segment.assign(k_count + 1, n);
  for (int j = n - 1; j >= 0; --j) layout.first_segment[segment[j]] = j;
  for (int k = 0; k < k_count; ++k)  // each section a run of segments, in order from the top
    if (layout.first_segment[k] + sections[k].elements != layout.first_segment[k + 1])
      throw std::logic_error("sectionLayout: line.sections[" + std::to_string(k) + "] has " +
                             std::to_string(sections[k].elements) + " elements, the resolved line does not");
  layout.rfe_section.resize(n + 1);
  for (int i = 0; i <= n; ++i) layout.rfe_section[i] = segment[std::min(i, n - 1)];
  return layout;
}

}  // namespace riser_sim_ros
