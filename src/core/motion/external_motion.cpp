#include "riser_sim/motion/external_motion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace riser_sim {

namespace {
constexpr double kGapPeriods = 3.0;   // a gap: more than this many nominal periods (and blend + coast) without
constexpr double kMaxRejoin = 600.0;  // longest rejoin [s]
constexpr int kRejoinChecks = 64;     // points per candidate quintic where the rejoin's bounds are checked
}  // namespace

std::string ExternalMotionOptions::validate() const {
  auto bad = [](double x) { return !std::isfinite(x); };
  if (bad(fit_window) || fit_window <= 0.0) return "fit_window: must be > 0";
  if (fit_max_samples < 1 || fit_max_samples > kMotionHistory)
    return "fit_max_samples: must be in [1, " + std::to_string(kMotionHistory) + "]";
  if (bad(min_period) || min_period <= 0.0) return "min_period: must be > 0";
  if (bad(max_period) || max_period < min_period) return "max_period: must be >= min_period";
  if (bad(default_period) || default_period < min_period || default_period > max_period)
    return "default_period: must be in [min_period, max_period]";
  if (bad(min_blend) || min_blend < 0.0) return "min_blend: must be >= 0";
  if (bad(max_prediction) || max_prediction < 0.0) return "max_prediction: must be >= 0";
  if (bad(coast_time) || coast_time < 0.0) return "coast_time: must be >= 0";
  if (bad(stop_time) || stop_time <= 0.0) return "stop_time: must be > 0";
  if (bad(start_blend) || start_blend < 0.0) return "start_blend: must be >= 0";
  if (bad(rejoin_max_acceleration) || rejoin_max_acceleration <= 0.0) return "rejoin_max_acceleration: must be > 0";
  if (bad(rejoin_max_velocity) || rejoin_max_velocity <= 0.0) return "rejoin_max_velocity: must be > 0";
  if (bad(rejoin_max_angular_acceleration) || rejoin_max_angular_acceleration <= 0.0)
    return "rejoin_max_angular_acceleration: must be > 0";
  if (bad(rejoin_max_angular_velocity) || rejoin_max_angular_velocity <= 0.0)
    return "rejoin_max_angular_velocity: must be > 0";
  return "";
}

template <int D>
void SampledMotion<D>::Quintic::set(double t0_, double T_, const State& a, const State& b) {
  t0 = t0_;
  T = T_;
  const double T2 = T * T, T3 = T2 * T, T4 = T3 * T, T5 = T4 * T;
  const Vec dp = b.p - a.p;
  c[0] = a.p;
  c[1] = a.v;
  c[2] = 0.5 * a.a;
  c[3] = (20.0 * dp - (8.0 * b.v + 12.0 * a.v) * T - (3.0 * a.a - b.a) * T2) / (2.0 * T3);
  c[4] = (-30.0 * dp + (14.0 * b.v + 16.0 * a.v) * T + (3.0 * a.a - 2.0 * b.a) * T2) / (2.0 * T4);
  c[5] = (12.0 * dp - 6.0 * (b.v + a.v) * T + (b.a - a.a) * T2) / (2.0 * T5);
}

template <int D>
typename SampledMotion<D>::State SampledMotion<D>::Quintic::eval(double t) const {
  const double s = t - t0;
  State m;
  m.p = c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * (c[4] + s * c[5]))));
  m.v = c[1] + s * (2.0 * c[2] + s * (3.0 * c[3] + s * (4.0 * c[4] + s * 5.0 * c[5])));
  m.a = 2.0 * c[2] + s * (6.0 * c[3] + s * (12.0 * c[4] + s * 20.0 * c[5]));
  return m;
}

template <int D>
SampledMotion<D>::SampledMotion(const Vec& p, double t, const ExternalMotionOptions& options, Limits rejoin)
    : opt_(options), lim_(rejoin) {
  const std::string err = opt_.validate();
  if (!err.empty()) throw std::invalid_argument("external motion " + err);
  reset(t, p);
}

template <int D>
void SampledMotion<D>::reset(double t, const Vec& p) {
  head_ = 0;
  ring_[0] = {t, p};
  count_ = 1;
  State rest;
  rest.p = p;
  // Degenerate pieces that all hold p; the hold starts at t.
  blend_.set(t, 1.0, rest, rest);
  coast_ = blend_;
  stop_ = blend_;
  hold_ = p;
  t_hold_ = t;
  t_reset_ = t;
  t_applied_ = t;
  gaps_.rejoin_end = -std::numeric_limits<double>::infinity();
}

template <int D>
const std::pair<double, typename SampledMotion<D>::Vec>& SampledMotion<D>::sample(int back) const {
  return ring_[(head_ - back + kMotionHistory) % kMotionHistory];
}

template <int D>
double SampledMotion<D>::lastSampleTime() const {
  return sample(0).first;
}

template <int D>
double SampledMotion<D>::nominalPeriod() const {
  constexpr int kSpacings = 9;
  std::array<double, kSpacings> d;
  const int m = std::min(count_ - 1, kSpacings);
  if (m < 1) return opt_.default_period;
  for (int i = 0; i < m; ++i) d[i] = sample(i).first - sample(i + 1).first;
  std::nth_element(d.begin(), d.begin() + m / 2, d.begin() + m);
  return std::clamp(d[m / 2], opt_.min_period, opt_.max_period);
}

template <int D>
double SampledMotion<D>::blendTime() const {
  return std::max(nominalPeriod(), opt_.min_blend);
}

template <int D>
void SampledMotion<D>::fit(State& out) const {
  const double tk = sample(0).first;
  int m = 1;
  const int m_max = std::min(count_, opt_.fit_max_samples);
  while (m < m_max && tk - sample(m).first <= opt_.fit_window) ++m;
  out.p = sample(0).second;
  out.v.setZero();
  out.a.setZero();
  if (m == 1) return;
  if (m == 2) {
    out.v = (sample(0).second - sample(1).second) / (tk - sample(1).first);
    return;
  }
  // Quadratic p(τ) = b0 + b1 τ + b2 τ² in scaled time τ = (t - t_k) / span, least squares.
  const double span = std::max(tk - sample(m - 1).first, 1e-9);
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, D> r = Eigen::Matrix<double, 3, D>::Zero();
  for (int i = 0; i < m; ++i) {
    const double tau = (sample(i).first - tk) / span;
    const Eigen::Vector3d phi(1.0, tau, tau * tau);
    N.noalias() += phi * phi.transpose();
    r.noalias() += phi * sample(i).second.transpose();
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(N);
  const Eigen::Matrix<double, 3, D> b = ldlt.solve(r);
  if (ldlt.info() != Eigen::Success || !b.allFinite() || ldlt.rcond() < 1e-12) {
    out.v = (sample(0).second - sample(m - 1).second) / span;
    return;
  }
  out.p = b.row(0).transpose();
  out.v = b.row(1).transpose() / span;
  out.a = 2.0 * b.row(2).transpose() / (span * span);
}

// The fitted state h after its stamp: the fitted acceleration for up to max_prediction, constant velocity beyond
// (a catch-up, the start's or a rejoin, reaches that far; the usual blends stop at max_prediction).
template <int D>
typename SampledMotion<D>::State SampledMotion<D>::predict(const State& fitted, double h, bool catch_up) const {
  State s = fitted;
  if (!opt_.predict) return s;
  h = std::clamp(h, 0.0, catch_up ? std::max(h, opt_.max_prediction) : opt_.max_prediction);
  const double ha = std::min(h, opt_.max_prediction);
  s.p += fitted.v * h + fitted.a * ha * (h - 0.5 * ha);
  s.v += fitted.a * ha;
  return s;
}

// The shortest T >= T_min whose quintic from `from` to the source's state predicted to t_now + T keeps
// |a| <= a_max + |a_source| (or |a_from|, where it starts) and |v| <= max(|v_from|, |v_source|) + v_max (or + 0.52
// |v_source - v_from| when larger: a quintic's change of velocity overshoots by 0.512 of it) at kRejoinChecks
// points: a geometric search, then bisection.
template <int D>
double SampledMotion<D>::rejoinTime(double T_min, double t_sample, double t_now, const State& from, const State& fitted,
                                    State& target) const {
  const auto within = [&](double T, State& tgt) {
    tgt = predict(fitted, t_now + T - t_sample, true);
    Quintic q;
    q.set(t_now, T, from, tgt);
    const double la = std::max(lim_.a_max + tgt.a.norm(), from.a.norm());
    const double lv = std::max(from.v.norm(), tgt.v.norm()) + std::max(lim_.v_max, 0.52 * (tgt.v - from.v).norm());
    for (int i = 1; i <= kRejoinChecks; ++i) {
      const State s = q.eval(t_now + T * i / kRejoinChecks);
      if (s.a.norm() > la || s.v.norm() > lv) return false;
    }
    return true;
  };
  double lo = T_min, hi = T_min;
  if (within(hi, target)) return hi;
  while (hi < kMaxRejoin) {
    lo = hi;
    hi = std::min(1.5 * hi, kMaxRejoin);
    if (within(hi, target)) break;
  }
  for (int i = 0; i < 12 && hi - lo > 1e-3 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    State t_mid;
    if (within(mid, t_mid))
      hi = mid;
    else
      lo = mid;
  }
  within(hi, target);
  return hi;
}

template <int D>
bool SampledMotion<D>::addSample(double t_sample, const Vec& p, double t_now, const State& from) {
  if (!std::isfinite(t_sample) || !std::isfinite(t_now) || !p.allFinite()) return false;
  if (count_ > 0 && !(t_sample > lastSampleTime())) return false;
  const double spacing = std::max(t_sample - lastSampleTime(), t_now - t_applied_);
  const bool gap = spacing > std::max(kGapPeriods * nominalPeriod(), blendTime() + opt_.coast_time);
  head_ = (head_ + 1) % kMotionHistory;
  ring_[head_] = {t_sample, p};
  count_ = std::min(count_ + 1, kMotionHistory);
  t_applied_ = t_now;
  if (gap) {
    ++gaps_.count;
    gaps_.last = spacing;
    gaps_.longest = std::max(gaps_.longest, spacing);
  }

  State fitted;
  fit(fitted);
  double T = blendTime();
  const double catch_up_left = std::max(t_reset_ + opt_.start_blend, gaps_.rejoin_end) - t_now;
  const bool catch_up = catch_up_left > T;
  if (catch_up) T = catch_up_left;  // one blend to the window's end, aimed at the state predicted there
  State target;
  if (gap || gaps_.rejoin_end - t_now > blendTime()) {
    T = rejoinTime(T, t_sample, t_now, from, fitted, target);
    gaps_.rejoin_end = t_now + T;
  } else {
    target = predict(fitted, t_now + T - t_sample, catch_up);
  }
  plan(t_now, T, from, target);
  return true;
}

template <int D>
void SampledMotion<D>::plan(double t_now, double T, const State& from, const State& target) {
  blend_.set(t_now, T, from, target);
  // Coast: the acceleration ramps linearly to zero (the end state of that ramp, reached by a quintic).
  const double Tc = opt_.coast_time;
  State c_end = target;
  c_end.a.setZero();
  if (Tc > 0.0) {
    c_end.p = target.p + target.v * Tc + target.a * (Tc * Tc / 3.0);
    c_end.v = target.v + 0.5 * target.a * Tc;
    coast_.set(t_now + T, Tc, target, c_end);
  } else {
    coast_ = blend_;  // unused: the stop piece starts where the blend ends
  }
  // Stop: smoothstep velocity decay v (1 - 3s² + 2s³), which travels v Ts / 2; its deceleration, at most
  // 1.5 |v| / Ts, kept within the rejoin's bound (a fast holder takes longer than stop_time).
  const double Ts = std::max(opt_.stop_time, 1.5 * c_end.v.norm() / lim_.a_max);
  State s_end;
  s_end.p = c_end.p + 0.5 * Ts * c_end.v;
  const State& s_begin = Tc > 0.0 ? c_end : target;  // acceleration continuity: the quintic takes a from target.a
  stop_.set(t_now + T + Tc, Ts, s_begin, s_end);
  hold_ = s_end.p;
  t_hold_ = t_now + T + Tc + Ts;
}

template <int D>
typename SampledMotion<D>::State SampledMotion<D>::at(double t) const {
  if (t >= t_hold_) {
    State s;
    s.p = hold_;
    return s;
  }
  if (t >= stop_.t0) return stop_.eval(t);
  if (opt_.coast_time > 0.0 && t >= coast_.t0) return coast_.eval(t);
  return blend_.eval(t);
}

template <int D>
void SampledMotion<D>::shiftSampleTimes(double dt) {
  for (int i = 0; i < count_; ++i) ring_[(head_ - i + kMotionHistory) % kMotionHistory].first -= dt;
}

template class SampledMotion<2>;
template class SampledMotion<3>;

ExternalMotion::ExternalMotion(const Vec2& p, double t, const ExternalMotionOptions& options)
    : m_(p, t, options, {options.rejoin_max_acceleration, options.rejoin_max_velocity}) {}

PointMotion ExternalMotion::at(double t) const {
  const SampledMotion<2>::State s = m_.at(t);
  return PointMotion{s.p, s.v, s.a};
}

}  // namespace riser_sim
