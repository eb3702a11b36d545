#include "riser_sim/spatial/modal.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
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
  bool isDelta(int c) const { return f_.coordinatesPerBody() == 3 && c % 3 == 0; }
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
  MatX stiffness(const VecX& theta0, const SpatialModel& model) {
    MatX K(p_, p_);
    VecX th = theta0, Qp;
    for (int c = 0; c < p_; ++c) {
      const double h = fd_step_ * (isDelta(c) ? model.line().segmentLength() : 1.0);
      th[c] = theta0[c] + h;
      Qp = forces(th);
      th[c] = theta0[c] - h;
      K.col(c) = -(Qp - forces(th)) / (2.0 * h);
      th[c] = theta0[c];
    }
    return K;
  }
  // Max |Q_θ| relative to the weight (Δ rows, N) and to weight x length (chart rows, N m).
  double residual(const VecX& theta, const SpatialModel& model) {
    const VecX& Q = forces(theta);
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
  if (model.bottom() == BottomBoundary::kPinned) throw std::invalid_argument("spatialEquilibrium: free bottom only");
  RestLine line(model, guess, options.fd_step);
  VecX theta = line.theta();
  for (int it = 0; it < iterations; ++it) {
    if (line.residual(theta, model) < 1e-12) return line.kinematics(theta, model);
    const MatX K = line.stiffness(theta, model);
    theta += K.partialPivLu().solve(VecX(line.forces(theta)));  // Q(θ + δ) ≈ Q - K δ = 0
  }
  if (line.residual(theta, model) < 1e-12) return line.kinematics(theta, model);
  throw std::runtime_error("spatialEquilibrium: Newton did not converge");
}

SpatialModalResult computeSpatialModes(const SpatialModel& model, const Kinematics3& equilibrium,
                                       const SpatialModalOptions& options) {
  if (!(options.fd_step > 0.0)) throw std::invalid_argument("spatial modal fd_step: must be > 0");
  if (model.bottom() == BottomBoundary::kPinned) throw std::invalid_argument("spatial modal: free bottom only");
  if (model.hasTorsion()) throw std::invalid_argument("spatial modal: no torsion yet");
  RestLine line(model, equilibrium, options.fd_step);
  const VecX theta0 = line.theta();
  SpatialModalResult res;
  res.equilibrium = line.kinematics(theta0, model);
  res.equilibrium_residual = line.residual(theta0, model);
  MatX K = line.stiffness(theta0, model);
  const double knorm = K.norm();
  res.asymmetry = knorm > 0.0 ? (K - K.transpose()).norm() / knorm : 0.0;
  K = 0.5 * (K + K.transpose()).eval();
  const MatX M = line.mass(theta0);
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(K, M);
  if (es.info() != Eigen::Success) throw std::runtime_error("spatial modal: the generalised eigen-solve failed");
  for (int m = 0; m < line.size(); ++m) {
    SpatialMode mode;
    mode.omega2 = es.eigenvalues()[m];
    mode.omega = mode.omega2 > 0.0 ? std::sqrt(mode.omega2) : 0.0;
    mode.theta = es.eigenvectors().col(m);
    const VecX Mt = M * mode.theta;
    for (int c = 0; c < line.size(); ++c)
      if (line.isDelta(c)) mode.axial_fraction += mode.theta[c] * Mt[c];
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
