// Positions and velocities of every rfe, computed once per evaluation and shared by all force terms.
#pragma once
#include "riser_sim/types.h"

namespace riser_sim {

struct BodyKinematics {
  Vec2 A = Vec2::Zero();                // point A_i [m]
  Vec2 A_dot = Vec2::Zero();            // [m/s]
  double delta = 0.0, delta_dot = 0.0;  // Δ_i [m], [m/s]
  double phi = 0.0, phi_dot = 0.0;      // φ_i [rad], [rad/s] from the x axis
  double c = 1.0, s = 0.0;              // cos φ_i, sin φ_i
  double len = 0.0;                     // l_i + Δ_i [m]

  Vec2 e() const { return Vec2(c, s); }     // unit vector along the rfe (ξ)
  Vec2 nrm() const { return Vec2(-s, c); }  // unit normal (η)
  // Point at distance s0 + kappa*Δ from A_i, and its velocity.
  Vec2 point(double s0, double kappa) const { return A + (s0 + kappa * delta) * e(); }
  Vec2 velocity(double s0, double kappa) const {
    return A_dot + kappa * delta_dot * e() + (s0 + kappa * delta) * phi_dot * nrm();
  }
  Vec2 end() const { return A + len * e(); }  // end point (A_{i+1} when constraints hold)
  Vec2 endVelocity() const { return velocity(len - delta, 1.0); }
};

using Kinematics = AlignedVector<BodyKinematics>;

// Generalised force (absolute coordinates of rfe i) of a force F [N] applied at distance s0 + kappa*Δ_i.
inline Vec4 pointForce(const BodyKinematics& b, double s0, double kappa, const Vec2& F) {
  const double s = s0 + kappa * b.delta;
  return Vec4(F.x(), F.y(), kappa * b.e().dot(F), s * b.nrm().dot(F));
}

}  // namespace riser_sim
