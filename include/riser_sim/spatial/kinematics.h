// Spatial (3D) rfe kinematics in natural (director) coordinates: q_i = [A_i (3), Δ_i, e_i (3)], e_i the
// unit vector along the rfe, held on the unit sphere by a constraint. No angles: no orientation
// singularity. World frame REP 103: x, y horizontal, z up. SI units.
#pragma once
#include <Eigen/Geometry>
#include <vector>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {
namespace spatial {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

constexpr int kDofPerBody3 = 7;             // [A (3), Δ, e (3)]
constexpr int kA = 0, kDelta3 = 3, kE = 4;  // offsets inside q_i

struct BodyKinematics3 {
  Vec3 A = Vec3::Zero();                // point A_i [m]
  Vec3 A_dot = Vec3::Zero();            // [m/s]
  double delta = 0.0, delta_dot = 0.0;  // Δ_i [m], [m/s]
  Vec3 e = Vec3(1, 0, 0);               // director, unit on the manifold
  Vec3 e_dot = Vec3::Zero();            // [1/s]
  double len = 0.0;                     // l_i + Δ_i [m]

  // Point at distance s0 + kappa Δ from A_i along e, and its velocity.
  Vec3 point(double s0, double kappa) const { return A + (s0 + kappa * delta) * e; }
  Vec3 velocity(double s0, double kappa) const { return A_dot + kappa * delta_dot * e + (s0 + kappa * delta) * e_dot; }
  Vec3 end() const { return A + len * e; }
  Vec3 endVelocity() const { return A_dot + delta_dot * e + len * e_dot; }
  Vec3 omega() const { return e.cross(e_dot); }  // angular velocity transverse to e [rad/s]
};

using Kinematics3 = AlignedVector<BodyKinematics3>;

// Adds to Q_i (7 entries at q) the generalised force of a force F [N] at distance s0 + kappa Δ from A_i:
// [F; kappa e·F; s F].
inline void addPointForce(const BodyKinematics3& b, double s0, double kappa, const Vec3& F, double* q) {
  const double s = s0 + kappa * b.delta;
  for (int k = 0; k < 3; ++k) q[kA + k] += F[k], q[kE + k] += s * F[k];
  q[kDelta3] += kappa * b.e.dot(F);
}
// Velocity of the point (s0, κ) of b per q' (3x7), also its position per q: [I, κ e, (s0 + κΔ) I].
inline Eigen::Matrix<double, 3, kDofPerBody3> pointJacobian(const BodyKinematics3& b, double s0, double kappa) {
  Eigen::Matrix<double, 3, kDofPerBody3> J = Eigen::Matrix<double, 3, kDofPerBody3>::Zero();
  J.block<3, 3>(0, kA).setIdentity();
  J.col(kDelta3) = kappa * b.e;
  J.block<3, 3>(0, kE) = (s0 + kappa * b.delta) * Mat3::Identity();
  return J;
}
// Adds the generalised force of a torque tau [N m] on rfe i: Q_e = tau × e (virtual power tau·ω).
inline void addTorque(const BodyKinematics3& b, const Vec3& tau, double* q) {
  const Vec3 qe = tau.cross(b.e);
  for (int k = 0; k < 3; ++k) q[kE + k] += qe[k];
}

// A straight or bent chain with closed joints and Δ_i = 0 moving rigidly: A_0 = top at velocity v_top,
// rfe i along directions[i] (normalised), angular velocity omega [rad/s] about A_0.
Kinematics3 rigidChain(const Model& line, const Vec3& top, const std::vector<Vec3>& directions, const Vec3& v_top,
                       const Vec3& omega);
// A planar (2D) state mapped into 3D: (x, y)_2D -> R (x, 0, y) + offset (the 2D plane is the rotated x-z plane).
Kinematics3 fromPlanar(const Kinematics& kin, const Mat3& R = Mat3::Identity(), const Vec3& offset = Vec3::Zero());
// Position of a 2D point in 3D under the same map.
inline Vec3 planarPoint(const Vec2& p, const Mat3& R = Mat3::Identity(), const Vec3& offset = Vec3::Zero()) {
  return R * Vec3(p.x(), 0.0, p.y()) + offset;
}

}  // namespace spatial
}  // namespace riser_sim
