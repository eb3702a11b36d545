// The range graph of a run: per station along the line, the least and largest value over the samples of the
// effective tension, the bending moment, the curvature and the seabed clearance, and the excursion of the
// touch-down point. Built over the one run contract (line_run.h: RunOutputs, planar or 3D alike). Stations:
// the rfes' middles (tension, clearance) and the joints (moment, curvature), at their unstretched arc length
// from the top. Sized once from the first outputs; add() allocates nothing.
#pragma once
#include <vector>

#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim {

// The seabed as a plane: clearance(p) = n·p - offset, the height of p above it along its unit normal n [m].
struct SeabedPlane {
  bool exists = false;
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;  // [m]
  double clearance(const Vec3& p) const { return normal.dot(p) - offset; }
};

// The scene's seabed in the 3D outputs' frame (z up): level at seabed.level, tilted by seabed.slope (3D
// scenes) as the contact force has it (spatial/forces/seabed.h). exists = seabed.enabled.
SeabedPlane seabedPlane(const Scene& scene);

// Least and largest value per station.
struct Envelope {
  std::vector<double> min, max;
};

class RangeGraph {
 public:
  // Sized from `first` (n + 1 rfes, n joints), which is the first sample. Throws std::invalid_argument when
  // its sizes do not match (points n + 2, joints n) or its arc lengths do not increase along the line.
  RangeGraph(const RunOutputs& first, const SeabedPlane& seabed);
  // One more sample: the same line (sizes checked in debug builds only). Allocates nothing.
  void add(const RunOutputs& o);
  // Starts over with `first` as the only sample (the line of the construction). Allocates nothing.
  void restart(const RunOutputs& first);

  long samples() const { return samples_; }
  bool hasSeabed() const { return seabed_.exists; }
  const std::vector<double>& stations() const { return s_; }             // rfe middles [m], n + 1
  const std::vector<double>& jointStations() const { return s_joint_; }  // joints 1..n [m], n
  const Envelope& tension() const { return tension_; }                   // effective tension (axial force) per rfe [N]
  const Envelope& clearance() const { return clearance_; }               // of each rfe's middle above the seabed [m]
  const Envelope& moment() const { return moment_; }        // bending moment per joint (planar signed, 3D |M|) [N m]
  const Envelope& curvature() const { return curvature_; }  // per joint [1/m]

  // Arc length of the station with the largest tension over the run [m].
  double tensionMaxS() const;
  double curvatureMax() const;   // [1/m]
  double curvatureMaxS() const;  // [m] (0 joints: NaN)
  // Touch-down point: the arc length of the first contact point from the top (joints A_0..A_n and the end,
  // clearance < 0, as the seabed force touches them); least and largest over the samples with contact [m].
  // NaN without a seabed or while the line never touched it; touchdownSamples() counts those samples.
  double touchdownMin() const { return td_min_; }
  double touchdownMax() const { return td_max_; }
  long touchdownSamples() const { return td_samples_; }

 private:
  SeabedPlane seabed_;
  std::vector<double> s_, s_joint_, s_point_;  // s_point_: arc length of the contact points (n + 2)
  Envelope tension_, clearance_, moment_, curvature_;
  double td_min_, td_max_;
  long td_samples_ = 0, samples_ = 0;
};

}  // namespace riser_sim
