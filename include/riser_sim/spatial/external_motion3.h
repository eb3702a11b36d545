// Top (or bottom) motion in 3D driven by external samples (vessel or ROV poses): the planar
// ExternalMotion (external_motion.h) on (x, z) and on (y, 0), so every axis is smoothed exactly as the
// planar node smooths x and z (same fit, blend, coast, stop and options). at() and addSample() allocate
// nothing.
#pragma once
#include "riser_sim/external_motion.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {

class ExternalMotion3 : public TopMotion3 {
 public:
  // At rest at p from time t. Throws std::invalid_argument for invalid options (as ExternalMotion).
  explicit ExternalMotion3(const Vec3& p, double t = 0.0, const ExternalMotionOptions& options = {});
  PointMotion3 at(double t) const override;

  // Restarts at rest at p from time t (history cleared).
  void reset(double t, const Vec3& p);
  // Sample taken at t_sample at p, applied at t_now (ExternalMotion::addSample). False, changing
  // nothing, for non-finite values or a stamp not newer than the previous sample.
  bool addSample(double t_sample, const Vec3& p, double t_now);
  // Moves every stored sample time by -dt.
  void shiftSampleTimes(double dt);

  double lastSampleTime() const { return xz_.lastSampleTime(); }
  int sampleCount() const { return xz_.sampleCount(); }
  double blendTime() const { return xz_.blendTime(); }
  double holdTime() const { return xz_.holdTime(); }
  const ExternalMotionOptions& options() const { return xz_.options(); }
  // The planar motions: (x, z) and (y, 0).
  const ExternalMotion& xz() const { return xz_; }
  const ExternalMotion& y() const { return y_; }

 private:
  ExternalMotion xz_, y_;
};

}  // namespace spatial
}  // namespace riser_sim
