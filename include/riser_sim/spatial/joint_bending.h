// The bending of a joint of a 3D line as the isotropic bending spring and damper see it (forces/bending_spring.h).
#pragma once
#include "riser_sim/spatial/kinematics.h"

namespace riser_sim {
namespace spatial {

// The bending of joint i between rfes a = i - 1 and b = i: curvature |κ| = θ / d [1/m] (θ the angle between
// e_a and e_b, d the segment length) and the moment vector [N m], EI κ along e_a × e_b (c θ, c = EI/d, the
// bending spring) plus the bending damper's c_d (ω_b - ω_a). Finite for any directions.
struct BendingJoint {
  double curvature = 0.0;
  Vec3 moment = Vec3::Zero();
};
BendingJoint bendingJoint(const BodyKinematics3& a, const BodyKinematics3& b, double stiffness, double damping,
                          double segment);

}  // namespace spatial
}  // namespace riser_sim
