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
      // k h (1 - th²) = k h / cosh²(k h): 0 for large k h (cosh² would overflow, the product is 0).
      const double kh = k * h, sech2 = kh > 300.0 ? 0.0 : 1.0 / std::pow(std::cosh(kh), 2);
      const double df = g * th + g * kh * sech2;
      const double dk = f / df;
      k -= dk;
      if (std::abs(dk) < 1e-14 * k) break;
    }
    k_ = k;
  }
}

WaterKinematics WaterKinematics::steady(double t) const {
  WaterSpec s = spec_;
  s.waves.height = 0.0;
  CurrentSpec& c = s.current;
  c.velocity += c.acceleration * t;
  for (CurrentSpec::Point& p : c.profile) p.vx += c.acceleration.x() * t;
  c.acceleration.setZero();
  WaterKinematics w(s, 0.0);  // no waves: gravity unused
  return w;
}

double WaterKinematics::rampFactor(double t, double* rate) const {
  const double T = spec_.waves.ramp;
  if (rate) *rate = 0.0;
  if (!(T > 0.0) || t >= T) return 1.0;
  if (t <= 0.0) return 0.0;
  if (rate) *rate = 0.5 * M_PI / T * std::sin(M_PI * t / T);
  return 0.5 * (1.0 - std::cos(M_PI * t / T));
}

void WaterKinematics::depthRatios(double z, double& c, double& s) const {
  // cosh(k(z + h)) / sinh(k h) and sinh(k(z + h)) / sinh(k h) for -h <= z <= 0, in the form
  // (e^{kz} ± e^{-k(z + 2h)}) / (1 - e^{-2kh}): every exponent <= 0, finite for any depth.
  const double h = spec_.waves.depth, zz = std::min(std::max(z, -h), 0.0);
  const double a = std::exp(k_ * zz), b = std::exp(-k_ * (zz + 2.0 * h)), d = -std::expm1(-2.0 * k_ * h);
  c = (a + b) / d;
  s = (a - b) / d;
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
    double rate;
    const double r = rampFactor(t, &rate);
    if (r == 0.0) return;
    double ch, sh;
    depthRatios(z, ch, sh);
    const double th = w.direction * k_ * p.x() - omega_ * t + w.phase;
    const double amp = 0.5 * w.height * omega_;
    const double ct = std::cos(th), st = std::sin(th);
    // Ramped amplitude r(t): v = r v_0, a = r a_0 + r' v_0 (a_0 = ∂v_0/∂t, linear theory).
    const Vec2 v0(w.direction * amp * ch * ct, amp * sh * st);
    const Vec2 a0(w.direction * amp * omega_ * ch * st, -amp * omega_ * sh * ct);
    v += r * v0;
    a += r * a0 + rate * v0;
  }
}

}  // namespace riser_sim
