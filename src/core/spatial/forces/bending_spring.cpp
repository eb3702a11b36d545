#include "riser_sim/spatial/forces/bending_spring.h"

#include <cmath>

namespace riser_sim {
namespace spatial {

namespace {
// θ / sin θ, exact to round-off for small θ (series 1 + θ²/6 + 7θ⁴/360).
double thetaOverSin(double theta) {
  if (theta < 1e-4) {
    const double t2 = theta * theta;
    return 1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0;
  }
  return theta / std::sin(theta);
}
constexpr double kFoldedTol = 1e-12;  // [rad] from π: bending direction undefined, no spring force
}  // namespace

// V = ½ k θ²: Q_b = -k θ ∂θ/∂b = k (θ/sinθ) / (|a||b|) (a - (a·b) b/|b|²), Q_a likewise with a, b swapped.
void BendingSpring::addForces(const SpatialModel& model, const Kinematics3& kin, double, VecX& Q) const {
  const double k = model.bendingStiffness(), c = model.bendingDamping();
  for (int i = 1; i < model.bodies(); ++i) {
    const Vec3& a = kin[i - 1].e;
    const Vec3& b = kin[i].e;
    double* qa = Q.data() + kDofPerBody3 * (i - 1);
    double* qb = Q.data() + kDofPerBody3 * i;
    const double theta = angle(a, b);
    if (k != 0.0 && theta < M_PI - kFoldedTol) {
      const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
      const double f = k * thetaOverSin(theta) / std::sqrt(aa * bb);
      const Vec3 Fa = f * (b - (ab / aa) * a), Fb = f * (a - (ab / bb) * b);
      for (int j = 0; j < 3; ++j) qa[kE + j] += Fa[j], qb[kE + j] += Fb[j];
    }
    if (c != 0.0) {
      const Vec3 tau = -c * (kin[i].omega() - kin[i - 1].omega());  // on rfe i; -tau on rfe i-1
      addTorque(kin[i], tau, qb);
      addTorque(kin[i - 1], -tau, qa);
    }
  }
}

double BendingSpring::potentialEnergy(const SpatialModel& model, const Kinematics3& kin) const {
  double v = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double theta = angle(kin[i - 1].e, kin[i].e);
    v += 0.5 * model.bendingStiffness() * theta * theta;
  }
  return v;
}

double BendingSpring::power(const SpatialModel& model, const Kinematics3& kin, double) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) p -= model.bendingDamping() * (kin[i].omega() - kin[i - 1].omega()).squaredNorm();
  return p;
}

}  // namespace spatial
}  // namespace riser_sim
