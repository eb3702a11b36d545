#include "riser_sim/planar/independent_formulation.h"

#include <Eigen/LU>

#include "riser_sim/planar/chain_kinematics.h"
#include "riser_sim/line/rfe_inertia.h"

namespace riser_sim {

// ldlt is sized in the initialiser list: assigning a sized temporary copied its uninitialised m_info
// (Eigen 3.4's LDLT(Index); UBSan: invalid enum load).
IndependentData::IndependentData(const IndependentFormulation& owner, const Model& model)
    : ChainData(owner, model), ldlt(owner.positionSize()) {
  const int nt = owner.positionSize(), nb = model.bodies();
  Mii.setZero(nt, nt);
  W.setZero(2, nt);
  C.setZero(2, nt);
  X.setZero(nt, 2);
  f.setZero(4 * nb);
  rhs.setZero(nt);
  qdd.setZero(nt);
  abias.assign(nb + 1, Vec2::Zero());
  A_dd.assign(nb + 1, Vec2::Zero());
}

IndependentFormulation::IndependentFormulation(const Model& model, double stabilization)
    : ChainFormulation(model, stabilization) {}

std::unique_ptr<FormulationData> IndependentFormulation::makeData() const {
  return std::make_unique<IndependentData>(*this, model_);
}

const MatX& IndependentFormulation::massMatrix(const FormulationData& data) const {
  checkOwner(data);
  return static_cast<const IndependentData&>(data).Mii;
}

void IndependentFormulation::derivative(double t, const VecX& y, const PointMotion& top, VecX& dy,
                                        FormulationData& data) const {
  IndependentData& d = dataOf<IndependentData>(data);
  const int nb = model_.bodies(), nt = positionSize(), K = k_;
  beginEvaluation(t, y, top, d);
  rfeMassBlocks(model_, d.kin, t, d.M, d.h);

  // Generalised forces of rfe i with θ'' = 0: f_i = Q_i - h_i - M_i q''_bias,i, where A''_bias,i collects
  // the top's acceleration and the velocity products of the rfes above (J' θ' + J_0 a_top); rhs = Jᵀ f.
  Vec2 a = top.a;
  for (int i = 0; i < nb; ++i) {
    d.abias[i] = a;
    d.f.segment<4>(4 * i) = d.Q.segment<4>(4 * i) - d.h.segment<4>(4 * i) - d.M[i].leftCols<2>() * a;
    a += d.bias[i];
  }
  d.abias[nb] = a;
  projectToChain(model_, d.kin, d.f.data(), d.rhs.data());

  // Column c of rfe j moves A_i (i > j) by g_c (e_j for Δ_j, (l_j+Δ_j) n_j for φ_j) and its own slot by 1.
  // With P̄_j = Σ_{i>j} P_i (P, B, D the A-A, A-slot, slot-slot parts of M_i):
  //   M_II(c, d) = g_c·(P̄_k g_d + B_k[:, d]) for c of rfe j < k ∋ d,  g_c·P̄_j g_d + D_j(c, d) on the diagonal.
  Mat2 Pbar = Mat2::Zero();
  for (int j = nb - 1; j >= 0; --j) {
    const BodyKinematics& b = d.kin[j];
    for (int ca = 0; ca < K; ++ca) {
      const int c = K * j + ca, slot = K == 2 ? 2 + ca : 3;
      const Vec2 g = slot == 2 ? b.e() : Vec2(b.len * b.nrm());
      d.C.col(c) = g;
      d.W.col(c) = Pbar * g + d.M[j].block<2, 1>(0, slot);
      for (int cb = 0; cb <= ca; ++cb) {
        const int slot_b = K == 2 ? 2 + cb : 3;
        const Vec2 gb = slot_b == 2 ? b.e() : Vec2(b.len * b.nrm());
        d.Mii(c, K * j + cb) = gb.dot(Pbar * g) + d.M[j](slot, slot_b);
      }
    }
    Pbar += d.M[j].topLeftCorner<2, 2>();
  }
  // Below the diagonal blocks: rows d of rfes k > j, column c of rfe j.
  for (int c = 0; c < nt; ++c) {
    const int start = K * (c / K + 1);
    if (start < nt) d.Mii.col(c).tail(nt - start).noalias() = d.W.rightCols(nt - start).transpose() * d.C.col(c);
  }

  d.ldlt.compute(d.Mii);
  d.qdd = d.ldlt.solve(d.rhs);

  Vec2 tip = Vec2::Zero();  // force on the anchor by rfe n (f_{n+1})
  d.constraint_error = 0.0;
  if (pinned()) {
    // End acceleration E'' = abias[n+1] + C θ''; anchor force F on rfe n adds C^T F to the rhs.
    // C (θ''_0 + X F) = target, X = M_II^-1 C^T; tip force f_{n+1} = -F.
    const Vec2 E = d.kin[nb - 1].end() - model_.bottomPoint(), Ed = d.kin[nb - 1].endVelocity();
    const Vec2 target = -2.0 * omega_ * Ed - omega_ * omega_ * E;
    d.X = d.ldlt.solve(d.C.transpose());
    const Mat2 S = d.C * d.X;
    const Vec2 F = S.inverse() * (target - d.abias[nb] - d.C * d.qdd);
    d.qdd.noalias() += d.X * F;
    tip = -F;
    d.constraint_error = E.norm();
  }

  // Absolute accelerations of A_i for the reactions.
  Vec2 A = top.a;
  for (int i = 0; i < nb; ++i) {
    d.A_dd[i] = A;
    A += d.bias[i];
    for (int a = 0; a < K; ++a) A += d.qdd[K * i + a] * d.C.col(K * i + a);
  }
  d.A_dd[nb] = A;
  reactionsFromAccelerations(d.A_dd, d.qdd, tip, d);

  dy.head(nt) = y.segment(nt, nt);
  dy.segment(nt, nt) = d.qdd;
}

}  // namespace riser_sim
