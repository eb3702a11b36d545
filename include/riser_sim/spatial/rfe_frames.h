// Frames of the rfes of a 3D line (x along each rfe), for display and tf: the minimal-rotation frames when
// the line has no material frame, the material frames with line.torsion.
#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "riser_sim/types.h"

namespace riser_sim {
namespace spatial {

// Frames along a 3D line: frame i has its x axis along rfe i; the others follow by the minimal rotation
// from rfe i - 1's frame, and rfe 0's by the minimal rotation from its frame at the previous call (first
// call: y as close to world y as x allows). So they turn continuously in time and along the line and are
// never singular for vertical or horizontal elements. Not the material frame: without torsion there is no
// twist to show (with line.torsion: materialFrame). Allocates nothing.
class LineFrames {
 public:
  // x_i = unit (points[i + 1] - points[i]), i = 0..nb - 1; out[0..nb - 1] gets the rotations.
  void update(const AlignedVector<Eigen::Vector3d>& points, int nb, std::vector<Eigen::Quaterniond>& out);

 private:
  Eigen::Quaterniond first_ = Eigen::Quaterniond::Identity();
  bool started_ = false;
};

// The material frame of an rfe with torsion on (torsion.h): x along e, y the chart reference
// R(centre -> e) ref turned by the spin angle theta about e, z = x × y. rfe 0: the hang-off's axis and
// reference, theta = 0 (held in twist).
Eigen::Quaterniond materialFrame(const Eigen::Vector3d& e, const Eigen::Vector3d& centre, const Eigen::Vector3d& ref,
                                 double theta);

}  // namespace spatial
}  // namespace riser_sim
