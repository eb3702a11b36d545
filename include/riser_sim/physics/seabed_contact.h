// Seabed contact of one point (penalty law of the paper's J-lay case, with the 3D core's friction), for either
// engine: with the penetration δ > 0 below the plane (unit normal n) and the point's velocity v,
// - normal: F_n = max(C_n δ - c_n v_n, 0) (never pulls), V = ½ C_n δ²;
// - tangential damping -c_t v_h, v_h = v - v_n n;
// - Coulomb friction, smoothed: F_f = -F_n (μ_a v_a a + μ_l v_l l) / sqrt(v_a² + v_l² + v_s²) along the plane's
//   axes a (the line's direction on the plane) and l = n × a; it saturates at μ F_n above the speed v_s and acts
//   as a viscous stick below it.
#pragma once
#include <algorithm>
#include <cmath>

#include "riser_sim/physics/morison_drag.h"

namespace riser_sim {
namespace physics {

// F_n [N] for stiffness C_n [N/m], penetration δ [m] and the damper's force c_n v_n [N] (0: without damping).
inline double contactNormalForce(double stiffness, double penetration, double damping_force) {
  return std::max(stiffness * penetration - damping_force, 0.0);
}

// ½ C_n δ² [J].
inline double contactSpringEnergy(double stiffness, double penetration) {
  return 0.5 * stiffness * penetration * penetration;
}

// The plane's axes for the friction: a the unit projection of the line's axis e on the plane of unit normal n
// (any direction when e is upright), l = n × a.
inline void frictionAxes(const VecD<3>& e, const VecD<3>& n, VecD<3>& a, VecD<3>& l) {
  a = e - n.dot(e) * n;
  const double an = a.norm();
  a = an > 1e-12 ? VecD<3>(a / an) : VecD<3>(n.unitOrthogonal());
  l = n.cross(a);
}

// F_f [N] for the normal force fn [N], the velocity along the plane v_h [m/s], its axes a, l, the coefficients
// μ_a, μ_l [-] and the sliding speed v_s [m/s].
template <int D>
inline VecD<D> smoothedFriction(double fn, const VecD<D>& v_h, const VecD<D>& a, const VecD<D>& l, double mu_a,
                                double mu_l, double v_s) {
  const double va = v_h.dot(a), vl = v_h.dot(l);
  return -(fn / std::sqrt(va * va + vl * vl + v_s * v_s)) * (mu_a * va * a + mu_l * vl * l);
}

}  // namespace physics
}  // namespace riser_sim
