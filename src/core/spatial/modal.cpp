#include "riser_sim/spatial/modal.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rest_line.h"

namespace riser_sim {
namespace spatial {

using detail::RestLine;

ModalResult3 computeModes3(const Model3& model, const Kinematics3& equilibrium, const ModalOptions3& options,
                           const AlignedVector<Vec3>* material_axes) {
  if (!(options.fd_step > 0.0)) throw std::invalid_argument("spatial modal fd_step: must be > 0");
  if (model.bottomMoves()) throw std::invalid_argument("spatial modal: a fixed or free bottom only (not a moving one)");
  RestLine line(model, equilibrium, options.fd_step, material_axes, options.hang_off);
  const VecX theta0 = line.theta();
  ModalResult3 res;
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
      throw std::runtime_error(
          "spatial modal: the pinned end's Jacobian is singular (an inextensible line pinned "
          "at exactly its length is locked); use axial flexibility");
    const MatX Q = qr.householderQ();
    N = Q.rightCols(line.size() - 3);
  }
  const MatX Kr = pinned ? MatX(N.transpose() * K * N) : K, Mr = pinned ? MatX(N.transpose() * M * N) : M;
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(0.5 * (Kr + Kr.transpose()), 0.5 * (Mr + Mr.transpose()));
  if (es.info() != Eigen::Success) throw std::runtime_error("spatial modal: the generalised eigen-solve failed");
  for (int m = 0; m < int(Kr.rows()); ++m) {
    Mode3 mode;
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
