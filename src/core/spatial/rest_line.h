// The line at rest from the fixed top in IndependentFormulation3's coordinates (internal to the spatial
// statics and modes: statics.cpp, modal.cpp).
#pragma once
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <memory>

#include "riser_sim/spatial/independent_formulation.h"

namespace riser_sim {
namespace spatial {
namespace detail {

// The line at rest from the fixed top in IndependentFormulation3's coordinates: generalised forces Q_θ
// (the right side at θ' = 0, where the velocity and top terms vanish), M_θ and the FD stiffness.
class RestLine {
 public:
  // axes (torsion on, when given and not empty): the guess's material axes 1 per rfe, its spins (else untwisted).
  // hang_off_ref: as Simulator3::reset's.
  RestLine(const Model3& model, const Kinematics3& kin, double fd_step, const AlignedVector<Vec3>* axes = nullptr,
           const HangOff& hang_off = HangOff())
      : f_(model), data_(f_.makeData()), p_(f_.positionSize()), fd_step_(fd_step) {
    top_.p = kin[0].A;
    Kinematics3 rest = kin;
    for (auto& b : rest) b.A_dot.setZero(), b.e_dot.setZero(), b.delta_dot = 0.0;
    y_.setZero(2 * p_);
    dy_.setZero(2 * p_);
    f_.packState(rest, charts_, y_, hang_off);  // charts centred on kin's directors: u = 0
    if (axes && !axes->empty() && model.hasTorsion()) {
      VecX spins(model.bodies());
      spinsFromAxes(rest, charts_.twist, *axes, spins.data());
      f_.setSpins(spins, VecX::Zero(model.bodies()), y_);
    }
    theta_ = y_.head(p_);
  }
  int size() const { return p_; }
  bool isDelta(int c) const { return f_.coordinatesPerBody() == 3 && c < spinStart() && c % 3 == 0; }
  // Torsion on: the spin angles are the last coordinates (IndependentFormulation3).
  int spinStart() const { return p_ - f_.spinDofs(); }
  bool isSpin(int c) const { return c >= spinStart(); }
  VecX& theta() { return theta_; }
  const VecX& forces(const VecX& theta) {  // O(n): no mass matrix
    y_.head(p_) = theta;
    f_.forces(0.0, y_, charts_, top_, *data_);
    return data_->rhs;
  }
  MatX mass(const VecX& theta) {
    y_.head(p_) = theta;
    f_.derivative(0.0, y_, charts_, top_, dy_, *data_);
    return data_->M;
  }
  // Pinned end: Φ = ∂E_n/∂θ (3 x p) and the gap E_n - p_b [m].
  MatX endJacobian(const VecX& theta) {
    forces(theta);
    return data_->Phi;
  }
  Vec3 endGap(const VecX& theta, const Model3& model) {
    return kinematics(theta, model).back().end() - model.bottomPoint();
  }
  // The anchor's force λ on the end that balances Q_θ in least squares (Φᵀ λ = -Q_θ; 0 for a free end).
  Vec3 anchorForce(const VecX& theta, const Model3& model) {
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
  MatX stiffness(const VecX& theta0, const Model3& model, const Vec3& lambda = Vec3::Zero()) {
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
  // C = -∂Q_θ/∂θ' at θ' = 0 (drag, damping; the velocity-product terms vanish there): central differences.
  MatX damping(const VecX& theta0, const Model3& model) {
    MatX C(p_, p_);
    y_.head(p_) = theta0;
    for (int c = 0; c < p_; ++c) {
      const double h = fd_step_ * (isDelta(c) ? model.line().segmentLength() : 1.0);  // [1/s] or [m/s]
      y_[p_ + c] = h;
      f_.forces(0.0, y_, charts_, top_, *data_);
      C.col(c) = -data_->rhs;
      y_[p_ + c] = -h;
      f_.forces(0.0, y_, charts_, top_, *data_);
      C.col(c) = (C.col(c) + data_->rhs) / (2.0 * h);
      y_[p_ + c] = 0.0;
    }
    return C;
  }
  // Max |Q_θ + Φᵀ λ| (λ the anchor's force, pinned) relative to the weight (Δ rows, N) and to weight x length
  // (chart rows, N m).
  double residual(const VecX& theta, const Model3& model) {
    const VecX Q = loaded(theta, anchorForce(theta, model));
    double w = 0.0;
    for (int i = 0; i < model.bodies(); ++i) w += model.rfe(i).mass;
    w *= model.gravity().norm();
    double r = 0.0;
    for (int c = 0; c < p_; ++c) r = std::max(r, std::abs(Q[c]) / (isDelta(c) ? w : w * model.line().length()));
    return r;
  }
  Kinematics3 kinematics(const VecX& theta, const Model3& model) {
    y_.head(p_) = theta;
    Kinematics3 kin(model.bodies());
    f_.kinematics(y_, charts_, top_, kin);
    return kin;
  }
  // Torsion on: material axis 1 of every rfe at θ (world, unit; frame-free: the spins' result); else untouched.
  void materialAxes(const VecX& theta, const Model3& model, AlignedVector<Vec3>* axes) {
    if (!axes || !model.hasTorsion()) return;
    const Kinematics3 kin = kinematics(theta, model);
    axes->resize(model.bodies());
    for (int i = 0; i < model.bodies(); ++i) (*axes)[i] = f_.materialDirector(y_, charts_, kin, i);
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

}  // namespace detail
}  // namespace spatial
}  // namespace riser_sim
