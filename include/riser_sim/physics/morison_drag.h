// Morison drag on a wet part of length l (paper eq. 12, by the cross-flow principle), for either engine
// (D = 2 planar, 3 spatial), on the velocity V' of the part's centroid relative to the water:
// F = -½ ρ_w D_out l [C_t |V'_ξ| V'_ξ e + C_n |V'_η| V'_η], V'_ξ = e·V' along the rfe's unit axis e and
// V'_η = V' - V'_ξ e across it [N]. The planar engine splits V'_η along its unit normal n = (-e_y, e_x).
#pragma once
#include <cmath>

#include <Eigen/Dense>

namespace riser_sim {
namespace physics {

template <int D>
using VecD = Eigen::Matrix<double, D, 1>;
template <int D>
using MatD = Eigen::Matrix<double, D, D>;

// The drag force [N] on the part: rel V' [m/s], e unit axis, density ρ_w [kg/m^3], diameter D_out [m],
// length l [m], cd_t C_t and cd_n C_n [-].
template <int D>
inline VecD<D> morisonDrag(const VecD<D>& rel, const VecD<D>& e, double density, double diameter, double length,
                           double cd_t, double cd_n) {
  static_assert(D == 2 || D == 3, "morisonDrag: 2D or 3D");
  const double k = 0.5 * density * diameter * length;
  const double vt = e.dot(rel);
  if constexpr (D == 2) {
    const VecD<D> n(-e.y(), e.x());
    const double vn = n.dot(rel);
    return -k * (cd_t * std::abs(vt) * vt * e + cd_n * std::abs(vn) * vn * n);
  } else {
    const VecD<D> vn = rel - vt * e;
    return -k * (cd_t * std::abs(vt) * vt * e + cd_n * vn.norm() * vn);
  }
}

// Its damping -∂F/∂V' [N s/m] = ½ ρ_w D_out l [2 C_t |V'_ξ| e eᵀ + C_n (|V'_η| (I - e eᵀ) + V'_η V'_ηᵀ / |V'_η|)]
// (in 2D the normal part is 2 C_n |V'_η| n nᵀ).
template <int D>
inline MatD<D> morisonDragDamping(const VecD<D>& rel, const VecD<D>& e, double density, double diameter, double length,
                                  double cd_t, double cd_n) {
  static_assert(D == 2 || D == 3, "morisonDragDamping: 2D or 3D");
  const double vt = e.dot(rel);
  if constexpr (D == 2) {
    const double k = 0.5 * density * diameter * length;
    const VecD<D> n(-e.y(), e.x());
    const double vn = n.dot(rel);
    return (2.0 * k * cd_t * std::abs(vt)) * e * e.transpose() + (2.0 * k * cd_n * std::abs(vn)) * n * n.transpose();
  } else {
    const double k = 0.5 * density * diameter;
    const VecD<D> vn = rel - vt * e;
    const double un = vn.norm();
    const MatD<D> P = MatD<D>::Identity() - e * e.transpose();
    MatD<D> C = (2.0 * cd_t * std::abs(vt)) * e * e.transpose() + (cd_n * un) * P;
    if (un > 0.0) C += (cd_n / un) * vn * vn.transpose();
    C *= k * length;
    return C;
  }
}

}  // namespace physics
}  // namespace riser_sim
