#include "riser_sim/spatial/rfe_frames.h"

#include <cmath>

#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

namespace {
// A frame with x = e and y as close to world y as possible (world x when e is near world y).
Eigen::Quaterniond startFrame(const Eigen::Vector3d& e) {
  const Eigen::Vector3d ref = std::abs(e.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = (ref - ref.dot(e) * e).normalized();
  Eigen::Matrix3d R;
  R << e, y, e.cross(y);
  return Eigen::Quaterniond(R);
}
}  // namespace

void LineFrames::update(const AlignedVector<Eigen::Vector3d>& points, int nb, std::vector<Eigen::Quaterniond>& out) {
  Eigen::Quaterniond q = first_;
  Eigen::Vector3d prev = q * Eigen::Vector3d::UnitX();
  for (int i = 0; i < nb; ++i) {
    const Eigen::Vector3d e = (points[i + 1] - points[i]).normalized();
    // Not yet started, or a turn of more than 120 deg since the last call (a fold): start afresh.
    if (i == 0 && (!started_ || prev.dot(e) < -0.5))
      q = startFrame(e);
    else
      q = (Eigen::Quaterniond::FromTwoVectors(prev, e) * q).normalized();  // the minimal rotation prev -> e
    out[i] = q;
    prev = e;
    if (i == 0) first_ = q;
  }
  started_ = true;
}

Eigen::Quaterniond materialFrame(const Eigen::Vector3d& e, const Eigen::Vector3d& centre, const Eigen::Vector3d& ref,
                                 double theta) {
  const Eigen::Vector3d x = e.normalized();
  Eigen::Vector3d u = minimalRotation(centre, x, ref);
  u = (u - u.dot(x) * x).normalized();  // round-off off the normal plane
  const Eigen::Vector3d y = std::cos(theta) * u + std::sin(theta) * x.cross(u);
  Eigen::Matrix3d R;
  R << x, y, x.cross(y);
  return Eigen::Quaterniond(R).normalized();
}

}  // namespace spatial
}  // namespace riser_sim
