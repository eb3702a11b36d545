// Top motion driven by external samples (e.g. vessel poses at 10-100 Hz with timing jitter), smoothed
// into a C2-continuous p, v, a for A_0 (A_0's acceleration enters the constraint equations).
//
// On every new sample (t_k, p_k) a quadratic least-squares fit over the recent samples gives
// (p_k, v_k, a_k). A quintic blend then starts at the time the sample is applied, from the current
// (p, v, a), and ends one blend time T later (T = max(sample period, min_blend)) at the state predicted
// for that instant (or at the sample itself when predict = false: lag = T + latency). Past the blend the
// acceleration ramps to zero over coast_time (constant velocity), then the velocity decays to zero
// over stop_time and the last position is held. Every piece starts from the exact state where the
// previous one is left, so p, v, a are continuous at all times.
//
// Gaps. A sample is "after a gap" when it comes more than max(3 nominal periods, blend + coast_time) after the
// previous one, by stamp or by the time it is applied (the motion has then run out of its blend and coast). The
// rejoin with the source is one quintic to the source's state predicted to its end, its duration the shortest
// (from the usual blend time up) whose acceleration stays within rejoin_max_acceleration of the source's and
// whose speed stays within rejoin_max_velocity of the faster of the held and source speeds; for a rest-to-rest
// distance D: T ~ max(sqrt(5.77 D / a_max), 1.875 D / v_max). The samples that arrive before that end re-plan to
// the same end (or later, should the bound need it), as start_blend does. The stop after the coast lasts
// max(stop_time, 1.5 |v| / rejoin_max_acceleration): its deceleration within the same bound.
//
// SampledMotion<D> is that smoothing on a D-vector (the planar top: D = 2; in 3D the position and the attitude's
// rotation vector: D = 3); ExternalMotion is the planar TopMotion on it.
// at() and addSample() allocate nothing (fixed ring buffer).
#pragma once
#include <Eigen/Core>
#include <array>
#include <limits>
#include <string>

#include "riser_sim/motion/top_motion.h"

namespace riser_sim {

constexpr int kMotionHistory = 32;  // samples kept

struct ExternalMotionOptions {
  double fit_window = 0.5;      // samples within this time of the newest one enter the fit [s]
  int fit_max_samples = 32;     // at most this many (<= kMotionHistory)
  double default_period = 0.1;  // sample period assumed before two samples arrived [s]
  double min_period = 0.002;    // clamp of the estimated sample period [s]
  double max_period = 0.5;      // [s]
  double min_blend = 0.1;       // shortest blend: bounds the acceleration a noisy sample can cause [s]
  bool predict = true;          // aim at the extrapolated state (lag ~ 0) instead of the sample
  double max_prediction = 0.3;  // longest extrapolation beyond the newest sample [s]
  double coast_time = 0.2;      // constant-velocity continuation past the blend [s]
  double stop_time = 0.5;       // velocity decay to zero, then hold [s] (> 0; longer for a fast holder, above)
  // After reset() (the line at rest): the catch-up with a source already moving is spread until this long after
  // the reset [s] (each blend then ends there, aimed at the source's state predicted to that time), so the top
  // accelerates by ~v / start_blend instead of v / min_blend. 0: off.
  double start_blend = 0.0;
  // After a gap: the rejoin's acceleration beyond the source's [m/s^2] and speed beyond what its change of
  // velocity needs [m/s]; ExternalMotion3's attitude: the same in [rad/s^2], [rad/s].
  double rejoin_max_acceleration = 0.5;
  double rejoin_max_velocity = 2.0;
  double rejoin_max_angular_acceleration = 0.5;
  double rejoin_max_angular_velocity = 1.0;

  // Empty when valid, else "field: reason".
  std::string validate() const;
};

// What the motion saw of gaps in its samples (since its construction).
struct MotionGaps {
  long count = 0;                                                // samples that came after a gap
  double longest = 0.0;                                          // [s]
  double last = 0.0;                                             // the last gap [s]
  double rejoin_end = -std::numeric_limits<double>::infinity();  // the last rejoin ends at this time [s]
  bool rejoining(double t) const { return t < rejoin_end; }
};

template <int D>
class SampledMotion {
 public:
  using Vec = Eigen::Matrix<double, D, 1>;
  struct State {
    Vec p = Vec::Zero(), v = Vec::Zero(), a = Vec::Zero();
  };
  struct Limits {
    double a_max, v_max;  // the rejoin's bounds (see the file's comment)
  };

  // At rest at p from time t. Throws std::invalid_argument for invalid options.
  SampledMotion(const Vec& p, double t, const ExternalMotionOptions& options, Limits rejoin);
  State at(double t) const;
  void reset(double t, const Vec& p);
  // Sample taken at t_sample [s] of value p, applied at t_now [s] (not earlier than the previous application).
  // False, changing nothing, for non-finite values or a stamp not newer than the previous sample.
  bool addSample(double t_sample, const Vec& p, double t_now) { return addSample(t_sample, p, t_now, at(t_now)); }
  // The same from the state `from` at t_now (the caller re-expressed at(t_now) in new coordinates).
  bool addSample(double t_sample, const Vec& p, double t_now, const State& from);
  // Rewrites every stored sample value, newest first: f(Vec& value).
  template <class F>
  void mapSampleValues(F&& f) {
    for (int i = 0; i < count_; ++i) f(ring_[(head_ - i + kMotionHistory) % kMotionHistory].second);
  }
  void shiftSampleTimes(double dt);

  double nominalPeriod() const;  // median of the recent sample spacings, clamped [s]
  double blendTime() const;      // T [s]
  double lastSampleTime() const;
  int sampleCount() const { return count_; }
  double holdTime() const { return t_hold_; }
  const MotionGaps& gaps() const { return gaps_; }
  const ExternalMotionOptions& options() const { return opt_; }

 private:
  struct Quintic {
    double t0 = 0.0, T = 0.0;
    std::array<Vec, 6> c;
    void set(double t0, double T, const State& a, const State& b);
    State eval(double t) const;
  };
  const std::pair<double, Vec>& sample(int back) const;  // back = 0: newest
  void fit(State& out) const;                            // p, v, a at the newest sample time
  State predict(const State& fitted, double h, bool catch_up) const;
  double rejoinTime(double T_min, double t_sample, double t_now, const State& from, const State& fitted,
                    State& target) const;
  void plan(double t_now, double T, const State& from, const State& target);

  ExternalMotionOptions opt_;
  Limits lim_;
  std::array<std::pair<double, Vec>, kMotionHistory> ring_;
  int head_ = 0, count_ = 0;
  Quintic blend_, coast_, stop_;
  Vec hold_ = Vec::Zero();
  double t_hold_ = 0.0;
  double t_reset_ = 0.0;    // the last reset() (start_blend counts from it)
  double t_applied_ = 0.0;  // when the newest sample was applied
  MotionGaps gaps_;
};

class ExternalMotion : public TopMotion {
 public:
  static constexpr int kHistory = kMotionHistory;

  explicit ExternalMotion(const Vec2& p, double t = 0.0, const ExternalMotionOptions& options = {});
  std::string name() const override { return "external"; }
  PointMotion at(double t) const override;

  // Restarts at rest at p from time t: history cleared, (t, p) becomes the first sample.
  void reset(double t, const Vec2& p) { m_.reset(t, p); }
  // New sample taken at t_sample [s] at position p [m], applied at time t_now [s] (the current
  // integration time; not earlier than the previous application). Returns false, changing nothing,
  // for non-finite values or a stamp not newer than the previous sample.
  bool addSample(double t_sample, const Vec2& p, double t_now) { return m_.addSample(t_sample, p, t_now); }
  // Moves every stored sample time by -dt (the caller re-mapped its clock by dt).
  void shiftSampleTimes(double dt) { m_.shiftSampleTimes(dt); }

  double nominalPeriod() const { return m_.nominalPeriod(); }    // median of the recent sample spacings, clamped [s]
  double blendTime() const { return m_.blendTime(); }            // T [s]
  double lastSampleTime() const { return m_.lastSampleTime(); }  // [s]
  int sampleCount() const { return m_.sampleCount(); }
  double holdTime() const { return m_.holdTime(); }  // from this time on, the motion holds still [s]
  const MotionGaps& gaps() const { return m_.gaps(); }
  const ExternalMotionOptions& options() const { return m_.options(); }

 private:
  SampledMotion<2> m_;
};

}  // namespace riser_sim
