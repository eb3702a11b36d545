// The extremes of a sectioned line per section (line.sections) and of a wave configuration, over a run: per
// section the largest effective tension and the largest curvature with their arc lengths (from the range graph's
// envelopes, range_graph.h), and for a lazy or steep wave the sag and hog bends' heights. Elevations are tracked
// here at the line's points A_0..A_n and the end (their unstretched arc length from the top) over the samples;
// add() allocates nothing.
//
// Wave configuration: the line has a buoyant section (its mass per length, contents included, below the water it
// displaces, ρ_w π D²/4) and, over the run, the lowest point before that section's start (the sag bend: least
// elevation reached there) is followed along the line by a point higher than it that is not the line's last
// point (the hog bend: the largest elevation reached after the sag).
#pragma once
#include <vector>

#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim {

class SectionExtremes {
 public:
  // The scene's sections (one when line.sections is absent) and the first sample. Throws std::invalid_argument
  // when first's points do not match the arc lengths (n + 2 points, n + 1 rfes).
  SectionExtremes(const Scene& scene, const RunOutputs& first);
  void add(const RunOutputs& o);  // one more sample of the same line; allocates nothing

  struct PerSection {
    double start = 0.0, end = 0.0;                      // arc length from the top [m]
    double tension_max = 0.0, tension_max_s = 0.0;      // over the rfes whose middle is in [start, end) [N], [m]
    double curvature_max = 0.0, curvature_max_s = 0.0;  // over the joints in [start, end) [1/m], [m]; NaN: none
  };
  // From the range graph of the same run (its stations): the last section also holds the station at its end.
  std::vector<PerSection> sections(const RangeGraph& graph) const;

  struct Wave {
    bool found = false;
    double sag_z = 0.0, sag_s = 0.0;  // the sag bend: its least elevation [m] and arc length [m]
    double hog_z = 0.0, hog_s = 0.0;  // the hog bend: its largest elevation [m] and arc length [m]
    int buoyant_section = -1;         // the first buoyant section (-1: none)
  };
  Wave wave() const;

  const std::vector<double>& pointStations() const { return s_point_; }  // A_0..A_n, the end [m]
  const Envelope& elevation() const { return z_; }                       // z of those points [m]

 private:
  std::vector<double> bounds_;  // section boundaries from the top, sections + 1 [m]
  int buoyant_ = -1;
  std::vector<double> s_point_;
  Envelope z_;
};

}  // namespace riser_sim
