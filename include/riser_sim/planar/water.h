// Sea state: water density and free surface, current (uniform or depth profile, optionally
// accelerating) and linear waves with finite-depth kinematics: regular (Airy) or irregular long-crested
// (a sum of Airy components from a JONSWAP spectrum, random phases from a seed).
#pragma once
#include <vector>

#include "riser_sim/scene/choices.h"
#include "riser_sim/types.h"

namespace riser_sim {

struct CurrentSpec {
  Vec2 velocity = Vec2::Zero();      // uniform current at t = 0 [m/s] (x, y_up: the planar core's plane)
  Vec2 acceleration = Vec2::Zero();  // uniform acceleration of the current [m/s^2]
  // The same in 3D (x, y horizontal, z up; the planar ones are their (x, z)): the spatial core reads these.
  Eigen::Vector3d velocity3 = Eigen::Vector3d::Zero(), acceleration3 = Eigen::Vector3d::Zero();
  struct Point {
    double depth;     // below the surface [m], increasing
    double vx;        // horizontal velocity [m/s]
    double vy = 0.0;  // the other horizontal component (3D only) [m/s]
  };
  std::vector<Point> profile;  // depth profile (replaces the horizontal velocity when given), linear between points
};

struct WaveSpec {
  WaveKind type = WaveKind::kRegular;  // regular (Airy) or irregular long-crested (JONSWAP)
  double height = 0.0;                 // H, crest to trough [m]; 0 = no waves
  double period = 10.0;                // T [s]
  double phase = 0.0;                  // [rad]
  double direction = 1.0;  // +1 travels towards +x, -1 towards -x (in 3D: along +-(cos heading, sin heading))
  double heading = 0.0;    // azimuth of +direction from +x towards +y [rad] (3D only; planar: 0)
  double depth = 1000.0;   // water depth for the dispersion relation [m]
  double ramp = 0.0;       // amplitude ramped from 0 at t = 0 to full at t = ramp, ½(1 - cos πt/ramp) [s]; 0 = none
  // jonswap: significant height Hs [m] (0 = no waves), peak period Tp [s], peak enhancement γ, the number of
  // components on [0.5, 3] ω_p (equal bins) and the seed of their random phases (the same seed, the same sea).
  double significant_height = 0.0, peak_period = 10.0, gamma = 3.3;
  int components = 100;
  unsigned seed = 1;
  bool active() const { return type == WaveKind::kRegular ? height > 0.0 : significant_height > 0.0; }
};

struct WaterSpec {
  bool enabled = false;
  double density = 1025.0;  // ρ_w [kg/m^3]
  double surface = 0.0;     // y of the mean free surface [m]
  CurrentSpec current;
  WaveSpec waves;
};

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
