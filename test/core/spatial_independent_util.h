// Shared by the tests of the spatial independent formulation: a 3D top motion starting at rest, the
// angular momentum about the vertical, position comparison of the two spatial simulators.
#pragma once
#include <cmath>

#include "riser_sim/spatial/independent_formulation.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace spatial_test {

// p(t) = a ⊙ (cos(ω t) - 1) with ω per axis [rad/s]: starts at the origin at rest, leaves every plane
// when the ω differ.
class OscillatingTop : public spatial::TopMotion3 {
 public:
  OscillatingTop(const Vec3& amplitude, const Vec3& omega) : a_(amplitude), w_(omega) {}
  spatial::PointMotion3 at(double t) const override {
    spatial::PointMotion3 m;
    for (int k = 0; k < 3; ++k) {
      const double c = std::cos(w_[k] * t), s = std::sin(w_[k] * t);
      m.p[k] = a_[k] * (c - 1.0);
      m.v[k] = -a_[k] * w_[k] * s;
      m.a[k] = -a_[k] * w_[k] * w_[k] * c;
    }
    return m;
  }

 private:
  Vec3 a_, w_;
};

// Angular momentum about the z axis through the origin [kg m²/s]: point masses plus director inertia.
inline double angularMomentumZ(const spatial::Model3& m, const spatial::Kinematics3& kin) {
  double lz = 0.0;
  for (int i = 0; i < m.bodies(); ++i) {
    const Rfe& r = m.rfe(i);
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& q = r.part[p];
      lz += q.mass * kin[i].point(q.s0, q.kappa).cross(kin[i].velocity(q.s0, q.kappa)).z() +
            q.inertia * kin[i].omega().z();
    }
  }
  return lz;
}

}  // namespace spatial_test
}  // namespace riser_sim
