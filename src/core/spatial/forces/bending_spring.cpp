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

// asin(x)/x = θ/sinθ from x² = sin²θ (θ < 90°): its Maclaurin series to x¹⁴, c_j = (2j)! / (4^j (j!)² (2j+1));
// for x² <= kSeriesSin2 = 0.01 the first term left out, c_8 x¹⁶ = 1.2e-18, is below round-off.
double BendingSpring::asinOverSin(double x2) {
  constexpr double c[8] = {1.0,           1.0 / 6.0,     3.0 / 40.0,      5.0 / 112.0,
                           35.0 / 1152.0, 63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0};
  const double x4 = x2 * x2, x8 = x4 * x4;  // Estrin's scheme: three levels, not a chain of seven
  const double p01 = c[0] + c[1] * x2, p23 = c[2] + c[3] * x2, p45 = c[4] + c[5] * x2, p67 = c[6] + c[7] * x2;
  return (p01 + x4 * p23) + x8 * (p45 + x4 * p67);
}

// V = ½ k θ²: Q_b = -k θ ∂θ/∂b = k (θ/sinθ) / (|a||b|) (a - (a·b) b/|b|²), Q_a likewise with a, b swapped.
// With sinθ = |a×b| / (|a||b|) the factor is k (θ/sinθ) / (|a||b|): below ~5.7° (sin²θ <= 0.01, a·b > 0) by
// asinOverSin's series (no atan2: a tenth of the 3D evaluation), above as k θ / |a×b| with θ = atan2.
void BendingSpring::addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const {
  addForcesAndPower(model, kin, t, Q);
}

double BendingSpring::addForcesAndPower(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double k = model.bendingStiffness(i), c = model.bendingDamping(i);
    const Vec3& a = kin[i - 1].e;
    const Vec3& b = kin[i].e;
    double* qa = Q.data() + kDofPerBody3 * (i - 1);
    double* qb = Q.data() + kDofPerBody3 * i;
    if (k != 0.0) {
      const double ab = a.dot(b), ss = a.cross(b).squaredNorm(), aa = a.squaredNorm(), bb = b.squaredNorm();
      const double r2 = 1.0 / (aa * bb), sin2 = ss * r2;  // 1 / (|a||b|)², sin²θ
      double f = 0.0;
      bool bent = true;
      if (ab > 0.0 && sin2 <= kSeriesSin2) {  // θ below ~5.7°, the usual bend between neighbours
        f = k * asinOverSin(sin2) * std::sqrt(r2);
      } else {
        const double s = std::sqrt(ss), theta = std::atan2(s, ab);
        bent = theta < M_PI - kFoldedTol;
        f = k * theta / s;
      }
      if (bent) {
        const double ab_r2 = ab * r2;  // a·b / |a|² = ab_r2 |b|²
        const Vec3 Fa = f * (b - (ab_r2 * bb) * a), Fb = f * (a - (ab_r2 * aa) * b);
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

double BendingSpring::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int i = 1; i < model.bodies(); ++i) {
    const double theta = angle(kin[i - 1].e, kin[i].e);
    v += 0.5 * model.bendingStiffness(i) * theta * theta;
  }
  return v;
}

double BendingSpring::power(const Model3& model, const Kinematics3& kin, double) const {
  double p = 0.0;
  for (int i = 1; i < model.bodies(); ++i)
    p -= model.bendingDamping(i) * (kin[i].omega() - kin[i - 1].omega()).squaredNorm();
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
void BendingSpring::addStiffness(const Model3& model, const Kinematics3& kin, double, Stiffness3& S) const {
  const Mat3 I3 = Mat3::Identity();
  for (int i = 1; i < model.bodies(); ++i) {
    const double k = model.bendingStiffness(i), c = model.bendingDamping(i);
    const Vec3& a = kin[i - 1].e;
    const Vec3& b = kin[i].e;
    const double theta = angle(a, b);
    if (k != 0.0 && theta < M_PI - kFoldedTol) {
      const double la = a.norm(), lb = b.norm();
      const Vec3 u = a / la, w = b / lb;
      const double cs = u.dot(w), sn = std::sin(theta), phi = thetaOverSin(theta);
      const double psi =
          theta < 1e-4 ? 1.0 / 3.0 + 2.0 * theta * theta / 15.0 : (sn - theta * std::cos(theta)) / (sn * sn * sn);
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
