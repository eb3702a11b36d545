// Buoyancy and Froude-Krylov force on a wet part of length l (paper eq. 11, 13, 16), for either engine
// (D = 2 planar, 3 spatial). The lift per submerged length is ρ_w A_w |g| [N/m] (A_w the displaced area),
// applied up at the wet part's centroid, with potential V = -ρ_w A_w |g| l h (h the centroid's height above the
// mean surface, h < 0 under water). The water's acceleration a_w adds the Froude-Krylov force
// ρ_w A_w l [C_M a_w,η + C_m,t a_w,ξ], a_w,ξ = (e·a_w) e along the rfe and a_w,η = a_w - a_w,ξ across it.
#pragma once
#include "riser_sim/physics/morison_drag.h"

namespace riser_sim {
namespace physics {

// ρ_w A_w |g| [N/m]: density [kg/m^3], area A_w [m^2], gravity |g| [m/s^2].
inline double liftPerLength(double density, double area, double gravity) { return density * area * gravity; }

// The lift [N] on a wet length l [m] with lift_per_length f [N/m], along the unit vector up.
template <int D>
inline VecD<D> buoyancyForce(double lift_per_length, double wet_length, const VecD<D>& up) {
  return (lift_per_length * wet_length) * up;
}

// Its potential [J] at the centroid's height h [m] above the mean surface.
inline double buoyancyPotential(double lift_per_length, double wet_length, double height) {
  return -(lift_per_length * wet_length * height);
}

// The Froude-Krylov force [N] on the wet part: rho_a ρ_w A_w [kg/m], length l [m], water acceleration a_w [m/s^2],
// e unit axis, cm_normal C_M, cm_axial C_m,t = 1 + C_a,t. 2D splits a_w along the unit normal n = (-e_y, e_x).
template <int D>
inline VecD<D> froudeKrylov(double rho_a, double wet_length, const VecD<D>& a_w, const VecD<D>& e, double cm_normal,
                            double cm_axial) {
  static_assert(D == 2 || D == 3, "froudeKrylov: 2D or 3D");
  if constexpr (D == 2) {
    const VecD<D> n(-e.y(), e.x());
    return rho_a * wet_length * (cm_normal * n.dot(a_w) * n + cm_axial * e.dot(a_w) * e);
  } else {
    const VecD<D> along = e.dot(a_w) * e;
    return (rho_a * wet_length) * (cm_normal * (a_w - along) + cm_axial * along);
  }
}

}  // namespace physics
}  // namespace riser_sim
