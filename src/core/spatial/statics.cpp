#include "riser_sim/spatial/statics.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rest_line.h"

namespace riser_sim {
namespace spatial {

using detail::RestLine;

namespace {

bool positiveDefinite(const MatX& A) { return Eigen::LLT<MatX>(0.5 * (A + A.transpose())).info() == Eigen::Success; }

// K + ρ CᵀC, symmetrised: positive definite iff K is on null(C), for ρ large enough (Finsler's lemma; ρ is 1e3 x
// K's stiffest diagonal over CᵀC's). Tests on the motions C allows without forming a basis of them.
MatX penalised(const MatX& K, const MatX& C) {
  MatX Kp = 0.5 * (K + K.transpose());
  if (C.rows() > 0) {
    const MatX CC = C.transpose() * C;
    Kp += (1e3 * K.diagonal().cwiseAbs().maxCoeff() / CC.diagonal().maxCoeff()) * CC;
  }
  return Kp;
}

// The least σ in {0, s, 4s, 16s, ...} (s = 1e-6 of K's stiffest diagonal over M's heaviest) that makes K + σ M
// positive definite on the motions C allows: a Newton step with it goes downhill in the energy, so the
// iteration is pushed off a saddle (an unstable equilibrium) and settles in a stable one; σ = 0 near one.
double stabilizingShift(const MatX& K, const MatX& M, const MatX& C) {
  const MatX Kp = penalised(K, C);
  if (positiveDefinite(Kp)) return 0.0;
  double sigma = 1e-6 * K.diagonal().cwiseAbs().maxCoeff() / M.diagonal().cwiseAbs().maxCoeff();
  for (int k = 0; k < 60 && !positiveDefinite(Kp + sigma * M); ++k) sigma *= 4.0;
  return sigma;
}

// Throws unless K is positive definite on the motions C allows (a rigid spin of a free top, neutral, passes at
// 1e-9 of the stiffest diagonal).
void requireStable(const MatX& K, const MatX& M, const MatX& C) {
  const double neutral = 1e-9 * K.diagonal().cwiseAbs().maxCoeff() / M.diagonal().cwiseAbs().maxCoeff();
  if (!positiveDefinite(penalised(K, C) + neutral * M))
    throw std::runtime_error(
        "the equilibrium found is unstable (its stiffness is negative in some motion the ends "
        "allow)");
}

}  // namespace

Kinematics3 equilibrium3(const Model3& model, const Kinematics3& guess, int iterations, const ModalOptions3& options,
                         AlignedVector<Vec3>* material_axes) {
  RestLine line(model, guess, options.fd_step, material_axes, options.hang_off);
  VecX theta = line.theta();
  const bool pinned = model.bottom() == BottomBoundary::kPinned;
  const double gap_tol = 1e-12 * model.line().length();
  auto converged = [&] {
    return line.residual(theta, model) < 1e-12 && (!pinned || line.endGap(theta, model).norm() < gap_tol);
  };
  const int p = line.size();
  // A free top in twist: K is singular along the rigid spin (Q_φ = 0 there); least-norm Newton steps.
  const bool free_spin = model.hasTorsion() && model.torsion().free_top;
  auto solve = [free_spin](const MatX& A, const VecX& b) -> VecX {
    return free_spin ? VecX(A.completeOrthogonalDecomposition().solve(b)) : VecX(A.partialPivLu().solve(b));
  };
  // Pinned: the anchor's force λ a multiplier whose geometric stiffness is in K (a dead load at fixed λ):
  // Q + Φᵀ λ - K_λ δ + Φᵀ Δλ = 0, E_n - p_b + Φ δ = 0. Steps halved (to 1/64) until residual + gap / L falls.
  Vec3 lambda = pinned ? line.anchorForce(theta, model) : Vec3::Zero();
  const double L = model.line().length();
  auto merit = [&] { return line.residual(theta, model) + (pinned ? line.endGap(theta, model).norm() / L : 0.0); };
  for (int it = 0; it < iterations; ++it) {
    if (converged()) {
      if (options.stable)
        requireStable(line.stiffness(theta, model, lambda), line.mass(theta),
                      pinned ? line.endJacobian(theta) : MatX(0, p));
      line.materialAxes(theta, model, material_axes);
      return line.kinematics(theta, model);
    }
    MatX K = line.stiffness(theta, model, lambda);
    if (options.stable) {
      const MatX M = line.mass(theta);
      K += stabilizingShift(K, M, pinned ? line.endJacobian(theta) : MatX(0, p)) * M;
    }
    VecX x;
    if (!pinned) {
      x = solve(K, VecX(line.forces(theta)));  // Q(θ + δ) ≈ Q - K δ = 0
    } else {
      const MatX Phi = line.endJacobian(theta);
      MatX A = MatX::Zero(p + 3, p + 3);
      A.topLeftCorner(p, p) = K;
      A.topRightCorner(p, 3) = -Phi.transpose();
      A.bottomLeftCorner(3, p) = Phi;
      VecX b(p + 3);
      b.head(p) = line.loaded(theta, lambda);
      b.tail(3) = -line.endGap(theta, model);
      x = solve(A, b);
    }
    const double merit0 = merit();
    const VecX theta0 = theta;
    const Vec3 lambda0 = lambda;
    for (double a = 1.0;; a *= 0.5) {
      theta = theta0 + a * x.head(p);
      if (pinned) lambda = lambda0 + a * x.tail<3>();
      if (a < 1.0 / 64.0 || merit() < merit0) break;
    }
  }
  if (converged()) {
    line.materialAxes(theta, model, material_axes);
    return line.kinematics(theta, model);
  }
  throw std::runtime_error("the 3D statics (Newton in the independent coordinates) did not converge");
}

Kinematics3 equilibriumHeldEnd3(const Model3& model, const Kinematics3& guess, const Vec2& xy, Vec3& force,
                                int iterations, const ModalOptions3& options, AlignedVector<Vec3>* material_axes) {
  if (model.bottom() == BottomBoundary::kPinned)
    throw std::invalid_argument(
        "the 3D statics with the end held horizontally: a free end only (a pinned one is held in full)");
  RestLine line(model, guess, options.fd_step, material_axes, options.hang_off);
  VecX theta = line.theta();
  const int p = line.size();
  Eigen::Matrix<double, 3, 2> P = Eigen::Matrix<double, 3, 2>::Zero();  // λ = P ν: horizontal
  P(0, 0) = P(1, 1) = 1.0;
  Vec2 nu = force.head<2>();
  double weight = 0.0;
  for (int i = 0; i < model.bodies(); ++i) weight += model.rfe(i).mass;
  weight *= model.gravity().norm();
  const double L = model.line().length();
  auto gap = [&] { return Vec2(line.kinematics(theta, model).back().end().head<2>() - xy); };
  auto residual = [&] {  // as RestLine::residual, with the end's force ν
    const VecX R = line.loaded(theta, P * nu);
    double r = 0.0;
    for (int c = 0; c < p; ++c) r = std::max(r, std::abs(R[c]) / (line.isDelta(c) ? weight : weight * L));
    return r;
  };
  for (int it = 0; it <= iterations; ++it) {
    if (residual() < 1e-12 && gap().norm() < 1e-12 * L) {
      if (options.stable)
        requireStable(line.stiffness(theta, model, P * nu), line.mass(theta), P.transpose() * line.endJacobian(theta));
      force = P * nu;
      line.materialAxes(theta, model, material_axes);
      return line.kinematics(theta, model);
    }
    if (it == iterations) break;
    // R(θ, ν) = Q + Φᵀ P ν: K_ν δ - Φᵀ P Δν = R, P ᵀ Φ δ = -gap (K_ν: ν's geometric stiffness in).
    MatX K = line.stiffness(theta, model, P * nu);
    const MatX G = P.transpose() * line.endJacobian(theta);
    if (options.stable) {
      const MatX M = line.mass(theta);
      K += stabilizingShift(K, M, G) * M;
    }
    MatX A = MatX::Zero(p + 2, p + 2);
    A.topLeftCorner(p, p) = K;
    A.topRightCorner(p, 2) = -G.transpose();
    A.bottomLeftCorner(2, p) = G;
    VecX b(p + 2);
    b.head(p) = line.loaded(theta, P * nu);
    b.tail(2) = -gap();
    const VecX x = A.partialPivLu().solve(b);
    // Backtracking on residual + gap / L: a contact (the seabed's kink at zero penetration) can make the full
    // step overshoot.
    const double merit0 = residual() + gap().norm() / L;
    const VecX theta0 = theta;
    const Vec2 nu0 = nu;
    for (double a = 1.0;; a *= 0.5) {
      theta = theta0 + a * x.head(p);
      nu = nu0 + a * x.tail(2);
      if (a < 1.0 / 64.0 || residual() + gap().norm() / L < merit0) break;
    }
  }
  throw std::runtime_error("the 3D equilibrium with the end held horizontally did not converge in " +
                           std::to_string(iterations) + " Newton iterations (residual " + std::to_string(residual()) +
                           " of the weight, gap " + std::to_string(gap().norm()) + " m)");
}

}  // namespace spatial
}  // namespace riser_sim
