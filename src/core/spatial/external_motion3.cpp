#include "riser_sim/spatial/external_motion3.h"

#include <cmath>

namespace riser_sim {
namespace spatial {

namespace {
Vec2 rpOf(const Vec3& a) { return Vec2(a.x(), a.y()); }
Vec2 yawOf(const Vec3& a) { return Vec2(a.z(), 0.0); }
bool usable(const Eigen::Quaterniond& q) { return q.coeffs().allFinite() && q.norm() > 1e-9; }
}  // namespace

ExternalMotion3::ExternalMotion3(const Vec3& p, double t, const ExternalMotionOptions& options)
    : xz_(Vec2(p.x(), p.z()), t, options), y_(Vec2(p.y(), 0.0), t, options), rp_(Vec2::Zero(), t, options),
      yaw_(Vec2::Zero(), t, options) {}

ExternalMotion3::ExternalMotion3(const Vec3& p, const Eigen::Quaterniond& q, double t,
                                 const ExternalMotionOptions& options)
    : ExternalMotion3(p, t, options) {
  rotates_ = true;
  reset(t, p, q);
}

Vec3 ExternalMotion3::angles(const Eigen::Quaterniond& q, const Vec3& near) {
  const Mat3 R = q.normalized().toRotationMatrix();
  const double pitch = std::asin(std::max(-1.0, std::min(1.0, -R(2, 0))));
  const double roll = std::atan2(R(2, 1), R(2, 2)), yaw = std::atan2(R(1, 0), R(0, 0));
  return Vec3(near.x() + std::remainder(roll - near.x(), 2.0 * M_PI), pitch,
              near.z() + std::remainder(yaw - near.z(), 2.0 * M_PI));
}

PointMotion3 ExternalMotion3::at(double t) const {
  const PointMotion a = xz_.at(t), b = y_.at(t);
  PointMotion3 m{Vec3(a.p.x(), b.p.x(), a.p.y()), Vec3(a.v.x(), b.v.x(), a.v.y()), Vec3(a.a.x(), b.a.x(), a.a.y())};
  if (!rotates_) return m;
  const PointMotion rp = rp_.at(t), yw = yaw_.at(t);
  setAttitudeZYX(Vec3(rp.p.x(), rp.p.y(), yw.p.x()), Vec3(rp.v.x(), rp.v.y(), yw.v.x()), m);
  return m;
}

void ExternalMotion3::reset(double t, const Vec3& p) {
  xz_.reset(t, Vec2(p.x(), p.z()));
  y_.reset(t, Vec2(p.y(), 0.0));
  if (!rotates_) return;
  rp_.reset(t, rpOf(last_angles_));
  yaw_.reset(t, yawOf(last_angles_));
}

void ExternalMotion3::reset(double t, const Vec3& p, const Eigen::Quaterniond& q) {
  if (usable(q)) last_angles_ = angles(q, last_angles_);
  reset(t, p);
}

bool ExternalMotion3::addSample(double t_sample, const Vec3& p, double t_now) {
  // Every channel keeps the same stamps: the others accept whatever xz_ accepts, so a refusal changes nothing.
  if (!p.allFinite()) return false;
  if (!xz_.addSample(t_sample, Vec2(p.x(), p.z()), t_now)) return false;
  y_.addSample(t_sample, Vec2(p.y(), 0.0), t_now);
  if (rotates_) {
    rp_.addSample(t_sample, rpOf(last_angles_), t_now);
    yaw_.addSample(t_sample, yawOf(last_angles_), t_now);
  }
  return true;
}

bool ExternalMotion3::addSample(double t_sample, const Vec3& p, const Eigen::Quaterniond& q, double t_now) {
  if (!usable(q)) return false;
  const Vec3 previous = last_angles_;
  if (rotates_) last_angles_ = angles(q, last_angles_);
  if (addSample(t_sample, p, t_now)) return true;
  last_angles_ = previous;
  return false;
}

void ExternalMotion3::shiftSampleTimes(double dt) {
  xz_.shiftSampleTimes(dt);
  y_.shiftSampleTimes(dt);
  if (!rotates_) return;
  rp_.shiftSampleTimes(dt);
  yaw_.shiftSampleTimes(dt);
}

}  // namespace spatial
}  // namespace riser_sim
