// Prescribed motion of the top point A_0 in 3D: position, velocity and acceleration (the acceleration
// enters the constraint equations), and the holder's attitude (what a flex joint's axis turns with).
#pragma once
#include <memory>
#include <string>

#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/motion/top_motion.h"

namespace riser_sim {
namespace spatial {

struct PointMotion3 {
  Vec3 p = Vec3::Zero();      // [m]
  Vec3 v = Vec3::Zero();      // [m/s]
  Vec3 a = Vec3::Zero();      // [m/s^2]
  Mat3 R = Mat3::Identity();  // the holder's orientation: holder frame -> world
  Vec3 w = Vec3::Zero();      // the holder's angular velocity, world frame [rad/s]
};

// m.R = Rz(ψ) Ry(θ) Rx(φ) and m.w = ψ' z + θ' Rz y + φ' Rz Ry x (each rate about its axis where it acts) from the
// Z-Y-X angles (φ, θ, ψ) [rad] and their rates [rad/s]: the holder's attitude of the motions that turn it.
inline void setAttitudeZYX(const Vec3& angles, const Vec3& rates, PointMotion3& m) {
  const Mat3 Rz = Eigen::AngleAxisd(angles.z(), Vec3::UnitZ()).toRotationMatrix();
  const Mat3 Rzy = Rz * Eigen::AngleAxisd(angles.y(), Vec3::UnitY()).toRotationMatrix();
  m.R = Rzy * Eigen::AngleAxisd(angles.x(), Vec3::UnitX()).toRotationMatrix();
  m.w = rates.z() * Vec3::UnitZ() + rates.y() * Rz.col(1) + rates.x() * Rzy.col(0);
}

class TopMotion3 {
 public:
  virtual ~TopMotion3() = default;
  virtual PointMotion3 at(double t) const = 0;
  // True when at() can turn R (a holder that rotates: the node's vessel or ROV); false: R = I, w = 0 always.
  virtual bool rotates() const { return false; }
};

class FixedMotion3 : public TopMotion3 {
 public:
  explicit FixedMotion3(const Vec3& p) : p_(p) {}
  PointMotion3 at(double) const override { return PointMotion3{p_, Vec3::Zero(), Vec3::Zero()}; }

 private:
  Vec3 p_;
};

// p(t) = start + v t (ConstantVelocityMotion in 3D).
class ConstantVelocityMotion3 : public TopMotion3 {
 public:
  ConstantVelocityMotion3(const Vec3& start, const Vec3& v) : p_(start), v_(v) {}
  PointMotion3 at(double t) const override { return PointMotion3{p_ + v_ * t, v_, Vec3::Zero()}; }

 private:
  Vec3 p_, v_;
};

// A 2D top motion mapped into 3D: (x, y)_2D -> R (x, 0, y) + offset (see fromPlanar).
class PlanarMotion3 : public TopMotion3 {
 public:
  PlanarMotion3(std::unique_ptr<TopMotion> planar, const Mat3& R = Mat3::Identity(), const Vec3& offset = Vec3::Zero())
      : planar_(std::move(planar)), R_(R), offset_(offset) {}
  PointMotion3 at(double t) const override {
    const PointMotion m = planar_->at(t);
    return PointMotion3{planarPoint(m.p, R_, offset_), planarPoint(m.v, R_), planarPoint(m.a, R_)};
  }

 private:
  std::unique_ptr<TopMotion> planar_;
  Mat3 R_;
  Vec3 offset_;
};

}  // namespace spatial
}  // namespace riser_sim
