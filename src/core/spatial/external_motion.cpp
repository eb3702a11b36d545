#include "riser_sim/spatial/external_motion.h"

#include <cmath>

namespace riser_sim {
namespace spatial {

namespace {
bool usable(const Eigen::Quaterniond& q) { return q.coeffs().allFinite() && q.norm() > 1e-9; }

Mat3 hat(const Vec3& r) {
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// A = (1 - cos θ)/θ², B = (θ - sin θ)/θ³ and A'(θ)/θ, B'(θ)/θ (series below θ = 0.05: the closed forms cancel).
struct JacobianCoefficients {
  double A, B, dA, dB;
  explicit JacobianCoefficients(double th) {
    const double t2 = th * th;
    if (th < 0.05) {
      A = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
      B = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0;
      dA = -1.0 / 12.0 + t2 / 180.0 - t2 * t2 / 6720.0;
      dB = -1.0 / 60.0 + t2 / 1260.0 - t2 * t2 / 60480.0;
    } else {
      const double s = std::sin(th), c = std::cos(th);
      A = (1.0 - c) / t2;
      B = (th - s) / (t2 * th);
      dA = (th * s - 2.0 * (1.0 - c)) / (t2 * t2);
      dB = ((1.0 - c) * th - 3.0 * (th - s)) / (t2 * t2 * th);
    }
  }
};

}  // namespace

Mat3 ExternalMotion3::expMap(const Vec3& r) {
  const double th = r.norm();
  const Mat3 K = hat(r);
  const double t2 = th * th;
  const double a = th < 0.05 ? 1.0 - t2 / 6.0 + t2 * t2 / 120.0 : std::sin(th) / th;
  const double b = th < 0.05 ? 0.5 - t2 / 24.0 + t2 * t2 / 720.0 : (1.0 - std::cos(th)) / t2;
  return Mat3::Identity() + a * K + b * K * K;
}

Mat3 ExternalMotion3::leftJacobian(const Vec3& r) {
  const JacobianCoefficients k(r.norm());
  const Mat3 K = hat(r);
  return Mat3::Identity() + k.A * K + k.B * K * K;
}

Mat3 ExternalMotion3::leftJacobianRate(const Vec3& r, const Vec3& v) {
  const JacobianCoefficients k(r.norm());
  const Mat3 K = hat(r), V = hat(v);
  const double rv = r.dot(v);  // θ θ'
  return k.dA * rv * K + k.A * V + k.dB * rv * K * K + k.B * (V * K + K * V);
}

Vec3 ExternalMotion3::logNear(const Mat3& R, const Vec3& near) {
  const Eigen::AngleAxisd aa(R);
  const double th = aa.angle();
  if (!(th > 1e-12)) {  // the identity: 2πk about near's axis
    const double n = near.norm();
    if (n < M_PI) return Vec3::Zero();
    return near / n * (2.0 * M_PI * std::round(n / (2.0 * M_PI)));
  }
  const Vec3 u = aa.axis();
  const double k = std::round((u.dot(near) - th) / (2.0 * M_PI));
  return u * (th + 2.0 * M_PI * k);
}

ExternalMotion3::ExternalMotion3(const Vec3& p, double t, const ExternalMotionOptions& options)
    : pos_(p, t, options, {options.rejoin_max_acceleration, options.rejoin_max_velocity}),
      rot_(Vec3::Zero(), t, options, {options.rejoin_max_angular_acceleration, options.rejoin_max_angular_velocity}) {}

ExternalMotion3::ExternalMotion3(const Vec3& p, const Eigen::Quaterniond& q, double t,
                                 const ExternalMotionOptions& options)
    : ExternalMotion3(p, t, options) {
  rotates_ = true;
  reset(t, p, q);
}

PointMotion3 ExternalMotion3::at(double t) const {
  const SampledMotion<3>::State s = pos_.at(t);
  PointMotion3 m{s.p, s.v, s.a};
  if (!rotates_) return m;
  const SampledMotion<3>::State r = rot_.at(t);
  m.R = base_ * expMap(r.p);
  m.w = base_ * (leftJacobian(r.p) * r.v);
  return m;
}

Vec3 ExternalMotion3::angularAcceleration(double t) const {
  if (!rotates_) return Vec3::Zero();
  const SampledMotion<3>::State r = rot_.at(t);
  return base_ * (leftJacobianRate(r.p, r.v) * r.v + leftJacobian(r.p) * r.a);
}

void ExternalMotion3::reset(double t, const Vec3& p) {
  pos_.reset(t, p);
  if (!rotates_) return;
  base_ = last_;
  rot_.reset(t, Vec3::Zero());
}

void ExternalMotion3::reset(double t, const Vec3& p, const Eigen::Quaterniond& q) {
  if (usable(q)) last_ = q.normalized().toRotationMatrix();
  reset(t, p);
}

bool ExternalMotion3::addSample(double t_sample, const Vec3& p, double t_now) {
  // Both channels keep the same stamps: the attitude accepts whatever the position accepts.
  if (!p.allFinite()) return false;
  if (!pos_.addSample(t_sample, p, t_now)) return false;
  if (rotates_) addAttitude(t_sample, last_, t_now);
  return true;
}

bool ExternalMotion3::addSample(double t_sample, const Vec3& p, const Eigen::Quaterniond& q, double t_now) {
  if (!usable(q)) return false;
  if (!p.allFinite() || !pos_.addSample(t_sample, p, t_now)) return false;
  if (rotates_) {
    last_ = q.normalized().toRotationMatrix();
    addAttitude(t_sample, last_, t_now);
  }
  return true;
}

// Re-base to the attitude at t_now, R_b' = R_b Exp(r): there r' = 0, ṙ' = J_r(r) ṙ (the same w) and
// r̈' = R_b'^T α (the same angular acceleration α = R_b (J̇_l ṙ + J_l r̈), as J_l(0) = I and J̇_l(0) ṙ' ∥ ṙ' × ṙ' = 0);
// the samples kept are re-expressed about R_b' (their branch the one nearest their old value minus r).
void ExternalMotion3::addAttitude(double t_sample, const Mat3& R, double t_now) {
  const SampledMotion<3>::State s = rot_.at(t_now);
  const Mat3 E = expMap(s.p);
  const Mat3 base = base_ * E;
  SampledMotion<3>::State from;
  from.v = E.transpose() * (leftJacobian(s.p) * s.v);  // J_r(r) = Exp(r)^T J_l(r)
  from.a = E.transpose() * (leftJacobianRate(s.p, s.v) * s.v + leftJacobian(s.p) * s.a);
  const Mat3 Et = E.transpose();
  Vec3 newest = Vec3::Zero();
  bool first = true;
  rot_.mapSampleValues([&](Vec3& r) {
    r = logNear(Et * expMap(r), r - s.p);
    if (first) newest = r, first = false;
  });
  base_ = Eigen::Quaterniond(base).normalized().toRotationMatrix();  // no drift from the products
  rot_.addSample(t_sample, logNear(base_.transpose() * R, newest), t_now, from);
}

void ExternalMotion3::shiftSampleTimes(double dt) {
  pos_.shiftSampleTimes(dt);
  if (rotates_) rot_.shiftSampleTimes(dt);
}

}  // namespace spatial
}  // namespace riser_sim
