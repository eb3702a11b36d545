#include "riser_sim/spatial/joint_bending.h"

#include <cmath>

#include "riser_sim/spatial/forces/bending_spring.h"

namespace riser_sim {
namespace spatial {

BendingJoint bendingJoint(const BodyKinematics3& a, const BodyKinematics3& b, double stiffness, double damping,
                          double segment) {
  BendingJoint j;
  const Vec3 axis = a.e.cross(b.e);
  const double s = axis.norm(), theta = BendingSpring::angle(a.e, b.e);
  j.curvature = theta / segment;
  // The spring's direction is a x b; none at theta = 0 (no moment) or folded (theta = pi: undefined, and
  // the spring has no force there either).
  if (s > 0.0 && theta < M_PI - BendingSpring::kFoldedTol) j.moment = (stiffness * theta / s) * axis;
  j.moment += damping * (b.omega() - a.omega());
  return j;
}

}  // namespace spatial
}  // namespace riser_sim
