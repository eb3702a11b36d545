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
// at() allocates nothing; addSample() allocates nothing (fixed ring buffer).
#pragma once
#include <array>
#include <string>

#include "riser_sim/top_motion.h"

namespace riser_sim {

struct ExternalMotionOptions {
  double fit_window = 0.5;       // samples within this time of the newest one enter the fit [s]
  int fit_max_samples = 32;      // at most this many (<= ExternalMotion::kHistory)
  double default_period = 0.1;   // sample period assumed before two samples arrived [s]
  double min_period = 0.002;     // clamp of the estimated sample period [s]
  double max_period = 0.5;       // [s]
  double min_blend = 0.1;        // shortest blend: bounds the acceleration a noisy sample can cause [s]
  bool predict = true;           // aim at the extrapolated state (lag ~ 0) instead of the sample
  double max_prediction = 0.3;   // longest extrapolation beyond the newest sample [s]
  double coast_time = 0.2;       // constant-velocity continuation past the blend [s]
  double stop_time = 0.5;        // velocity decay to zero, then hold [s] (> 0)
  // After reset() (the line at rest): the catch-up with a source already moving is spread until this long after
  // the reset [s] (each blend then ends there, aimed at the source's state predicted to that time), so the top
  // accelerates by ~v / start_blend instead of v / min_blend. 0: off.
  double start_blend = 0.0;

  // Empty when valid, else "field: reason".
  std::string validate() const;
};

class ExternalMotion : public TopMotion {
 public:
  static constexpr int kHistory = 32;

  explicit ExternalMotion(const Vec2& p, double t = 0.0, const ExternalMotionOptions& options = {});
  std::string name() const override { return "external"; }
  PointMotion at(double t) const override;

  // Restarts at rest at p from time t: history cleared, (t, p) becomes the first sample.
  void reset(double t, const Vec2& p);
  // New sample taken at t_sample [s] at position p [m], applied at time t_now [s] (the current
  // integration time; not earlier than the previous application). Returns false, changing nothing,
  // for non-finite values or a stamp not newer than the previous sample.
  bool addSample(double t_sample, const Vec2& p, double t_now);
  // Moves every stored sample time by -dt (the caller re-mapped its clock by dt).
  void shiftSampleTimes(double dt);

  double nominalPeriod() const;      // median of the recent sample spacings, clamped [s]
  double blendTime() const;          // T [s]
  double lastSampleTime() const;     // [s]
  int sampleCount() const { return count_; }
  double holdTime() const { return t_hold_; }  // from this time on, the motion holds still [s]
  const ExternalMotionOptions& options() const { return opt_; }

 private:
  struct Quintic {
    double t0 = 0.0, T = 0.0;
    std::array<Vec2, 6> c;
    void set(double t0, double T, const PointMotion& a, const PointMotion& b);
    PointMotion eval(double t) const;
  };
  const std::pair<double, Vec2>& sample(int back) const;  // back = 0: newest
  void fit(PointMotion& out) const;  // p, v, a at the newest sample time
  void plan(double t_now, double T, const PointMotion& from, const PointMotion& target);

  ExternalMotionOptions opt_;
  std::array<std::pair<double, Vec2>, kHistory> ring_;
  int head_ = 0, count_ = 0;
  Quintic blend_, coast_, stop_;
  Vec2 hold_ = Vec2::Zero();
  double t_hold_ = 0.0;
  double t_reset_ = 0.0;  // the last reset() (start_blend counts from it)
};

}  // namespace riser_sim
