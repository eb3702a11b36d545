// The sea in 3D (world frame REP 103: x, y horizontal, z up): water density and level, a current (a 3D
// vector, optionally accelerating, or a depth profile of horizontal vectors) and regular linear (Airy)
// waves travelling along a heading, with the planar core's finite-depth kinematics. "Up" is against
// gravity: the level, the depths and the waves are measured along it.
#pragma once
#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/planar/water.h"

namespace riser_sim {
namespace spatial {

class Water3 {
 public:
  // gravity: the model's gravity vector [m/s^2] (non-zero). Waves need it along -z: throws
  // std::invalid_argument("environment.waves: ...") otherwise.
  Water3(const WaterSpec& spec, const Vec3& gravity);
  const WaterSpec& spec() const { return spec_; }
  bool moving() const { return moving_; }
  // Height of p above the mean free surface [m] (< 0 below it).
  double height(const Vec3& p) const { return up_.dot(p) - spec_.surface; }
  const Vec3& up() const { return up_; }
  // Water particle velocity [m/s] and acceleration [m/s^2] at p and t (zero above the surface). With waves, the
  // last samples are remembered per thread (a direct-mapped table keyed by this water, p and t, compared
  // exactly): the terms that ask at the same points in one evaluation (drag, Froude-Krylov, their
  // linearisation) pay for the wave components once.
  void at(const Vec3& p, double t, Vec3& velocity, Vec3& acceleration) const;
  // The steady part at time t: no waves, the current frozen at its velocity at t (what the statics see).
  Water3 steady(double t) const;

 private:
  WaterSpec spec_;
  Vec3 up_;
  Vec3 wave_dir_ = Vec3::UnitX();  // horizontal unit vector of the planar kinematics' +x
  WaterKinematics waves_;          // the waves alone, in the vertical plane along wave_dir_
  bool moving_ = false;
  unsigned long long id_ = 0;  // this water's identity (copies share it): the samples' key
  void compute(const Vec3& p, double t, Vec3& v, Vec3& a) const;
};

// The part of rfe i's part p (0: A_i to the spring, 1: the spring to the end) below the surface: its length [m],
// the distance of its centroid from A_i at Δ = 0 and the part's kappa (as the planar WetPart).
struct WetPart3 {
  double length = 0.0, s0 = 0.0, kappa = 0.0;
};
WetPart3 wetPart3(const Model& line, const BodyKinematics3& b, int i, int part, const Water3& water);

}  // namespace spatial
}  // namespace riser_sim
