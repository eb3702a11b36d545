// Per-section extremes and the wave configuration's bends (section_extremes.h).
#include "riser_sim/run/section_extremes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace riser_sim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The section of arc length s: [bounds_k, bounds_k+1), the line's end in the last one.
int sectionOf(const std::vector<double>& bounds, double s) {
  const int n = static_cast<int>(bounds.size()) - 1;
  for (int k = 0; k + 1 < n; ++k)
    if (s < bounds[k + 1]) return k;
  return n - 1;
}

// The largest of v per section at stations s: (value, its station); NaN where a section has no station.
void maxPerSection(const std::vector<double>& v, const std::vector<double>& s, const std::vector<double>& bounds,
                   std::vector<SectionExtremes::PerSection>& out, bool tension) {
  for (auto& p : out)
    (tension ? p.tension_max : p.curvature_max) = (tension ? p.tension_max_s : p.curvature_max_s) = kNaN;
  for (size_t i = 0; i < v.size(); ++i) {
    SectionExtremes::PerSection& p = out[sectionOf(bounds, s[i])];
    double& value = tension ? p.tension_max : p.curvature_max;
    double& at = tension ? p.tension_max_s : p.curvature_max_s;
    if (std::isnan(value) || v[i] > value) value = v[i], at = s[i];
  }
}

}  // namespace

SectionExtremes::SectionExtremes(const Scene& scene, const RunOutputs& first) {
  const std::vector<LineSection> sections = lineSections(scene);
  bounds_.push_back(0.0);
  for (size_t k = 0; k < sections.size(); ++k) {
    bounds_.push_back(bounds_.back() + sections[k].length);
    const LineProperties& p = sections[k].props;
    if (buoyant_ < 0 && scene.water.enabled &&
        p.mass_per_length + p.content_mass_per_length < scene.water.density * p.externalArea())
      buoyant_ = static_cast<int>(k);
  }
  const size_t nb = first.arc_length.size();
  if (nb < 1 || first.points.size() != nb + 1)
    throw std::invalid_argument("SectionExtremes: outputs with " + std::to_string(nb) + " rfes and " +
                                std::to_string(first.points.size()) + " points (expected n + 1, n + 2)");
  s_point_.assign(nb + 1, 0.0);  // A_i starts rfe i: s_begin_{i+1} = 2 s_mid_i - s_begin_i (as the range graph)
  for (size_t i = 0; i < nb; ++i) s_point_[i + 1] = 2.0 * first.arc_length[i] - s_point_[i];
  z_.min.assign(nb + 1, 0.0);
  z_.max.assign(nb + 1, 0.0);
  for (size_t j = 0; j <= nb; ++j) z_.min[j] = z_.max[j] = first.points[j].z();
}

void SectionExtremes::add(const RunOutputs& o) {
  for (size_t j = 0; j < z_.min.size(); ++j) {
    const double z = o.points[j].z();
    z_.min[j] = std::min(z_.min[j], z);
    z_.max[j] = std::max(z_.max[j], z);
  }
}

std::vector<SectionExtremes::PerSection> SectionExtremes::sections(const RangeGraph& graph) const {
  std::vector<PerSection> out(bounds_.size() - 1);
  for (size_t k = 0; k < out.size(); ++k) out[k].start = bounds_[k], out[k].end = bounds_[k + 1];
  maxPerSection(graph.tension().max, graph.stations(), bounds_, out, true);
  maxPerSection(graph.curvature().max, graph.jointStations(), bounds_, out, false);
  return out;
}

SectionExtremes::Wave SectionExtremes::wave() const {
  Wave w;
  w.buoyant_section = buoyant_;
  if (buoyant_ < 0) return w;
  const double start = bounds_[buoyant_];
  const size_t np = s_point_.size();
  size_t sag = np;
  for (size_t j = 0; j < np && s_point_[j] < start; ++j)
    if (sag == np || z_.min[j] < z_.min[sag]) sag = j;
  if (sag == np) return w;  // the buoyant section starts at the top
  size_t hog = sag;
  for (size_t j = sag + 1; j < np; ++j)
    if (z_.max[j] > z_.max[hog]) hog = j;
  if (hog == sag || hog + 1 == np || !(z_.max[hog] > z_.min[sag])) return w;  // rises to the end: no hog bend
  w.found = true;
  w.sag_z = z_.min[sag];
  w.sag_s = s_point_[sag];
  w.hog_z = z_.max[hog];
  w.hog_s = s_point_[hog];
  return w;
}

}  // namespace riser_sim
