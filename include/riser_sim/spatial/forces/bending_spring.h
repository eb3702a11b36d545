// Bending springs c = EI/d between rfe i-1 and i (i = 1..n): V = ½ c θ², θ = atan2(|a×b|, a·b) the angle
// between a = e_{i-1} and b = e_i (planar line: θ = |φ_i - φ_{i-1}|, the planar energy). θ is
// homogeneous of degree 0 in a and in b, so its gradient is tangent: ∂θ/∂b = (c_ab b/|b|² - a) / s_ab
// with c_ab = a·b, s_ab = |a×b|; the factor θ/sinθ -> 1 as θ -> 0 (no NaN at θ = 0). At θ = π (a fully
// folded joint) the direction of bending is undefined: the spring force is set to zero there (only
// within 1e-12 rad of π; elsewhere it is exact).
// Bending damping: equal and opposite torques -c_d (ω_i - ω_{i-1}) on rfe i (ω = e × e'), the planar
// c_d (φ'_i - φ'_{i-1}) for a planar line.
#pragma once
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class BendingSpring : public ForceTerm3 {
 public:
  std::string name() const override { return "bending_spring"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  // Forces and the dampers' power in one pass over the joints (one ω difference per joint).
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
  // Angle between two directions [rad] in [0, π] (any lengths).
  static double angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }
  // θ / sin θ without cancellation near 0 (the spring force's factor).
  static double thetaOverSin(double theta);
  // θ/sinθ from sin²θ <= kSeriesSin2 (θ < 90°), by its series (bending_spring.cpp).
  static double asinOverSin(double sin2);
  static constexpr double kSeriesSin2 = 0.01;
  // [rad] from π: the bending direction is undefined there, no spring force (flex joints likewise).
  static constexpr double kFoldedTol = 1e-12;
};

}  // namespace spatial
}  // namespace riser_sim
