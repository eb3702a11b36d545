#include "riser_sim/spatial/bending_axes.h"

#include <cmath>

#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/model.h"

namespace riser_sim {
namespace spatial {

namespace {

// φ = θ/sinθ and ψ = φ'(θ)/sinθ = (sinθ - θ cosθ)/sin³θ at the joint (n_a·n_b = c, |n_a × n_b|² = s2).
// False within kFoldedTol of π (no bending direction).
bool bendFactors(double c, double s2, double& phi, double& psi) {
  const double theta = std::atan2(std::sqrt(s2), c);
  if (theta > M_PI - BendingSpring::kFoldedTol) return false;
  if (theta < 1e-2) {  // series; the next terms are below 1e-14 here
    const double t2 = theta * theta;
    phi = 1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0 + 31.0 * t2 * t2 * t2 / 15120.0;
    psi = 1.0 / 3.0 + 2.0 * t2 / 15.0 + 2.0 * t2 * t2 / 63.0;
    return true;
  }
  const double s = std::sin(theta);
  phi = theta / s;
  psi = (s - theta * std::cos(theta)) / (s * s * s);
  return true;
}

Vec3 unit(const Vec3& e) { return e / e.norm(); }

// P κ = m1 (m1·κ) - m2 (m2·κ), m2 = n × m1.
Vec3 splitCurvature(const Vec3& n, const Vec3& m1, const Vec3& kappa) {
  const Vec3 m2 = n.cross(m1);
  return m1.dot(kappa) * m1 - m2.dot(kappa) * m2;
}

void materialAxes(const Kinematics3& kin, const double* theta, const TwistFrames& f, AlignedVector<Vec3>& m1) {
  for (int i = 0; i < int(kin.size()); ++i) m1[i] = materialDirector(f, i, unit(kin[i].e), theta[i]);
}

}  // namespace

void addBendingAxesForces(const Model3& model, const Kinematics3& kin, const double* theta, const TwistFrames& f,
                          AlignedVector<Vec3>& m1, VecX& Q, double* moment) {
  if (!model.hasBendingAxes()) return;
  const double sigma = model.bendingSplit();
  if (sigma == 0.0) return;
  materialAxes(kin, theta, f, m1);
  for (int k = 0; k + 1 < model.bodies(); ++k) {
    const Vec3 na = unit(kin[k].e), nb = unit(kin[k + 1].e);
    const Vec3 X = na.cross(nb);
    double phi = 1.0, psi = 0.0;
    if (!bendFactors(na.dot(nb), X.squaredNorm(), phi, psi)) continue;
    const Vec3 kappa = phi * X;
    const Vec3 Pa = splitCurvature(na, m1[k], kappa), Pb = splitCurvature(nb, m1[k + 1], kappa);
    const Vec3 G = 0.5 * sigma * (Pa + Pb), Ma = 0.5 * sigma * Pa.cross(kappa), Mb = 0.5 * sigma * Pb.cross(kappa);
    const double gx = psi * G.dot(X);
    const Vec3 dna = phi * nb.cross(G) - gx * nb + Ma.cross(na);
    const Vec3 dnb = phi * G.cross(na) - gx * na + Mb.cross(nb);
    // On e (any length): -(I - n nᵀ) ∂V/∂n / |e|.
    Q.segment<3>(kDofPerBody3 * k + kE) -= (dna - dna.dot(na) * na) / kin[k].e.norm();
    Q.segment<3>(kDofPerBody3 * (k + 1) + kE) -= (dnb - dnb.dot(nb) * nb) / kin[k + 1].e.norm();
    moment[k] -= Ma.dot(na);
    moment[k + 1] -= Mb.dot(nb);
  }
}

double bendingAxesEnergy(const Model3& model, const Kinematics3& kin, const double* theta, const TwistFrames& f) {
  if (!model.hasBendingAxes() || model.bendingSplit() == 0.0) return 0.0;
  double v = 0.0;
  Vec3 m1a = materialDirector(f, 0, unit(kin[0].e), theta[0]);
  for (int k = 0; k + 1 < model.bodies(); ++k) {
    const Vec3 na = unit(kin[k].e), nb = unit(kin[k + 1].e);
    const Vec3 m1b = materialDirector(f, k + 1, nb, theta[k + 1]);
    const Vec3 X = na.cross(nb);
    double phi = 1.0, psi = 0.0;
    if (bendFactors(na.dot(nb), X.squaredNorm(), phi, psi)) {
      const Vec3 kappa = phi * X;
      v += kappa.dot(splitCurvature(na, m1a, kappa)) + kappa.dot(splitCurvature(nb, m1b, kappa));
    }
    m1a = m1b;
  }
  return 0.25 * model.bendingSplit() * v;
}

}  // namespace spatial
}  // namespace riser_sim
