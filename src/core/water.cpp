#include "riser_sim/water.h"

#include <cmath>

namespace riser_sim {

WaterKinematics::WaterKinematics(const WaterSpec& spec, double gravity) : spec_(spec) {
  const CurrentSpec& c = spec.current;
  moving_ = c.velocity.norm() > 0.0 || c.acceleration.norm() > 0.0 || !c.profile.empty() || spec.waves.height > 0.0;
  if (spec.waves.height > 0.0) {
    omega_ = 2.0 * M_PI / spec.waves.period;
    const double h = spec.waves.depth, g = gravity;
    double k = omega_ * omega_ / g;  // deep-water start, Newton on ω² - g k tanh(k h)
    for (int it = 0; it < 50; ++it) {
      const double th = std::tanh(k * h);
      const double f = g * k * th - omega_ * omega_;
      const double df = g * th + g * k * h * (1.0 - th * th);
      const double dk = f / df;
      k -= dk;
      if (std::abs(dk) < 1e-14 * k) break;
    }
    k_ = k;
  }
}

void WaterKinematics::at(const Vec2& p, double t, Vec2& v, Vec2& a) const {
  v.setZero();
  a.setZero();
  const double z = p.y() - spec_.surface;  // < 0 below the surface
  if (z > 0.0) return;
  const CurrentSpec& c = spec_.current;
  v = c.velocity + c.acceleration * t;
  a = c.acceleration;
  if (!c.profile.empty()) {
    const double d = -z;
    double vx = c.profile.front().vx;
    if (d >= c.profile.back().depth) {
      vx = c.profile.back().vx;
    } else {
      for (size_t i = 1; i < c.profile.size(); ++i)
        if (d < c.profile[i].depth) {
          const auto& p0 = c.profile[i - 1];
          const auto& p1 = c.profile[i];
          const double f = d <= p0.depth ? 0.0 : (d - p0.depth) / (p1.depth - p0.depth);
          vx = p0.vx + f * (p1.vx - p0.vx);
          break;
        }
    }
    v.x() = vx + c.acceleration.x() * t;
  }
  const WaveSpec& w = spec_.waves;
  if (w.height > 0.0) {
    const double h = w.depth, zz = std::max(z, -h);
    const double th = w.direction * k_ * p.x() - omega_ * t + w.phase;
    const double amp = 0.5 * w.height * omega_ / std::sinh(k_ * h);
    const double ch = std::cosh(k_ * (zz + h)), sh = std::sinh(k_ * (zz + h));
    const double ct = std::cos(th), st = std::sin(th);
    v.x() += w.direction * amp * ch * ct;
    v.y() += amp * sh * st;
    a.x() += w.direction * amp * omega_ * ch * st;
    a.y() += -amp * omega_ * sh * ct;
  }
}

}  // namespace riser_sim
