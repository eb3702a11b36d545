#include "riser_sim/spatial/external_motion3.h"

namespace riser_sim {
namespace spatial {

ExternalMotion3::ExternalMotion3(const Vec3& p, double t, const ExternalMotionOptions& options)
    : xz_(Vec2(p.x(), p.z()), t, options), y_(Vec2(p.y(), 0.0), t, options) {}

PointMotion3 ExternalMotion3::at(double t) const {
  const PointMotion a = xz_.at(t), b = y_.at(t);
  return PointMotion3{Vec3(a.p.x(), b.p.x(), a.p.y()), Vec3(a.v.x(), b.v.x(), a.v.y()),
                      Vec3(a.a.x(), b.a.x(), a.a.y())};
}

void ExternalMotion3::reset(double t, const Vec3& p) {
  xz_.reset(t, Vec2(p.x(), p.z()));
  y_.reset(t, Vec2(p.y(), 0.0));
}

bool ExternalMotion3::addSample(double t_sample, const Vec3& p, double t_now) {
  // Both halves keep the same stamps: y_ accepts whatever xz_ accepts, so a refusal changes nothing.
  if (!p.allFinite()) return false;
  if (!xz_.addSample(t_sample, Vec2(p.x(), p.z()), t_now)) return false;
  const bool ok = y_.addSample(t_sample, Vec2(p.y(), 0.0), t_now);
  (void)ok;  // same stamp history as xz_: accepted whenever xz_ accepted
  return true;
}

void ExternalMotion3::shiftSampleTimes(double dt) {
  xz_.shiftSampleTimes(dt);
  y_.shiftSampleTimes(dt);
}

}  // namespace spatial
}  // namespace riser_sim
