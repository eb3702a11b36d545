// Top (or bottom) motion in 3D driven by external samples (vessel or ROV poses): the planar
// ExternalMotion (external_motion.h) on (x, z) and on (y, 0), so every axis is smoothed exactly as the
// planar node smooths x and z (same fit, blend, coast, stop and options). Built with an orientation, it
// also smooths the holder's attitude the same way, as Z-Y-X angles (roll, pitch) and (yaw, 0), yaw and roll
// unwrapped across ±π (a vessel may turn any number of times; pitch must stay clear of ±90°, where those
// angles are singular), and at() gives R and w: a flex joint's axis turns with it. at() and addSample()
// allocate nothing.
#pragma once
#include <Eigen/Geometry>

#include "riser_sim/external_motion.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {

class ExternalMotion3 : public TopMotion3 {
 public:
  // At rest at p from time t (R = I always). Throws std::invalid_argument for invalid options (as ExternalMotion).
  explicit ExternalMotion3(const Vec3& p, double t = 0.0, const ExternalMotionOptions& options = {});
  // At rest at p with orientation q (holder frame -> world, normalised) from time t; rotates().
  ExternalMotion3(const Vec3& p, const Eigen::Quaterniond& q, double t, const ExternalMotionOptions& options = {});
  PointMotion3 at(double t) const override;
  bool rotates() const override { return rotates_; }

  // Restarts at rest at p (and q, when rotates()) from time t (history cleared).
  void reset(double t, const Vec3& p);
  void reset(double t, const Vec3& p, const Eigen::Quaterniond& q);
  // Sample taken at t_sample at p (and q), applied at t_now (ExternalMotion::addSample). False, changing
  // nothing, for non-finite values, a zero quaternion or a stamp not newer than the previous sample. Without
  // q a rotating motion keeps its last orientation.
  bool addSample(double t_sample, const Vec3& p, double t_now);
  bool addSample(double t_sample, const Vec3& p, const Eigen::Quaterniond& q, double t_now);
  // Moves every stored sample time by -dt.
  void shiftSampleTimes(double dt);

  double lastSampleTime() const { return xz_.lastSampleTime(); }
  int sampleCount() const { return xz_.sampleCount(); }
  double blendTime() const { return xz_.blendTime(); }
  double holdTime() const { return xz_.holdTime(); }
  const ExternalMotionOptions& options() const { return xz_.options(); }
  // The planar motions: (x, z) and (y, 0); the attitude's (roll, pitch) and (yaw, 0) [rad].
  const ExternalMotion& xz() const { return xz_; }
  const ExternalMotion& y() const { return y_; }
  const ExternalMotion& rollPitch() const { return rp_; }
  const ExternalMotion& yaw() const { return yaw_; }

  // Z-Y-X angles (roll φ, pitch θ, yaw ψ) of q, R = Rz(ψ) Ry(θ) Rx(φ), roll and yaw unwrapped to lie within π
  // of `near`'s [rad].
  static Vec3 angles(const Eigen::Quaterniond& q, const Vec3& near = Vec3::Zero());

 private:
  ExternalMotion xz_, y_, rp_, yaw_;
  bool rotates_ = false;
  Vec3 last_angles_ = Vec3::Zero();  // (roll, pitch, yaw) of the newest sample, unwrapped
};

}  // namespace spatial
}  // namespace riser_sim
