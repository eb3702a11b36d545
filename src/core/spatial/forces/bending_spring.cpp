#include "riser_sim/spatial/forces/bending_spring.h"

#include <cmath>

namespace riser_sim {
namespace spatial {

// Series 1 + θ²/6 + 7θ⁴/360 below 1e-4 rad: exact to round-off there.
double BendingSpring::thetaOverSin(double theta) {
  if (theta < 1e-4) {
    const double t2 = theta * theta;
    return 1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0;
  }
  return theta / std::sin(theta);
}

// V = ½ k θ²: Q_b = -k θ ∂θ/∂b = k (θ/sinθ) / (|a||b|) (a - (a·b) b/|b|²), Q_a likewise with a, b swapped.
// With sinθ = |a×b| / (|a||b|) the factor is k θ / |a×b| (no sin, no square root) away from θ = 0; below
// 1e-4 rad the series of θ/sinθ over |a||b|.
void BendingSpring::addForces(const SpatialModel& model, const Kinematics3& kin, double t, VecX& Q) const {
  addForcesAndPower(model, kin, t, Q);
}

double BendingSpring::addForcesAndPower(const SpatialModel& model, const Kinematics3& kin, double, VecX& Q) const {
  const double k = model.bendingStiffness(), c = model.bendingDamping();
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const Vec3& a = kin[i - 1].e;
    const Vec3& b = kin[i].e;
    double* qa = Q.data() + kDofPerBody3 * (i - 1);
    double* qb = Q.data() + kDofPerBody3 * i;
    if (k != 0.0) {
      const double ab = a.dot(b), s = a.cross(b).norm(), theta = std::atan2(s, ab);
      if (theta < M_PI - kFoldedTol) {
        const double aa = a.squaredNorm(), bb = b.squaredNorm();
        const double f = theta < 1e-4 ? k * thetaOverSin(theta) / std::sqrt(aa * bb) : k * theta / s;
        const Vec3 Fa = f * (b - (ab / aa) * a), Fb = f * (a - (ab / bb) * b);
        for (int j = 0; j < 3; ++j) qa[kE + j] += Fa[j], qb[kE + j] += Fb[j];
      }
    }
    if (c != 0.0) {
      const Vec3 dw = kin[i].omega() - kin[i - 1].omega();
      const Vec3 tau = -c * dw;  // on rfe i; -tau on rfe i-1
      addTorque(kin[i], tau, qb);
      addTorque(kin[i - 1], -tau, qa);
      p -= c * dw.squaredNorm();
    }
  }
  return p;
}

double BendingSpring::potentialEnergy(const SpatialModel& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double theta = angle(kin[i - 1].e, kin[i].e);
    v += 0.5 * model.bendingStiffness() * theta * theta;
  }
  return v;
}

double BendingSpring::power(const SpatialModel& model, const Kinematics3& kin, double) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) p -= model.bendingDamping() * (kin[i].omega() - kin[i - 1].omega()).squaredNorm();
  return p;
}

namespace {
Mat3 cross(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}
}  // namespace

// Spring: the exact Hessian of ½ k θ² in a, b (any lengths). With u = a/|a|, w = b/|b|, c = u·w, s = sin θ,
// φ = θ/s, g_a = (w - c u)/|a| (= ∂c/∂a), ∂θ/∂a = -g_a/s: Q_a = k φ g_a, and
//   ∂Q_a/∂a = k (-ψ g_a g_aᵀ + φ ∂g_a/∂a),  ∂Q_a/∂b = k (-ψ g_a g_bᵀ + φ ∂g_a/∂b),  ψ = φ'(θ)/s = (s - θ cos θ)/s³,
//   ∂g_a/∂a = -(u g_aᵀ + g_a uᵀ)/|a| - c (I - u uᵀ)/|a|²,  ∂g_a/∂b = (I - u uᵀ - w wᵀ + c u wᵀ)/(|a||b|).
// Zero within 1e-12 rad of θ = π, as the force.
// Damping: Q_b = τ × b, Q_a = -τ × a, τ = -c_d (b × b' - a × a'): C_bb = c_d (|b|² I - b bᵀ),
// C_ba = c_d [b]×[a]×, and through e (not symmetric): K_bb = c_d [b]×[b']× - [τ]×, K_aa = c_d [a]×[a']× + [τ]×,
// K_ba = -c_d [b]×[a']×, K_ab = -c_d [a]×[b']×.
void BendingSpring::addStiffness(const SpatialModel& model, const Kinematics3& kin, double, SpatialStiffness& S) const {
  const double k = model.bendingStiffness(), c = model.bendingDamping();
  const Mat3 I3 = Mat3::Identity();
  for (int i = 1; i < model.bodies(); ++i) {
    const Vec3& a = kin[i - 1].e;
    const Vec3& b = kin[i].e;
    const double theta = angle(a, b);
    if (k != 0.0 && theta < M_PI - kFoldedTol) {
      const double la = a.norm(), lb = b.norm();
      const Vec3 u = a / la, w = b / lb;
      const double cs = u.dot(w), sn = std::sin(theta), phi = thetaOverSin(theta);
      const double psi = theta < 1e-4 ? 1.0 / 3.0 + 2.0 * theta * theta / 15.0
                                      : (sn - theta * std::cos(theta)) / (sn * sn * sn);
      const Vec3 ga = (w - cs * u) / la, gb = (u - cs * w) / lb;
      const Mat3 dga_a = -(u * ga.transpose() + ga * u.transpose()) / la - cs * (I3 - u * u.transpose()) / (la * la);
      const Mat3 dgb_b = -(w * gb.transpose() + gb * w.transpose()) / lb - cs * (I3 - w * w.transpose()) / (lb * lb);
      const Mat3 dgb_a = (I3 - u * u.transpose() - w * w.transpose() + cs * w * u.transpose()) / (la * lb);
      S.K_diag[i - 1].block<3, 3>(kE, kE) -= k * (-psi * ga * ga.transpose() + phi * dga_a);
      S.K_diag[i].block<3, 3>(kE, kE) -= k * (-psi * gb * gb.transpose() + phi * dgb_b);
      S.K_sub[i] -= k * (-psi * gb * ga.transpose() + phi * dgb_a);
    }
    if (c != 0.0) {
      const Mat3 Xa = cross(a), Xb = cross(b);
      S.C_diag[i - 1].block<3, 3>(kE, kE) -= c * Xa * Xa;
      S.C_diag[i].block<3, 3>(kE, kE) -= c * Xb * Xb;
      S.C_sub[i] += c * Xb * Xa;
      const Mat3 Xad = cross(kin[i - 1].e_dot), Xbd = cross(kin[i].e_dot);
      const Mat3 Xt = cross(-c * (kin[i].omega() - kin[i - 1].omega()));
      S.K_diag[i - 1].block<3, 3>(kE, kE) += c * Xa * Xad + Xt;
      S.K_diag[i].block<3, 3>(kE, kE) += c * Xb * Xbd - Xt;
      S.K_sub[i] -= c * Xb * Xad;
      S.K_sup[i] += c * (Xad * Xb - Xa * Xbd);  // K_ab - K_baᵀ
    }
  }
}

}  // namespace spatial
}  // namespace riser_sim
