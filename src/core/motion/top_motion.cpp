#include "riser_sim/motion/top_motion.h"

#include <cmath>
#include <stdexcept>

namespace riser_sim {

PointMotion SinusoidMotion::at(double t) const {
  const double arg = omega_ * t + phase_;
  const double c = std::cos(arg), s = std::sin(arg);
  return PointMotion{center_ + amp_ * c, -amp_ * omega_ * s, -amp_ * omega_ * omega_ * c};
}

VelocityProfileMotion::VelocityProfileMotion(const Vec2& start, std::vector<Knot> knots)
    : start_(start), knots_(std::move(knots)) {
  if (knots_.empty()) throw std::invalid_argument("top.motion.knots: needs at least one knot");
  for (size_t k = 1; k < knots_.size(); ++k)
    if (!(knots_[k].t > knots_[k - 1].t)) throw std::invalid_argument("top.motion.knots: times must increase");
  p_at_knot_.resize(knots_.size());
  p_at_knot_[0] = start_;
  for (size_t k = 1; k < knots_.size(); ++k)
    p_at_knot_[k] = p_at_knot_[k - 1] + 0.5 * (knots_[k].v + knots_[k - 1].v) * (knots_[k].t - knots_[k - 1].t);
}

PointMotion VelocityProfileMotion::at(double t) const {
  if (t <= knots_.front().t) return PointMotion{start_, Vec2::Zero(), Vec2::Zero()};
  if (t >= knots_.back().t) {
    const Vec2& v = knots_.back().v;
    return PointMotion{p_at_knot_.back() + v * (t - knots_.back().t), v, Vec2::Zero()};
  }
  size_t k = 1;
  while (knots_[k].t < t) ++k;
  const Knot& a = knots_[k - 1];
  const Knot& b = knots_[k];
  const double tau = t - a.t;
  const Vec2 acc = (b.v - a.v) / (b.t - a.t);
  return PointMotion{p_at_knot_[k - 1] + a.v * tau + 0.5 * acc * tau * tau, a.v + acc * tau, acc};
}

}  // namespace riser_sim
