#include "riser_sim/recursive_formulation.h"

#include <Eigen/LU>

namespace riser_sim {

RecursiveFormulation::RecursiveFormulation(const Model& model, double stabilization)
    : ChainFormulation(model, stabilization) {
  Node zero;
  zero.Lam = zero.T = zero.Bh = zero.Dinv = zero.G = Mat2::Zero();
  zero.beta = zero.rho = zero.c = Vec2::Zero();
  node_.assign(model.bodies(), zero);
}

template <int K, bool General>
void RecursiveFormulation::backward() {
  using M2K = Eigen::Matrix<double, 2, K>;
  using MKK = Eigen::Matrix<double, K, K>;
  using VK = Eigen::Matrix<double, K, 1>;
  const int nb = model_.bodies();
  const bool pin = pinned();
  Mat2 Lp = Mat2::Zero(), Tp = Mat2::Identity();
  Vec2 bp = Vec2::Zero();
  for (int i = nb - 1; i >= 0; --i) {
    const BodyKinematics& b = kin_[i];
    const Vec2 e = b.e(), nv = b.nrm();
    const double* q = Q_.data() + 4 * i;
    Mat2 P;
    M2K B, G;
    MKK D;
    Vec2 rA;
    VK ru;
    if (General) {
      const Mat4& M = M_[i];
      const double* h = h_.data() + 4 * i;
      P = M.topLeftCorner<2, 2>();
      rA = Vec2(q[0] - h[0], q[1] - h[1]);
      B = M.block<2, K>(0, 4 - K);
      D = M.block<K, K>(4 - K, 4 - K);
      for (int a = 0; a < K; ++a) ru[a] = q[4 - K + a] - h[4 - K + a];
    } else {  // rigid parts only: the closed-form blocks of ChainFormulation::generalMassBlocks
      const Rfe& r = model_.rfe(i);
      const double S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
      const double w2 = b.phi_dot * b.phi_dot, dw = 2.0 * b.delta_dot * b.phi_dot;
      P = r.mass * Mat2::Identity();
      rA = Vec2(q[0], q[1]) - (r.mass_k * dw) * nv + (S * w2) * e;
      B.col(K - 1) = S * nv;
      D(K - 1, K - 1) = r.inertiaAboutA(b.delta);
      ru[K - 1] = q[3] - Sk * dw;
      if (K == 2) {
        B.col(0) = r.mass_k * e;
        D(0, 0) = r.mass_k;
        D(0, K - 1) = D(K - 1, 0) = 0.0;
        ru[0] = q[2] + Sk * w2;
      }
    }
    G.col(K - 1) = b.len * nv;
    if (K == 2) G.col(0) = e;

    Node& nd = node_[i];
    const M2K LG = Lp * G;
    const MKK Dh = D + G.transpose() * LG;
    const M2K Bh = B + LG;
    const Vec2 c = bias_[i];
    const VK rho = ru - G.transpose() * (bp + Lp * c);
    const MKK Dinv = Dh.inverse();
    const M2K Kg = Bh * Dinv;
    nd.Lam = P + Lp - Kg * Bh.transpose();
    nd.beta = Kg * rho + Lp * c + bp - rA;
    if (pin) nd.T = (Mat2::Identity() - Kg * G.transpose()) * Tp;
    nd.Bh.leftCols<K>() = Bh;
    nd.Dinv.topLeftCorner<K, K>() = Dinv;
    nd.G.leftCols<K>() = G;
    nd.rho.head<K>() = rho;
    nd.c = c;
    Lp = nd.Lam;
    bp = nd.beta;
    Tp = nd.T;
  }
}

template <int K>
void RecursiveFormulation::forward(const Vec2& a_top, VecX& dy, int nt) {
  using VK = Eigen::Matrix<double, K, 1>;
  const int nb = model_.bodies();
  Vec2 A = a_top;
  for (int i = 0; i < nb; ++i) {
    const Node& nd = node_[i];
    const VK u = nd.Dinv.topLeftCorner<K, K>() * (nd.rho.head<K>() - nd.Bh.leftCols<K>().transpose() * A);
    reactions_.joint[i] = -(nd.Lam * A + nd.beta);
    dy.segment<K>(nt + K * i) = u;
    A += nd.G.leftCols<K>() * u + nd.c;
  }
}

template <int K>
Vec2 RecursiveFormulation::pinnedTipForce(const Vec2& a_top) {
  using M2K = Eigen::Matrix<double, 2, K>;
  using VK = Eigen::Matrix<double, K, 1>;
  using MK2 = Eigen::Matrix<double, K, 2>;
  const int nb = model_.bodies();
  // End acceleration for the tip force F = f_{n+1}: A''_{n+1} = a0 + S F (S_0 = 0, ∂ρ_i/∂F = -G^T T_{i+1}).
  Vec2 A = a_top;
  Mat2 S = Mat2::Zero();
  for (int i = 0; i < nb; ++i) {
    const Node& nd = node_[i];
    const Mat2 Tn = i + 1 < nb ? node_[i + 1].T : Mat2::Identity();
    const auto Dinv = nd.Dinv.topLeftCorner<K, K>();
    const M2K Bh = nd.Bh.leftCols<K>(), G = nd.G.leftCols<K>();
    const VK u = Dinv * (nd.rho.head<K>() - Bh.transpose() * A);
    const MK2 U = Dinv * (-G.transpose() * Tn - Bh.transpose() * S);
    A += G * u + nd.c;
    S += G * U;
  }
  const BodyKinematics& last = kin_[nb - 1];
  const Vec2 E = last.end() - model_.bottomPoint(), Ed = last.endVelocity();
  const Vec2 target = -2.0 * omega_ * Ed - omega_ * omega_ * E;
  const Vec2 F = S.inverse() * (target - A);
  for (int i = 0; i < nb; ++i) {
    Node& nd = node_[i];
    const Mat2 Tn = i + 1 < nb ? node_[i + 1].T : Mat2::Identity();
    nd.rho.head<K>() -= nd.G.leftCols<K>().transpose() * (Tn * F);
    nd.beta += nd.T * F;
  }
  last_constraint_error_ = E.norm();
  return F;
}

void RecursiveFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) {
  const int nb = model_.bodies(), nt = positionSize();
  updateKinematics(y, top);
  evaluateForces(t);
  if (!rigid_only_) generalMassBlocks(t);
  if (k_ == 2) {
    rigid_only_ ? backward<2, false>() : backward<2, true>();
  } else {
    rigid_only_ ? backward<1, false>() : backward<1, true>();
  }
  Vec2 tip = Vec2::Zero();
  if (pinned()) tip = k_ == 2 ? pinnedTipForce<2>(top.a) : pinnedTipForce<1>(top.a);
  if (k_ == 2)
    forward<2>(top.a, dy, nt);
  else
    forward<1>(top.a, dy, nt);
  reactions_.joint[nb] = -tip;
  reactions_.top = reactions_.joint[0];
  reactions_.bottom = pinned() ? tip : Vec2::Zero();
  dy.head(nt) = y.segment(nt, nt);
}

}  // namespace riser_sim
