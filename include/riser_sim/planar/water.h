// Sea state: water density and free surface, current (uniform or depth profile, optionally
// accelerating) and linear waves with finite-depth kinematics: regular (Airy) or irregular long-crested
// (a sum of Airy components from a JONSWAP spectrum, random phases from a seed).
#pragma once
#include <vector>

#include "riser_sim/scene/in_plane.h"
#include "riser_sim/scene/water_spec.h"
#include "riser_sim/types.h"

namespace riser_sim {

class WaterKinematics {
 public:
  WaterKinematics(const WaterSpec& spec, double gravity);
  const WaterSpec& spec() const { return spec_; }
  bool moving() const { return moving_; }
  // Water particle velocity and acceleration at point p [m] and time t [s] (zero above the surface).
  void at(const Vec2& p, double t, Vec2& velocity, Vec2& acceleration) const;
  double waveNumber() const { return comp_.empty() ? 0.0 : comp_.front().k; }  // regular: from ω² = g k tanh(k h)
  // Surface elevation above the mean level [m] at horizontal position x and time t (ramp included).
  double elevation(double x, double t) const;
  // The wave components: amplitude [m], ω [rad/s], k [1/m], phase [rad] (one for regular waves).
  struct Component {
    double a, omega, k, phase, decay, e2kh;  // decay: 1 - e^{-2kh}; e2kh: e^{-2kh}
  };
  const std::vector<Component>& components() const { return comp_; }
  // The JONSWAP spectral density S(ω) [m² s/rad] of a sea with Hs, Tp, γ, before the normalisation to Hs
  // (the Pierson-Moskowitz shape with α = 1; WaterKinematics scales the components to m0 = Hs²/16).
  static double jonswapShape(double omega, double omega_p, double gamma);
  // The steady part at time t: no waves, the current frozen at its velocity at t (what the statics see).
  WaterKinematics steady(double t) const;
  // The same with the current's velocity (uniform and profile) x current_factor.
  WaterKinematics steady(double t, double current_factor) const;
  // Wave amplitude factor at t (0 before, 1 after the ramp) and its rate [1/s] in *rate.
  double rampFactor(double t, double* rate = nullptr) const;

 private:
  // cosh(k(z+h))/sinh(kh) and sinh(k(z+h))/sinh(kh) at z below the surface, finite for any k h.
  void depthRatios(const Component& c, double z, double& ch, double& sh) const;
  WaterSpec spec_;
  Vec2 velocity_, acceleration_;  // the uniform current's (x, z): the plane's (x, y_up)
  std::vector<Component> comp_;
  bool moving_ = false;
};

// Portion of a straight segment p0→p1 below the level ys: fraction of its length and the centroid of
// that portion as a fraction from p0.
inline void submerged(double y0, double y1, double ys, double& fraction, double& centroid) {
  if (y0 <= ys && y1 <= ys) {
    fraction = 1.0, centroid = 0.5;
  } else if (y0 > ys && y1 > ys) {
    fraction = 0.0, centroid = 0.5;
  } else {
    const double t = (ys - y0) / (y1 - y0);
    if (y0 <= ys)
      fraction = t, centroid = 0.5 * t;
    else
      fraction = 1.0 - t, centroid = 0.5 * (1.0 + t);
  }
}

}  // namespace riser_sim
