// Prescribed motion of the top point A_0 (paper eq. 7.2): position, velocity and acceleration,
// since A_0's acceleration enters the constraint equations.
#pragma once
#include <string>
#include <vector>

#include "riser_sim/types.h"

namespace riser_sim {

struct PointMotion {
  Vec2 p = Vec2::Zero();  // [m]
  Vec2 v = Vec2::Zero();  // [m/s]
  Vec2 a = Vec2::Zero();  // [m/s^2]
};

class TopMotion {
 public:
  virtual ~TopMotion() = default;
  virtual std::string name() const = 0;
  virtual PointMotion at(double t) const = 0;
};

class FixedMotion : public TopMotion {
 public:
  explicit FixedMotion(const Vec2& p) : p_(p) {}
  std::string name() const override { return "fixed"; }
  PointMotion at(double) const override { return PointMotion{p_, Vec2::Zero(), Vec2::Zero()}; }

 private:
  Vec2 p_;
};

// p(t) = start + v t: a holder moving at a constant velocity (a fixed top carried along by initial.velocity).
class ConstantVelocityMotion : public TopMotion {
 public:
  ConstantVelocityMotion(const Vec2& start, const Vec2& v) : p_(start), v_(v) {}
  std::string name() const override { return "constant_velocity"; }
  PointMotion at(double t) const override { return PointMotion{p_ + v_ * t, v_, Vec2::Zero()}; }

 private:
  Vec2 p_, v_;
};

// p(t) = center + amplitude * cos(2π t / period + phase), per axis (paper eq. 27: x_0 = 10 cos(2πt/27)).
class SinusoidMotion : public TopMotion {
 public:
  SinusoidMotion(const Vec2& center, const Vec2& amplitude, double period, double phase)
      : center_(center), amp_(amplitude), omega_(2.0 * M_PI / period), phase_(phase) {}
  std::string name() const override { return "sinusoid"; }
  PointMotion at(double t) const override;

 private:
  Vec2 center_, amp_;
  double omega_, phase_;
};

// Velocity piecewise linear between (time, velocity) knots, zero before the first knot and held
// after the last; position integrated exactly (paper Fig. 9b).
class VelocityProfileMotion : public TopMotion {
 public:
  struct Knot {
    double t;
    Vec2 v;
  };
  VelocityProfileMotion(const Vec2& start, std::vector<Knot> knots);
  std::string name() const override { return "velocity_profile"; }
  PointMotion at(double t) const override;

 private:
  Vec2 start_;
  std::vector<Knot> knots_;
  std::vector<Vec2> p_at_knot_;
};

}  // namespace riser_sim
