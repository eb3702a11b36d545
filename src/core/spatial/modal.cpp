#include "riser_sim/spatial/modal.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "riser_sim/spatial/independent_formulation.h"

namespace riser_sim {
namespace spatial {

namespace {

// The line at rest from the fixed top in IndependentFormulation3's coordinates: generalised forces Q_θ
// (the right side at θ' = 0, where the velocity and top terms vanish), M_θ and the FD stiffness.
class RestLine {
 public:
  RestLine(const SpatialModel& model, const Kinematics3& kin, double fd_step)
      : f_(model), data_(f_.makeData()), p_(f_.positionSize()), fd_step_(fd_step) {
    top_.p = kin[0].A;
    Kinematics3 rest = kin;
    for (auto& b : rest) b.A_dot.setZero(), b.e_dot.setZero(), b.delta_dot = 0.0;
    y_.setZero(2 * p_);
    dy_.setZero(2 * p_);
    f_.packState(rest, charts_, y_);  // charts centred on kin's directors: u = 0
    theta_ = y_.head(p_);
  }
  int size() const { return p_; }
  bool isDelta(int c) const { return f_.coordinatesPerBody() == 3 && c < spinStart() && c % 3 == 0; }
  // Torsion on: the spin angles are the last coordinates (IndependentFormulation3).
  int spinStart() const { return p_ - f_.spinDofs(); }
  bool isSpin(int c) const { return c >= spinStart(); }
  VecX& theta() { return theta_; }
  const VecX& forces(const VecX& theta) {
    y_.head(p_) = theta;
    f_.derivative(0.0, y_, charts_, top_, dy_, *data_);
    return data_->rhs;
  }
  MatX mass(const VecX& theta) {
    forces(theta);
    return data_->M;
  }
  // Pinned end: Φ = ∂E_n/∂θ (3 x p) and the gap E_n - p_b [m].
  MatX endJacobian(const VecX& theta) {
    forces(theta);
    return data_->Phi;
  }
  Vec3 endGap(const VecX& theta, const SpatialModel& model) {
    return kinematics(theta, model).back().end() - model.bottomPoint();
  }
  // The anchor's force λ on the end that balances Q_θ in least squares (Φᵀ λ = -Q_θ; 0 for a free end).
  Vec3 anchorForce(const VecX& theta, const SpatialModel& model) {
    if (model.bottom() != BottomBoundary::kPinned) return Vec3::Zero();
    const VecX Q = forces(theta);
    return data_->Phi.transpose().colPivHouseholderQr().solve(-Q);
  }
  // Q_θ + Φᵀ λ with λ held (a dead load at the end: its geometric stiffness is the constraint's).
  VecX loaded(const VecX& theta, const Vec3& lambda) {
    VecX Q = forces(theta);
    if (lambda.squaredNorm() > 0.0) Q += data_->Phi.transpose() * lambda;
    return Q;
  }
  MatX stiffness(const VecX& theta0, const SpatialModel& model, const Vec3& lambda = Vec3::Zero()) {
    MatX K(p_, p_);
    VecX th = theta0, Qp;
    for (int c = 0; c < p_; ++c) {
      const double h = fd_step_ * (isDelta(c) ? model.line().segmentLength() : 1.0);
      th[c] = theta0[c] + h;
      Qp = loaded(th, lambda);
      th[c] = theta0[c] - h;
      K.col(c) = -(Qp - loaded(th, lambda)) / (2.0 * h);
      th[c] = theta0[c];
    }
    return K;
  }
  // Max |Q_θ + Φᵀ λ| (λ the anchor's force, pinned) relative to the weight (Δ rows, N) and to weight x length
  // (chart rows, N m).
  double residual(const VecX& theta, const SpatialModel& model) {
    const VecX Q = loaded(theta, anchorForce(theta, model));
    double w = 0.0;
    for (int i = 0; i < model.bodies(); ++i) w += model.rfe(i).mass;
    w *= model.gravity().norm();
    double r = 0.0;
    for (int c = 0; c < p_; ++c) r = std::max(r, std::abs(Q[c]) / (isDelta(c) ? w : w * model.line().length()));
    return r;
  }
  Kinematics3 kinematics(const VecX& theta, const SpatialModel& model) {
    y_.head(p_) = theta;
    Kinematics3 kin(model.bodies());
    f_.kinematics(y_, charts_, top_, kin);
    return kin;
  }

 private:
  IndependentFormulation3 f_;
  std::unique_ptr<IndependentData3> data_;
  SphereCharts charts_;
  PointMotion3 top_;
  const int p_;
  const double fd_step_;
  VecX y_, dy_, theta_;
};

}  // namespace

Kinematics3 spatialEquilibrium(const SpatialModel& model, const Kinematics3& guess, int iterations,
                               const SpatialModalOptions& options) {
  RestLine line(model, guess, options.fd_step);
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
  for (int it = 0; it < iterations; ++it) {
    if (converged()) return line.kinematics(theta, model);
    const MatX K = line.stiffness(theta, model);
    if (!pinned) {
      theta += solve(K, VecX(line.forces(theta)));  // Q(θ + δ) ≈ Q - K δ = 0
      continue;
    }
    // Pinned: Q - K δ + Φᵀ ν = 0 (ν: the anchor's force beyond the model's), E_n - p_b + Φ δ = 0.
    const MatX Phi = line.endJacobian(theta);
    MatX A = MatX::Zero(p + 3, p + 3);
    A.topLeftCorner(p, p) = K;
    A.topRightCorner(p, 3) = -Phi.transpose();
    A.bottomLeftCorner(3, p) = Phi;
    VecX b(p + 3);
    b.head(p) = line.forces(theta);
    b.tail(3) = -line.endGap(theta, model);
    theta += solve(A, b).head(p);
  }
  if (converged()) return line.kinematics(theta, model);
  throw std::runtime_error("spatialEquilibrium: Newton did not converge");
}

Kinematics3 spatialEquilibriumHeldEnd(const SpatialModel& model, const Kinematics3& guess, const Vec2& xy, Vec3& force,
                                      int iterations, const SpatialModalOptions& options) {
  if (model.bottom() == BottomBoundary::kPinned)
    throw std::invalid_argument("spatialEquilibriumHeldEnd: a free end only (a pinned one is held in full)");
  RestLine line(model, guess, options.fd_step);
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
      force = P * nu;
      return line.kinematics(theta, model);
    }
    if (it == iterations) break;
    // R(θ, ν) = Q + Φᵀ P ν: K_ν δ - Φᵀ P Δν = R, P ᵀ Φ δ = -gap (K_ν: ν's geometric stiffness in).
    const MatX K = line.stiffness(theta, model, P * nu);
    const MatX G = P.transpose() * line.endJacobian(theta);
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

SpatialModalResult computeSpatialModes(const SpatialModel& model, const Kinematics3& equilibrium,
                                       const SpatialModalOptions& options) {
  if (!(options.fd_step > 0.0)) throw std::invalid_argument("spatial modal fd_step: must be > 0");
  if (model.bottomMoves()) throw std::invalid_argument("spatial modal: a fixed or free bottom only (not a moving one)");
  RestLine line(model, equilibrium, options.fd_step);
  const VecX theta0 = line.theta();
  SpatialModalResult res;
  res.equilibrium = line.kinematics(theta0, model);
  res.equilibrium_residual = line.residual(theta0, model);
  // Pinned: the anchor's force as a dead load at the end (its geometric stiffness is the constraint's), the
  // modes in the null space N of Φ = ∂E_n/∂θ (the end held).
  const bool pinned = model.bottom() == BottomBoundary::kPinned;
  MatX K = line.stiffness(theta0, model, line.anchorForce(theta0, model));
  const double knorm = K.norm();
  res.asymmetry = knorm > 0.0 ? (K - K.transpose()).norm() / knorm : 0.0;
  K = 0.5 * (K + K.transpose()).eval();
  const MatX M = line.mass(theta0);
  MatX N;
  if (pinned) {
    Eigen::ColPivHouseholderQR<MatX> qr(line.endJacobian(theta0).transpose());
    qr.setThreshold(1e-10);
    if (qr.rank() < 3)
      throw std::runtime_error("spatial modal: the pinned end's Jacobian is singular (an inextensible line pinned "
                               "at exactly its length is locked); use axial flexibility");
    const MatX Q = qr.householderQ();
    N = Q.rightCols(line.size() - 3);
  }
  const MatX Kr = pinned ? MatX(N.transpose() * K * N) : K, Mr = pinned ? MatX(N.transpose() * M * N) : M;
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(0.5 * (Kr + Kr.transpose()), 0.5 * (Mr + Mr.transpose()));
  if (es.info() != Eigen::Success) throw std::runtime_error("spatial modal: the generalised eigen-solve failed");
  for (int m = 0; m < int(Kr.rows()); ++m) {
    SpatialMode mode;
    mode.omega2 = es.eigenvalues()[m];
    mode.omega = mode.omega2 > 0.0 ? std::sqrt(mode.omega2) : 0.0;
    mode.theta = pinned ? VecX(N * es.eigenvectors().col(m)) : VecX(es.eigenvectors().col(m));
    const VecX Mt = M * mode.theta;
    for (int c = 0; c < line.size(); ++c) {
      if (line.isDelta(c)) mode.axial_fraction += mode.theta[c] * Mt[c];
      if (line.isSpin(c)) mode.torsion_fraction += mode.theta[c] * Mt[c];
    }
    mode.torsional = mode.torsion_fraction > 0.5;
    mode.axial = mode.axial_fraction > 0.5;
    const double h = options.fd_step / std::max(mode.theta.cwiseAbs().maxCoeff(), 1e-300);
    const Kinematics3 kp = line.kinematics(theta0 + h * mode.theta, model);
    const Kinematics3 km = line.kinematics(theta0 - h * mode.theta, model);
    const int nb = model.bodies();
    mode.displacement.assign(nb + 1, Vec3::Zero());
    double along = 0.0, normal = 0.0;
    for (int i = 0; i <= nb; ++i) {
      const Vec3 p = i < nb ? kp[i].A : kp[nb - 1].end(), q = i < nb ? km[i].A : km[nb - 1].end();
      mode.displacement[i] = (p - q) / (2.0 * h);
      if (i == nb) break;
      // Parts: δx = δA + κ δΔ e + (s0 + κ Δ) δe, split along e and across it (+ the parts' J |δe|²).
      const BodyKinematics3& b = res.equilibrium[i];
      const Vec3 de = (kp[i].e - km[i].e) / (2.0 * h);
      const double dd = (kp[i].delta - km[i].delta) / (2.0 * h);
      const Rfe& r = model.rfe(i);
      for (int k = 0; k < r.num_parts; ++k) {
        const RigidPart& part = r.part[k];
        const Vec3 dx = mode.displacement[i] + part.kappa * dd * b.e + (part.s0 + part.kappa * b.delta) * de;
        const double a = b.e.dot(dx);
        along += part.mass * a * a;
        normal += part.mass * (dx - a * b.e).squaredNorm() + part.inertia * de.squaredNorm();
      }
    }
    mode.along_fraction = along + normal > 0.0 ? along / (along + normal) : 0.0;
    res.modes.push_back(std::move(mode));
  }
  res.stiffness = std::move(K);
  res.mass = M;
  return res;
}

}  // namespace spatial
}  // namespace riser_sim
