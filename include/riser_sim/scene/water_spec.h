// The scene's sea (environment.water, current, waves): plain data, 3D vectors [x, y, z] with z up (REP 103).
// The planar engine reads the (x, z) of its vectors (scene/in_plane.h; planar/water.h), the 3D one all of them.
#pragma once
#include <vector>

#include "riser_sim/scene/choices.h"
#include "riser_sim/types.h"

namespace riser_sim {

struct CurrentSpec {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // uniform current at t = 0 [m/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // uniform acceleration of the current [m/s^2]
  struct Point {
    double depth;     // below the surface [m], increasing
    double vx;        // horizontal velocity [m/s]
    double vy = 0.0;  // along y (3D only; the planar engine reads vx) [m/s]
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
  double surface = 0.0;     // height z of the mean free surface [m]
  CurrentSpec current;
  WaveSpec waves;
};

}  // namespace riser_sim
