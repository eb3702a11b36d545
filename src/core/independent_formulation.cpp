#include "riser_sim/independent_formulation.h"

#include <Eigen/LU>

namespace riser_sim {

// ldlt_ is sized in the initialiser list: assigning a sized temporary copied its uninitialised m_info
// (Eigen 3.4's LDLT(Index); UBSan: invalid enum load).
IndependentFormulation::IndependentFormulation(const Model& model, double stabilization)
    : ChainFormulation(model, stabilization), ldlt_(positionSize()) {
  const int nt = positionSize(), nb = model.bodies();
  Mii_.setZero(nt, nt);
  W_.setZero(2, nt);
  C_.setZero(2, nt);
  X_.setZero(nt, 2);
  rhs_.setZero(nt);
  qdd_.setZero(nt);
  abias_.assign(nb + 1, Vec2::Zero());
  f_.assign(nb, Vec4::Zero());
  A_dd_.assign(nb + 1, Vec2::Zero());
}

void IndependentFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy) {
  const int nb = model_.bodies(), nt = positionSize(), K = k_;
  updateKinematics(y, top);
  evaluateForces(t);
  generalMassBlocks(t);

  // Generalised forces of rfe i with θ'' = 0: f_i = Q_i - h_i - M_i q''_bias,i, where A''_bias,i collects
  // the top's acceleration and the velocity products of the rfes above (J' θ' + J_0 a_top).
  Vec2 a = top.a;
  for (int i = 0; i < nb; ++i) {
    abias_[i] = a;
    f_[i] = Q_.segment<4>(4 * i) - h_.segment<4>(4 * i) - M_[i].leftCols<2>() * a;
    a += bias_[i];
  }
  abias_[nb] = a;

  // Column c of rfe j moves A_i (i > j) by g_c (e_j for Δ_j, (l_j+Δ_j) n_j for φ_j) and its own slot by 1.
  // With P̄_j = Σ_{i>j} P_i (P, B, D the A-A, A-slot, slot-slot parts of M_i):
  //   M_II(c, d) = g_c·(P̄_k g_d + B_k[:, d]) for c of rfe j < k ∋ d,  g_c·P̄_j g_d + D_j(c, d) on the diagonal;
  //   rhs_c = g_c·Σ_{i>j} f_i,A + f_j[c].
  Mat2 Pbar = Mat2::Zero();
  Vec2 Fbar = Vec2::Zero();
  for (int j = nb - 1; j >= 0; --j) {
    const BodyKinematics& b = kin_[j];
    for (int ca = 0; ca < K; ++ca) {
      const int c = K * j + ca, slot = K == 2 ? 2 + ca : 3;
      const Vec2 g = slot == 2 ? b.e() : Vec2(b.len * b.nrm());
      C_.col(c) = g;
      rhs_[c] = g.dot(Fbar) + f_[j][slot];
      W_.col(c) = Pbar * g + M_[j].block<2, 1>(0, slot);
      for (int cb = 0; cb <= ca; ++cb) {
        const int slot_b = K == 2 ? 2 + cb : 3;
        const Vec2 gb = slot_b == 2 ? b.e() : Vec2(b.len * b.nrm());
        Mii_(c, K * j + cb) = gb.dot(Pbar * g) + M_[j](slot, slot_b);
      }
    }
    Pbar += M_[j].topLeftCorner<2, 2>();
    Fbar += f_[j].head<2>();
  }
  // Below the diagonal blocks: rows d of rfes k > j, column c of rfe j.
  for (int c = 0; c < nt; ++c) {
    const int start = K * (c / K + 1);
    if (start < nt) Mii_.col(c).tail(nt - start).noalias() = W_.rightCols(nt - start).transpose() * C_.col(c);
  }

  ldlt_.compute(Mii_);
  qdd_ = ldlt_.solve(rhs_);

  Vec2 tip = Vec2::Zero();  // force on the anchor by rfe n (f_{n+1})
  last_constraint_error_ = 0.0;
  if (pinned()) {
    // End acceleration E'' = abias_[n+1] + C θ''; anchor force F on rfe n adds C^T F to the rhs.
    // C (θ''_0 + X F) = target, X = M_II^-1 C^T; tip force f_{n+1} = -F.
    const Vec2 E = kin_[nb - 1].end() - model_.bottomPoint(), Ed = kin_[nb - 1].endVelocity();
    const Vec2 target = -2.0 * omega_ * Ed - omega_ * omega_ * E;
    X_ = ldlt_.solve(C_.transpose());
    const Mat2 S = C_ * X_;
    const Vec2 F = S.inverse() * (target - abias_[nb] - C_ * qdd_);
    qdd_.noalias() += X_ * F;
    tip = -F;
    last_constraint_error_ = E.norm();
  }

  // Absolute accelerations of A_i for the reactions.
  Vec2 A = top.a;
  for (int i = 0; i < nb; ++i) {
    A_dd_[i] = A;
    A += bias_[i];
    for (int a = 0; a < K; ++a) A += qdd_[K * i + a] * C_.col(K * i + a);
  }
  A_dd_[nb] = A;
  reactionsFromAccelerations(A_dd_, qdd_, tip);

  dy.head(nt) = y.segment(nt, nt);
  dy.segment(nt, nt) = qdd_;
}

}  // namespace riser_sim
