// Shared by the 3D sea tests: a 60 m line in the sea, and the planar sea scene yawed into 3D run against the
// planar core (the planar-through-3D check of docs/spatial.md).
#pragma once
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/simulator.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace spatial_test {

// A 60 m line, n = 12, hung from 5 m above the surface (its top crosses it), with drag. Axial ω ~ 60 rad/s:
// rk4 at 0.01 s is well inside its limit (ω h ~ 0.6).
inline const char* kSeaLine = R"(line:
  length: 60.0
  elements: 12
  EA: 1.0e7
  EI: 1.0e5
  mass_per_length: 100.0
  outer_diameter: 0.3
  axial_damping: 1.0e4
  bending_damping: 1.0e3
  end_mass: 200.0
hydrodynamics:
  drag_normal: 1.2
  drag_tangential: 0.1
solver:
  integrator: rk4
  dt: 0.01
)";

inline std::string num17(double v) {
  char b[40];
  std::snprintf(b, sizeof(b), "%.17g", v);
  return b;
}

inline spatial::Mat3 yawDeg(double deg) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, spatial::Vec3::UnitZ()).toRotationMatrix();
}

// The planar sea (the top 5 m above the surface swaying in x and z, a current profile, 3 m waves ramped in
// over 2 s) and the same sea yawed by psi [deg] as a 3D scene (top, amplitude, current and heading rotated).
struct YawedSea {
  std::string planar, spatial;
};
inline YawedSea yawedSea(double psi) {
  const spatial::Mat3 R = yawDeg(psi);
  const double c = std::cos(psi * M_PI / 180.0), s = std::sin(psi * M_PI / 180.0);
  YawedSea y;
  y.planar = R"(top:
  position: [0.0, 5.0]
  motion: {type: sinusoid, amplitude: [0.8, 0.4], period: 6.0}
environment:
  water: {density: 1025.0, surface: 0.0}
  current:
    profile: [[0.0, 0.9], [40.0, 0.3]]
  waves: {height: 3.0, period: 7.0, depth: 200.0, ramp: 2.0}
)";
  const spatial::Vec3 rt = R * spatial::Vec3(0.0, 0.0, 5.0), ra = R * spatial::Vec3(0.8, 0.0, 0.4);
  y.spatial = "space: spatial\ntop:\n  position: [" + num17(rt.x()) + ", " + num17(rt.y()) + ", " + num17(rt.z()) +
              "]\n  motion: {type: sinusoid, amplitude: [" + num17(ra.x()) + ", " + num17(ra.y()) + ", " +
              num17(ra.z()) +
              "], period: 6.0}\nenvironment:\n  water: {density: 1025.0, surface: 0.0}\n"
              "  current:\n    profile: [[0.0, " +
              num17(0.9 * c) + ", " + num17(0.9 * s) + "], [40.0, " + num17(0.3 * c) + ", " + num17(0.3 * s) +
              "]]\n  waves: {height: 3.0, period: 7.0, depth: 200.0, "
              "ramp: 2.0, heading: " +
              num17(psi) + "}\n";
  return y;
}

// Largest distance [m] between the joints of the planar run (rotated by R into 3D) and of the 3D run, sampled
// every 100 steps over `duration` [s]; both step at the same dt. *planar_end0: the planar end's x at t = 0.
inline double planarVs3D(riser_sim::Run& planar, spatial::Run3& run, const spatial::Mat3& R, double duration,
                         double* planar_end0 = nullptr) {
  Kinematics kin2(planar.model->bodies());
  const long steps = std::lround(duration / run.dt());
  double worst = 0.0;
  for (long k = 0; k <= steps; ++k) {
    if (k > 0 && (!planar.sim->step() || !run.step())) return HUGE_VAL;
    if (k % 100) continue;
    planar.sim->kinematics(kin2);
    const spatial::LineOutputs3& o = run.outputs();
    for (int i = 0; i < planar.model->bodies(); ++i)
      worst = std::max(worst, (o.points[i] - spatial::planarPoint(kin2[i].A, R)).norm());
    if (k == 0 && planar_end0) *planar_end0 = kin2.back().end().x();
  }
  return worst;
}

}  // namespace spatial_test
}  // namespace riser_sim
