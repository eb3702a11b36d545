// Top (or bottom) motion in 3D driven by external samples (vessel or ROV poses): the planar smoothing
// (external_motion.h: fit, blend, coast, stop, gaps and rejoin, same options) on the 3D position. Built with an
// orientation, it also smooths the holder's attitude on SO(3): the same smoothing on the rotation vector r of
// R = R_b Exp(r) relative to a base rotation R_b, re-based on every sample to the current attitude (the samples
// kept and the current state carried over exactly: p' = 0, v' = J_r(r) v, a' from the angular acceleration), so
// any attitude (pitch through ±90°, any number of turns, tumbling) is smooth, the same lag and prediction as the
// position. at() gives R and w = R_b J_l(r) ṙ, continuous (and so is the angular acceleration): a flex joint's
// axis turns with it. at() and addSample() allocate nothing.
#pragma once
#include <Eigen/Geometry>

#include "riser_sim/motion/external_motion.h"
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
  // The angular acceleration at t, world frame [rad/s^2] (0 when !rotates()).
  Vec3 angularAcceleration(double t) const;

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

  double lastSampleTime() const { return pos_.lastSampleTime(); }
  int sampleCount() const { return pos_.sampleCount(); }
  double blendTime() const { return pos_.blendTime(); }
  double holdTime() const { return pos_.holdTime(); }
  const MotionGaps& gaps() const { return pos_.gaps(); }
  const ExternalMotionOptions& options() const { return pos_.options(); }
  // The smoothing of the position, and of the attitude's rotation vector relative to base().
  const SampledMotion<3>& position() const { return pos_; }
  const SampledMotion<3>& attitude() const { return rot_; }
  const Mat3& base() const { return base_; }

  // SO(3): Exp(r), its left Jacobian J_l(r) (w = J_l(r) ṙ in the frame the rotation is applied in) and the
  // time derivative of J_l along ṙ = v.
  static Mat3 expMap(const Vec3& r);
  static Mat3 leftJacobian(const Vec3& r);
  static Mat3 leftJacobianRate(const Vec3& r, const Vec3& v);
  // The rotation vector of R nearest to `near` (angle θ + 2πk about the axis of log R).
  static Vec3 logNear(const Mat3& R, const Vec3& near);

 private:
  void addAttitude(double t_sample, const Mat3& R, double t_now);

  SampledMotion<3> pos_, rot_;
  bool rotates_ = false;
  Mat3 base_ = Mat3::Identity();  // R = base_ Exp(r)
  Mat3 last_ = Mat3::Identity();  // the newest sample's attitude
};

}  // namespace spatial
}  // namespace riser_sim
