#include "riser_sim/planar/recursive_formulation.h"

#include <Eigen/LU>

#include "riser_sim/line/rfe_inertia.h"

namespace riser_sim {

RecursiveData::RecursiveData(const RecursiveFormulation& owner, const Model& model) : ChainData(owner, model) {
  Node zero;
  zero.Lam = zero.T = zero.Bh = zero.Dinv = zero.G = Mat2::Zero();
  zero.beta = zero.rho = zero.c = Vec2::Zero();
  node.assign(model.bodies(), zero);
  rigid.assign(model.bodies(), RigidNode{});
}

RecursiveFormulation::RecursiveFormulation(const Model& model, double stabilization)
    : ChainFormulation(model, stabilization) {}

std::unique_ptr<FormulationData> RecursiveFormulation::makeData() const {
  return std::make_unique<RecursiveData>(*this, model_);
}

inline void RecursiveFormulation::finishNode(RigidNode& nd, double c, double s, double len, double c0, double c1,
                                             double Di00, double Di01, double Di11, double Bh00, double Bh01,
                                             double Bh10, double Bh11, double rho0, double rho1, double L00, double L01,
                                             double L11, double be, double bn) {
  // u'' = D̂^-1 ρ - W R^T A'' with W = D̂^-1 B̂^T (frame); R = [e n].
  const double W00 = Di00 * Bh00 + Di01 * Bh01, W01 = Di00 * Bh10 + Di01 * Bh11;
  const double W10 = Di01 * Bh00 + Di11 * Bh01, W11 = Di01 * Bh10 + Di11 * Bh11;
  nd.U00 = -(W00 * c - W01 * s), nd.U01 = -(W00 * s + W01 * c);
  nd.U10 = -(W10 * c - W11 * s), nd.U11 = -(W10 * s + W11 * c);
  nd.u0 = Di00 * rho0 + Di01 * rho1, nd.u1 = Di01 * rho0 + Di11 * rho1;
  // Λ = R Λ_frame R^T, β = R β_frame.
  const double cc = c * c, ss = s * s, cs = c * s;
  nd.La = L00 * cc - 2.0 * L01 * cs + L11 * ss;
  nd.Ld = L00 * ss + 2.0 * L01 * cs + L11 * cc;
  nd.Lb = (L00 - L11) * cs + L01 * (cc - ss);
  nd.bx = c * be - s * bn, nd.by = s * be + c * bn;
  // A''_{i+1} = A'' + R (G u'' + c_frame), G = diag(1, l).
  const double V00 = nd.U00, V01 = nd.U01, V10 = len * nd.U10, V11 = len * nd.U11;
  nd.M00 = 1.0 + c * V00 - s * V10, nd.M01 = c * V01 - s * V11;
  nd.M10 = s * V00 + c * V10, nd.M11 = 1.0 + s * V01 + c * V11;
  const double g0 = nd.u0 + c0, g1 = len * nd.u1 + c1;
  nd.mx = c * g0 - s * g1, nd.my = s * g0 + c * g1;
}

// Rigid parts, extensible line. In rfe i's frame (e, n): G = diag(1, l), B = diag(mk, S), D = diag(mk, I),
// so B̂^T = D̂ E - Z with E = diag(1, 1/l), Z = diag(0, δ), δ = I/l - S, and
//   Λ_i = m + Λ' - B̂ D̂^-1 B̂^T = diag(m - mk, m + I/l² - 2S/l - δ² D̂_ee / det D̂):
// the articulated inertia along e is part (1) alone. Hence Λ_i = m1 I + σ n n^T (σ = Λ_nn - m1), and
// with α = φ_i - φ_{i+1}, Λ' in rfe i's frame is p = m1' + σ' sin²α, q = σ' sinα cosα, r = m1' + σ' cos²α,
// D̂_ee = mk + p, det D̂ = N0 + σ' N1 (the σ'² terms cancel): one division per rfe on the serial chain.
void RecursiveFormulation::rigidBackwardAxial(RecursiveData& d) const {
  const int nb = model_.bodies();
  double sig = 0.0, m1n = 0.0, cn = 1.0, sn = 0.0, bx = 0.0, by = 0.0;  // rfe i+1: Λ' = m1n I + sig n'n'^T, β'
  for (int i = nb - 1; i >= 0; --i) {
    const Rfe& r = model_.rfe(i);
    const BodyKinematics& k = d.kin[i];
    RigidNode& nd = d.rigid[i];
    const double c = k.c, s = k.s, len = k.len, w = k.phi_dot, w2 = w * w, dw = 2.0 * k.delta_dot * w;
    const double m = r.mass, mk = r.mass_k, S = r.firstMoment(k.delta), Sk = r.firstMomentK(k.delta);
    const double I = r.inertiaAboutA(k.delta), l2 = len * len;
    const double sa = s * cn - c * sn, ca = c * cn + s * sn, sa2 = sa * sa, ca2 = ca * ca;
    const double p = m1n + sig * sa2, q = sig * sa * ca, rr = m1n + sig * ca2;
    const double D2 = mk + p;
    const double det = (I + l2 * m1n) * (mk + m1n) + sig * (I * sa2 + l2 * (m1n + mk * ca2));
    const double inv = 1.0 / det, delta = I / len - S;
    const double L00 = m - mk, L11 = m + (I / len - 2.0 * S) / len - delta * delta * D2 * inv;
    const double Bh00 = D2, Bh01 = q * len, Bh10 = q, Bh11 = S + rr * len;
    const double Di00 = (I + rr * l2) * inv, Di01 = -q * len * inv, Di11 = D2 * inv;
    // β: t = β' + Λ'c in the frame, c = (-l w², 2Δ'w); ρ = r_u - G^T t; β = K ρ + t - r_A, K = B̂ D̂^-1.
    const double c0 = -len * w2, c1 = dw;
    const double t0 = c * bx + s * by + p * c0 + q * c1, t1 = -s * bx + c * by + q * c0 + rr * c1;
    const double* Q = d.Q.data() + 4 * i;
    const double rAe = c * Q[0] + s * Q[1] + S * w2, rAn = -s * Q[0] + c * Q[1] - mk * dw;
    const double rho0 = Q[2] + Sk * w2 - t0, rho1 = Q[3] - Sk * dw - len * t1;
    const double K00 = Bh00 * Di00 + Bh01 * Di01, K01 = Bh00 * Di01 + Bh01 * Di11;
    const double K10 = Bh10 * Di00 + Bh11 * Di01, K11 = Bh10 * Di01 + Bh11 * Di11;
    const double be = K00 * rho0 + K01 * rho1 + t0 - rAe, bn = K10 * rho0 + K11 * rho1 + t1 - rAn;
    finishNode(nd, c, s, len, c0, c1, Di00, Di01, Di11, Bh00, Bh01, Bh10, Bh11, rho0, rho1, L00, 0.0, L11, be, bn);
    sig = L11 - L00, m1n = L00, cn = c, sn = s;
    bx = nd.bx, by = nd.by;
  }
}

// Rigid parts, inextensible line (φ only): B̂, D̂ reduce to the φ column and entry; Λ is a full 2x2.
void RecursiveFormulation::rigidBackwardLocked(RecursiveData& d) const {
  const int nb = model_.bodies();
  double la = 0.0, lb = 0.0, ld = 0.0, bx = 0.0, by = 0.0;  // Λ' = [[la, lb], [lb, ld]], β' in world axes
  for (int i = nb - 1; i >= 0; --i) {
    const Rfe& r = model_.rfe(i);
    const BodyKinematics& k = d.kin[i];
    RigidNode& nd = d.rigid[i];
    const double c = k.c, s = k.s, len = k.len, w = k.phi_dot, w2 = w * w;
    const double m = r.mass, S = r.firstMoment(0.0), I = r.inertiaAboutA(0.0);
    const double cc = c * c, ss = s * s, cs = c * s;
    const double p = la * cc + 2.0 * lb * cs + ld * ss, rr = la * ss - 2.0 * lb * cs + ld * cc;
    const double q = (ld - la) * cs + lb * (cc - ss);
    const double c0 = -len * w2;
    const double t0 = c * bx + s * by + p * c0, t1 = -s * bx + c * by + q * c0;
    const double* Q = d.Q.data() + 4 * i;
    const double rAe = c * Q[0] + s * Q[1] + S * w2, rAn = -s * Q[0] + c * Q[1];
    const double Bh01 = q * len, Bh11 = S + rr * len, Di11 = 1.0 / (I + rr * len * len);
    const double K01 = Bh01 * Di11, K11 = Bh11 * Di11;
    // Symmetric by construction (no antisymmetric round-off to grow).
    const double L00 = m + p - K01 * Bh01, L11 = m + rr - K11 * Bh11, L01 = q - K01 * Bh11;
    const double rho1 = Q[3] - len * t1;
    const double be = K01 * rho1 + t0 - rAe, bn = K11 * rho1 + t1 - rAn;
    finishNode(nd, c, s, len, c0, 0.0, 0.0, 0.0, Di11, 0.0, Bh01, 0.0, Bh11, 0.0, rho1, L00, L01, L11, be, bn);
    la = nd.La, lb = nd.Lb, ld = nd.Ld, bx = nd.bx, by = nd.by;
  }
}

// Forward from A''_0 = a_top: a short serial chain (A'' only), the rest per rfe.
template <bool Axial>
void RecursiveFormulation::rigidForward(const Vec2& a_top, VecX& dy, int nt, RecursiveData& d) const {
  const int nb = model_.bodies();
  double Ax = a_top.x(), Ay = a_top.y();
  double* out = dy.data() + nt;
  for (int i = 0; i < nb; ++i) {
    const RigidNode& nd = d.rigid[i];
    if (Axial) {
      out[2 * i] = nd.U00 * Ax + nd.U01 * Ay + nd.u0;
      out[2 * i + 1] = nd.U10 * Ax + nd.U11 * Ay + nd.u1;
    } else {
      out[i] = nd.U10 * Ax + nd.U11 * Ay + nd.u1;
    }
    d.reactions.joint[i] = Vec2(-(nd.La * Ax + nd.Lb * Ay + nd.bx), -(nd.Lb * Ax + nd.Ld * Ay + nd.by));
    const double x = nd.M00 * Ax + nd.M01 * Ay + nd.mx;
    Ay = nd.M10 * Ax + nd.M11 * Ay + nd.my;
    Ax = x;
  }
}

template <int K, bool General>
void RecursiveFormulation::backward(RecursiveData& d) const {
  using M2K = Eigen::Matrix<double, 2, K>;
  using MKK = Eigen::Matrix<double, K, K>;
  using VK = Eigen::Matrix<double, K, 1>;
  const int nb = model_.bodies();
  const bool pin = pinned();
  Mat2 Lp = Mat2::Zero(), Tp = Mat2::Identity();
  Vec2 bp = Vec2::Zero();
  for (int i = nb - 1; i >= 0; --i) {
    const BodyKinematics& b = d.kin[i];
    const Vec2 e = b.e(), nv = b.nrm();
    const double* q = d.Q.data() + 4 * i;
    Mat2 P;
    M2K B, G;
    MKK D;
    Vec2 rA;
    VK ru;
    if (General) {
      const Mat4& M = d.M[i];
      const double* h = d.h.data() + 4 * i;
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

    Node& nd = d.node[i];
    const M2K LG = Lp * G;
    const MKK Dh = D + G.transpose() * LG;
    const M2K Bh = B + LG;
    const Vec2 c = d.bias[i];
    const VK rho = ru - G.transpose() * (bp + Lp * c);
    const MKK Dinv = Dh.inverse();
    const M2K Kg = Bh * Dinv;
    // Λ_i is symmetric; computed as written its antisymmetric round-off part grows by |1 - eig(K G^T)|
    // ≈ 2.3 per rfe on a straight hanging line (the symmetric part contracts), so symmetrise.
    const Mat2 L = P + Lp - Kg * Bh.transpose();
    nd.Lam(0, 0) = L(0, 0);
    nd.Lam(1, 1) = L(1, 1);
    nd.Lam(0, 1) = nd.Lam(1, 0) = 0.5 * (L(0, 1) + L(1, 0));
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
void RecursiveFormulation::forward(const Vec2& a_top, VecX& dy, int nt, RecursiveData& d) const {
  using VK = Eigen::Matrix<double, K, 1>;
  const int nb = model_.bodies();
  Vec2 A = a_top;
  for (int i = 0; i < nb; ++i) {
    const Node& nd = d.node[i];
    const VK u = nd.Dinv.topLeftCorner<K, K>() * (nd.rho.head<K>() - nd.Bh.leftCols<K>().transpose() * A);
    d.reactions.joint[i] = -(nd.Lam * A + nd.beta);
    dy.segment<K>(nt + K * i) = u;
    A += nd.G.leftCols<K>() * u + nd.c;
  }
}

template <int K>
Vec2 RecursiveFormulation::pinnedTipForce(const Vec2& a_top, RecursiveData& d) const {
  using M2K = Eigen::Matrix<double, 2, K>;
  using VK = Eigen::Matrix<double, K, 1>;
  using MK2 = Eigen::Matrix<double, K, 2>;
  const int nb = model_.bodies();
  // End acceleration for the tip force F = f_{n+1}: A''_{n+1} = a0 + S F (S_0 = 0, ∂ρ_i/∂F = -G^T T_{i+1}).
  Vec2 A = a_top;
  Mat2 S = Mat2::Zero();
  for (int i = 0; i < nb; ++i) {
    const Node& nd = d.node[i];
    const Mat2 Tn = i + 1 < nb ? d.node[i + 1].T : Mat2::Identity();
    const auto Dinv = nd.Dinv.topLeftCorner<K, K>();
    const M2K Bh = nd.Bh.leftCols<K>(), G = nd.G.leftCols<K>();
    const VK u = Dinv * (nd.rho.head<K>() - Bh.transpose() * A);
    const MK2 U = Dinv * (-G.transpose() * Tn - Bh.transpose() * S);
    A += G * u + nd.c;
    S += G * U;
  }
  const BodyKinematics& last = d.kin[nb - 1];
  const Vec2 E = last.end() - model_.bottomPoint(), Ed = last.endVelocity();
  const Vec2 target = -2.0 * omega_ * Ed - omega_ * omega_ * E;
  const Vec2 F = S.inverse() * (target - A);
  for (int i = 0; i < nb; ++i) {
    Node& nd = d.node[i];
    const Mat2 Tn = i + 1 < nb ? d.node[i + 1].T : Mat2::Identity();
    nd.rho.head<K>() -= nd.G.leftCols<K>().transpose() * (Tn * F);
    nd.beta += nd.T * F;
  }
  d.constraint_error = E.norm();
  return F;
}

void RecursiveFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy,
                                      FormulationData& data) const {
  RecursiveData& d = dataOf<RecursiveData>(data);
  const int nb = model_.bodies(), nt = positionSize();
  beginEvaluation(t, y, top, d);
  if (rigid_only_ && !pinned()) {
    if (k_ == 2) {
      rigidBackwardAxial(d);
      rigidForward<true>(top.a, dy, nt, d);
    } else {
      rigidBackwardLocked(d);
      rigidForward<false>(top.a, dy, nt, d);
    }
    d.reactions.joint[nb].setZero();
    d.reactions.top = d.reactions.joint[0];
    d.reactions.bottom.setZero();
    dy.head(nt) = y.segment(nt, nt);
    return;
  }
  if (!rigid_only_) rfeMassBlocks(model_, d.kin, t, d.M, d.h);
  if (k_ == 2) {
    rigid_only_ ? backward<2, false>(d) : backward<2, true>(d);
  } else {
    rigid_only_ ? backward<1, false>(d) : backward<1, true>(d);
  }
  Vec2 tip = Vec2::Zero();
  if (pinned()) tip = k_ == 2 ? pinnedTipForce<2>(top.a, d) : pinnedTipForce<1>(top.a, d);
  if (k_ == 2)
    forward<2>(top.a, dy, nt, d);
  else
    forward<1>(top.a, dy, nt, d);
  d.reactions.joint[nb] = -tip;
  d.reactions.top = d.reactions.joint[0];
  d.reactions.bottom = pinned() ? tip : Vec2::Zero();
  dy.head(nt) = y.segment(nt, nt);
}

}  // namespace riser_sim
