#include "riser_sim/external_motion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace riser_sim {

std::string ExternalMotionOptions::validate() const {
  auto bad = [](double x) { return !std::isfinite(x); };
  if (bad(fit_window) || fit_window <= 0.0) return "fit_window: must be > 0";
  if (fit_max_samples < 1 || fit_max_samples > ExternalMotion::kHistory)
    return "fit_max_samples: must be in [1, " + std::to_string(ExternalMotion::kHistory) + "]";
  if (bad(min_period) || min_period <= 0.0) return "min_period: must be > 0";
  if (bad(max_period) || max_period < min_period) return "max_period: must be >= min_period";
  if (bad(default_period) || default_period < min_period || default_period > max_period)
    return "default_period: must be in [min_period, max_period]";
  if (bad(min_blend) || min_blend < 0.0) return "min_blend: must be >= 0";
  if (bad(max_prediction) || max_prediction < 0.0) return "max_prediction: must be >= 0";
  if (bad(coast_time) || coast_time < 0.0) return "coast_time: must be >= 0";
  if (bad(stop_time) || stop_time <= 0.0) return "stop_time: must be > 0";
  if (bad(start_blend) || start_blend < 0.0) return "start_blend: must be >= 0";
  return "";
}

void ExternalMotion::Quintic::set(double t0_, double T_, const PointMotion& a, const PointMotion& b) {
  t0 = t0_;
  T = T_;
  const double T2 = T * T, T3 = T2 * T, T4 = T3 * T, T5 = T4 * T;
  const Vec2 dp = b.p - a.p;
  c[0] = a.p;
  c[1] = a.v;
  c[2] = 0.5 * a.a;
  c[3] = (20.0 * dp - (8.0 * b.v + 12.0 * a.v) * T - (3.0 * a.a - b.a) * T2) / (2.0 * T3);
  c[4] = (-30.0 * dp + (14.0 * b.v + 16.0 * a.v) * T + (3.0 * a.a - 2.0 * b.a) * T2) / (2.0 * T4);
  c[5] = (12.0 * dp - 6.0 * (b.v + a.v) * T + (b.a - a.a) * T2) / (2.0 * T5);
}

PointMotion ExternalMotion::Quintic::eval(double t) const {
  const double s = t - t0;
  PointMotion m;
  m.p = c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * (c[4] + s * c[5]))));
  m.v = c[1] + s * (2.0 * c[2] + s * (3.0 * c[3] + s * (4.0 * c[4] + s * 5.0 * c[5])));
  m.a = 2.0 * c[2] + s * (6.0 * c[3] + s * (12.0 * c[4] + s * 20.0 * c[5]));
  return m;
}

ExternalMotion::ExternalMotion(const Vec2& p, double t, const ExternalMotionOptions& options) : opt_(options) {
  const std::string err = opt_.validate();
  if (!err.empty()) throw std::invalid_argument("external motion " + err);
  reset(t, p);
}

void ExternalMotion::reset(double t, const Vec2& p) {
  count_ = 0;
  head_ = 0;
  ring_[0] = {t, p};
  count_ = 1;
  const PointMotion rest{p, Vec2::Zero(), Vec2::Zero()};
  // Degenerate pieces that all hold p; the hold starts at t.
  blend_.set(t, 1.0, rest, rest);
  coast_ = blend_;
  stop_ = blend_;
  hold_ = p;
  t_hold_ = t;
  t_reset_ = t;
}

const std::pair<double, Vec2>& ExternalMotion::sample(int back) const {
  return ring_[(head_ - back + kHistory) % kHistory];
}

double ExternalMotion::lastSampleTime() const { return sample(0).first; }

double ExternalMotion::nominalPeriod() const {
  constexpr int kSpacings = 9;
  std::array<double, kSpacings> d;
  const int m = std::min(count_ - 1, kSpacings);
  if (m < 1) return opt_.default_period;
  for (int i = 0; i < m; ++i) d[i] = sample(i).first - sample(i + 1).first;
  std::nth_element(d.begin(), d.begin() + m / 2, d.begin() + m);
  return std::clamp(d[m / 2], opt_.min_period, opt_.max_period);
}

double ExternalMotion::blendTime() const { return std::max(nominalPeriod(), opt_.min_blend); }

void ExternalMotion::fit(PointMotion& out) const {
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
  Eigen::Matrix<double, 3, 2> r = Eigen::Matrix<double, 3, 2>::Zero();
  for (int i = 0; i < m; ++i) {
    const double tau = (sample(i).first - tk) / span;
    const Eigen::Vector3d phi(1.0, tau, tau * tau);
    N.noalias() += phi * phi.transpose();
    r.noalias() += phi * sample(i).second.transpose();
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(N);
  const Eigen::Matrix<double, 3, 2> b = ldlt.solve(r);
  if (ldlt.info() != Eigen::Success || !b.allFinite() || ldlt.rcond() < 1e-12) {
    out.v = (sample(0).second - sample(m - 1).second) / span;
    return;
  }
  out.p = b.row(0).transpose();
  out.v = b.row(1).transpose() / span;
  out.a = 2.0 * b.row(2).transpose() / (span * span);
}

bool ExternalMotion::addSample(double t_sample, const Vec2& p, double t_now) {
  if (!std::isfinite(t_sample) || !std::isfinite(t_now) || !p.allFinite()) return false;
  if (count_ > 0 && !(t_sample > lastSampleTime())) return false;
  const PointMotion from = at(t_now);
  head_ = (head_ + 1) % kHistory;
  ring_[head_] = {t_sample, p};
  count_ = std::min(count_ + 1, kHistory);

  PointMotion target;
  fit(target);
  double T = blendTime(), reach = opt_.max_prediction;
  const double start_left = t_reset_ + opt_.start_blend - t_now;
  if (start_left > T) {  // the start's catch-up: one blend to the window's end, aimed at the state predicted there
    T = start_left;
    reach = std::max(reach, t_now + T - t_sample);
  }
  if (opt_.predict) {  // the fitted acceleration for up to max_prediction, constant velocity beyond (the start)
    const double h = std::clamp(t_now + T - t_sample, 0.0, reach), ha = std::min(h, opt_.max_prediction);
    target.p += target.v * h + target.a * ha * (h - 0.5 * ha);
    target.v += target.a * ha;
  }
  plan(t_now, T, from, target);
  return true;
}

void ExternalMotion::plan(double t_now, double T, const PointMotion& from, const PointMotion& target) {
  blend_.set(t_now, T, from, target);
  // Coast: the acceleration ramps linearly to zero (the end state of that ramp, reached by a quintic).
  const double Tc = opt_.coast_time;
  PointMotion c_end{target.p, target.v, Vec2::Zero()};
  if (Tc > 0.0) {
    c_end.p = target.p + target.v * Tc + target.a * (Tc * Tc / 3.0);
    c_end.v = target.v + 0.5 * target.a * Tc;
    coast_.set(t_now + T, Tc, target, c_end);
  } else {
    coast_ = blend_;  // unused: the stop piece starts where the blend ends
    c_end = target;
    c_end.a.setZero();
  }
  // Stop: smoothstep velocity decay v (1 - 3s² + 2s³), which travels v Ts / 2.
  const double Ts = opt_.stop_time;
  const PointMotion s_end{c_end.p + 0.5 * Ts * c_end.v, Vec2::Zero(), Vec2::Zero()};
  PointMotion s_begin = c_end;
  if (Tc <= 0.0) s_begin = target;  // acceleration continuity: the quintic takes a from target.a
  stop_.set(t_now + T + Tc, Ts, s_begin, s_end);
  hold_ = s_end.p;
  t_hold_ = t_now + T + Tc + Ts;
}

PointMotion ExternalMotion::at(double t) const {
  if (t >= t_hold_) return PointMotion{hold_, Vec2::Zero(), Vec2::Zero()};
  if (t >= stop_.t0) return stop_.eval(t);
  if (opt_.coast_time > 0.0 && t >= coast_.t0) return coast_.eval(t);
  return blend_.eval(t);
}

void ExternalMotion::shiftSampleTimes(double dt) {
  for (int i = 0; i < count_; ++i) ring_[(head_ - i + kHistory) % kHistory].first -= dt;
}

}  // namespace riser_sim
