#include "riser_sim/planar/water.h"

#include <cmath>
#include <random>

namespace riser_sim {

namespace {

// k from ω² = g k tanh(k h): Newton from the deep-water value.
double waveNumberOf(double omega, double h, double g) {
  double k = omega * omega / g;
  for (int it = 0; it < 50; ++it) {
    const double th = std::tanh(k * h);
    const double f = g * k * th - omega * omega;
    // k h (1 - th²) = k h / cosh²(k h): 0 for large k h (cosh² would overflow, the product is 0).
    const double kh = k * h, sech2 = kh > 300.0 ? 0.0 : 1.0 / std::pow(std::cosh(kh), 2);
    const double df = g * th + g * kh * sech2;
    const double dk = f / df;
    k -= dk;
    if (std::abs(dk) < 1e-14 * k) break;
  }
  return k;
}

}  // namespace

double WaterKinematics::jonswapShape(double omega, double omega_p, double gamma) {
  if (!(omega > 0.0)) return 0.0;
  const double sigma = omega <= omega_p ? 0.07 : 0.09;
  const double r = std::exp(-std::pow(omega - omega_p, 2) / (2.0 * sigma * sigma * omega_p * omega_p));
  return std::pow(omega, -5.0) * std::exp(-1.25 * std::pow(omega_p / omega, 4)) * std::pow(gamma, r);
}

WaterKinematics::WaterKinematics(const WaterSpec& spec, double gravity)
    : spec_(spec), velocity_(inPlane(spec.current.velocity)), acceleration_(inPlane(spec.current.acceleration)) {
  const CurrentSpec& c = spec.current;
  const WaveSpec& w = spec.waves;
  moving_ = velocity_.norm() > 0.0 || acceleration_.norm() > 0.0 || !c.profile.empty() || w.active();
  if (!w.active()) return;
  const double h = w.depth;
  const auto add = [&](double a, double omega, double phase) {
    const double k = waveNumberOf(omega, h, gravity);
    comp_.push_back(Component{a, omega, k, phase, -std::expm1(-2.0 * k * h), std::exp(-2.0 * k * h)});
  };
  if (w.type == WaveKind::kRegular) {
    add(0.5 * w.height, 2.0 * M_PI / w.period, w.phase);
    return;
  }
  // JONSWAP on [0.5, 3] ω_p in equal bins, scaled so that the discrete sea has m0 = Σ a²/2 = Hs²/16 exactly;
  // phases uniform on [0, 2π) from the seed's raw mt19937 stream (the same on every platform).
  const double wp = 2.0 * M_PI / w.peak_period, lo = 0.5 * wp, dw = (3.0 * wp - lo) / w.components;
  std::vector<double> S(w.components);
  double m0 = 0.0;
  for (int i = 0; i < w.components; ++i) m0 += (S[i] = jonswapShape(lo + (i + 0.5) * dw, wp, w.gamma)) * dw;
  const double scale = w.significant_height * w.significant_height / 16.0 / m0;
  std::mt19937 rng(w.seed);
  for (int i = 0; i < w.components; ++i)
    add(std::sqrt(2.0 * scale * S[i] * dw), lo + (i + 0.5) * dw, 2.0 * M_PI * (rng() / 4294967296.0));
}

WaterKinematics WaterKinematics::steady(double t) const { return steady(t, 1.0); }

WaterKinematics WaterKinematics::steady(double t, double current_factor) const {
  WaterSpec s = spec_;
  s.waves.height = 0.0;
  s.waves.significant_height = 0.0;
  CurrentSpec& c = s.current;
  c.velocity += c.acceleration * t;
  for (CurrentSpec::Point& p : c.profile) p.vx += c.acceleration.x() * t;
  c.acceleration.setZero();
  if (current_factor != 1.0) {
    c.velocity *= current_factor;
    for (CurrentSpec::Point& p : c.profile) p.vx *= current_factor, p.vy *= current_factor;
  }
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

void WaterKinematics::depthRatios(const Component& c, double z, double& ch, double& sh) const {
  // cosh(k(z + h)) / sinh(k h) and sinh(k(z + h)) / sinh(k h) for -h <= z <= 0, in the form
  // (e^{kz} ± e^{-k(z + 2h)}) / (1 - e^{-2kh}): every exponent <= 0, finite for any depth.
  const double h = spec_.waves.depth, zz = std::min(std::max(z, -h), 0.0);
  // b = e^{-2kh} / a: one exp per component (a >= e^{-kh}, so b only needs its own exp when a underflows).
  const double a = std::exp(c.k * zz), b = a > 1e-300 ? c.e2kh / a : std::exp(-c.k * (zz + 2.0 * h));
  ch = (a + b) / c.decay;
  sh = (a - b) / c.decay;
}

double WaterKinematics::elevation(double x, double t) const {
  if (comp_.empty()) return 0.0;
  const double r = rampFactor(t);
  double eta = 0.0;
  for (const Component& c : comp_) eta += c.a * std::cos(spec_.waves.direction * c.k * x - c.omega * t + c.phase);
  return r * eta;
}

void WaterKinematics::at(const Vec2& p, double t, Vec2& v, Vec2& a) const {
  v.setZero();
  a.setZero();
  const double z = p.y() - spec_.surface;  // < 0 below the surface
  if (z > 0.0) return;
  const CurrentSpec& c = spec_.current;
  v = velocity_ + acceleration_ * t;
  a = acceleration_;
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
    v.x() = vx + acceleration_.x() * t;
  }
  const WaveSpec& w = spec_.waves;
  if (comp_.empty()) return;
  double rate;
  const double r = rampFactor(t, &rate);
  if (r == 0.0) return;
  for (const Component& c : comp_) {
    double ch, sh;
    depthRatios(c, z, ch, sh);
    const double th = w.direction * c.k * p.x() - c.omega * t + c.phase;
    const double amp = c.a * c.omega;
    const double ct = std::cos(th), st = std::sin(th);
    // Ramped amplitude r(t): v = r v_0, a = r a_0 + r' v_0 (a_0 = ∂v_0/∂t, linear theory).
    const Vec2 v0(w.direction * amp * ch * ct, amp * sh * st);
    const Vec2 a0(w.direction * amp * c.omega * ch * st, -amp * c.omega * sh * ct);
    v += r * v0;
    a += r * a0 + rate * v0;
  }
}

}  // namespace riser_sim
