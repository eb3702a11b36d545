#include "riser_sim/planar/chain_shifted_solver.h"

#include <Eigen/LU>

namespace riser_sim {

ChainShiftedSolver::ChainShiftedSolver(const Model& model, int dofs_per_rfe)
    : k_(dofs_per_rfe), nb_(model.bodies()), pinned_(model.bottom() == BottomBoundary::kPinned) {
  Stage zero;
  zero.E.setZero();
  zero.Rinv.setZero();
  zero.RN.setZero();
  zero.T.setZero();
  zero.Um.setZero();
  zero.gu.setZero();
  zero.x.setZero();
  st_.assign(nb_, zero);
  q_.assign(nb_, Vec4::Zero());
  q2_.assign(nb_, Vec4::Zero());
  f_.assign(nb_, Vec4::Zero());
}

void ChainShiftedSolver::setLinearization(const Kinematics& kin, const AlignedVector<Mat4>& M, const StiffnessBlocks& S,
                                          const AlignedVector<Vec2>& joint) {
  kin_ = &kin;
  M_ = &M;
  S_ = &S;
  joint_ = &joint;
}

Vec4 ChainShiftedSolver::lift(const Vec2& u) const {
  return k_ == 2 ? Vec4(0.0, 0.0, u[0], u[1]) : Vec4(0.0, 0.0, 0.0, u[0]);
}

Vec2 ChainShiftedSolver::drop(const Vec4& q) const { return k_ == 2 ? Vec2(q[2], q[3]) : Vec2(q[3], 0.0); }

Mat2 ChainShiftedSolver::geometric(int i) const {
  const BodyKinematics& b = (*kin_)[i];
  const Vec2& lam = (*joint_)[i + 1];
  const double ln = lam.dot(b.nrm()), le = lam.dot(b.e());
  Mat2 G = Mat2::Zero();
  if (k_ == 2) {
    G(0, 1) = G(1, 0) = -ln;
    G(1, 1) = b.len * le;
  } else {
    G(0, 0) = b.len * le;
  }
  return G;
}

namespace {
// Rows 0-1 of E: A_{i+1} = A_i + e_i Δ'_i + (l_i+Δ_i) n_i φ'_i, linearised (q_i -> A_{i+1}).
Mat4 endMap(const BodyKinematics& b) {
  Mat4 E = Mat4::Zero();
  E(0, 0) = E(1, 1) = 1.0;
  E(0, kDelta) = b.c;
  E(1, kDelta) = b.s;
  E(0, kPhi) = -b.len * b.s;
  E(1, kPhi) = b.len * b.c;
  return E;
}
}  // namespace

void ChainShiftedSolver::factor(double c) {
  const Kinematics& kin = *kin_;
  const double c2 = c * c;
  Mat4 S = Mat4::Zero();
  Mat42 T = Mat42::Zero();
  if (pinned_) T = endMap(kin[nb_ - 1]).topRows<2>().transpose();
  for (int i = nb_ - 1; i >= 0; --i) {
    Stage& st = st_[i];
    st.T = T;  // T_{i+1}
    const Mat4 H = (*M_)[i] + c * S_->C_diag[i] + c2 * S_->K_diag[i] + S;
    const Mat4 Hs = i > 0 ? Mat4(c * S_->C_sub[i] + c2 * S_->K_sub[i]) : Mat4::Zero();
    st.E = i > 0 ? endMap(kin[i - 1]) : Mat4::Zero();
    const Mat4 HE = H * st.E + Hs;  // columns: z; rows: q
    Mat2 R = c2 * geometric(i);
    Mat24 N;
    if (k_ == 2) {
      R += H.block<2, 2>(2, 2);
      N = HE.bottomRows<2>();
      st.Rinv = R.inverse();
    } else {
      R(0, 0) += H(3, 3);
      N.setZero();
      N.row(0) = HE.row(3);
      st.Rinv.setZero();
      st.Rinv(0, 0) = 1.0 / R(0, 0);
    }
    st.RN = st.Rinv * N;
    const Mat4 Z = st.E.transpose() * H * st.E + st.E.transpose() * Hs + Hs.transpose() * st.E;
    const Mat4 Sn = Z - N.transpose() * st.RN;
    S = 0.5 * (Sn + Sn.transpose());
    if (pinned_) {
      Mat24 FT;  // F^T T_{i+1} (k x 2)
      FT.setZero();
      if (k_ == 2)
        FT.leftCols<2>() = T.bottomRows<2>();
      else
        FT.row(0).head<2>() = T.row(3);
      T = st.E.transpose() * T - st.RN.transpose() * Mat2(FT.leftCols<2>());
    }
  }
  if (!pinned_) return;
  // Forward sensitivities of u_i and z_{i+1} = q_i to μ.
  Mat42 Zm = Mat42::Zero();
  for (int i = 0; i < nb_; ++i) {
    Stage& st = st_[i];
    Mat2 FT;
    FT.setZero();
    if (k_ == 2)
      FT = st.T.bottomRows<2>();
    else
      FT.row(0) = st.T.row(3);
    const Mat42 EZ = st.E * Zm;
    const Mat2 Um = -(Mat2(st.RN * Zm) + st.Rinv * FT);
    st.Um = Um;
    Zm = EZ;
    if (k_ == 2)
      Zm.bottomRows<2>() += Um;
    else
      Zm.row(3) += Um.row(0);
  }
  Sm_inv_ = (endMap(kin[nb_ - 1]).topRows<2>() * Zm).inverse();
}

void ChainShiftedSolver::solve(const VecX& r, VecX& x, const Vec2& end) {
  Vec4 s = Vec4::Zero();
  for (int i = nb_ - 1; i >= 0; --i) {
    Stage& st = st_[i];
    Vec2 g = drop(s);
    if (k_ == 2)
      g -= Vec2(r[2 * i], r[2 * i + 1]);
    else
      g[0] -= r[i];
    st.gu = st.Rinv * g;
    s = st.E.transpose() * s - st.RN.transpose() * g;  // N^T R^-1 g
  }
  Vec4 z = Vec4::Zero();
  for (int i = 0; i < nb_; ++i) {
    Stage& st = st_[i];
    st.x = -(st.RN * z + st.gu);
    z = st.E * z + lift(st.x);
  }
  Vec2 mu = Vec2::Zero();
  if (pinned_) mu = Sm_inv_ * (end - endMap((*kin_)[nb_ - 1]).topRows<2>() * z);
  for (int i = 0; i < nb_; ++i) {
    Stage& st = st_[i];
    const Vec2 u = pinned_ ? Vec2(st.x + st.Um * mu) : st.x;
    x[k_ * i + k_ - 1] = u[k_ - 1];
    if (k_ == 2) x[2 * i] = u[0];
  }
}

Vec2 ChainShiftedSolver::endMotion(const Eigen::Ref<const VecX>& w) const {
  Vec2 A = Vec2::Zero();
  for (int i = 0; i < nb_; ++i) {
    const BodyKinematics& b = (*kin_)[i];
    const double d = k_ == 2 ? w[2 * i] : 0.0, p = w[k_ * i + k_ - 1];
    A += d * b.e() + (b.len * p) * b.nrm();
  }
  return A;
}

void ChainShiftedSolver::toAbsolute(const Eigen::Ref<const VecX>& w) {
  Vec2 A = Vec2::Zero();
  for (int i = 0; i < nb_; ++i) {
    const BodyKinematics& b = (*kin_)[i];
    const double d = k_ == 2 ? w[2 * i] : 0.0, p = w[k_ * i + k_ - 1];
    q_[i] = Vec4(A.x(), A.y(), d, p);
    A += d * b.e() + (b.len * p) * b.nrm();
  }
}

void ChainShiftedSolver::massMinusStiffness(const Eigen::Ref<const VecX>& a, const Eigen::Ref<const VecX>& b, double c,
                                            VecX& y) {
  toAbsolute(b);
  q2_.swap(q_);   // q2_ = J b
  toAbsolute(a);  // q_ = J a
  const StiffnessBlocks& S = *S_;
  for (int i = 0; i < nb_; ++i) {
    Vec4 kb = S.K_diag[i] * q2_[i];
    if (i > 0) kb.noalias() += S.K_sub[i] * q2_[i - 1];
    if (i + 1 < nb_) kb.noalias() += S.K_sub[i + 1].transpose() * q2_[i + 1];
    f_[i] = (*M_)[i] * q_[i] - c * kb;
  }
  Vec2 below = Vec2::Zero();  // Σ_{k>i} f_k^A
  for (int i = nb_ - 1; i >= 0; --i) {
    const BodyKinematics& bk = (*kin_)[i];
    const Vec2 u = drop(f_[i]);
    const Vec2 bu(k_ == 2 ? b[2 * i] : b[i], k_ == 2 ? b[2 * i + 1] : 0.0);
    const Vec2 gb = geometric(i) * bu;
    const double yphi = (k_ == 2 ? u[1] : u[0]) + bk.len * bk.nrm().dot(below) - c * (k_ == 2 ? gb[1] : gb[0]);
    if (k_ == 2) {
      y[2 * i] = u[0] + bk.e().dot(below) - c * gb[0];
      y[2 * i + 1] = yphi;
    } else {
      y[i] = yphi;
    }
    below += f_[i].head<2>();
  }
}

}  // namespace riser_sim
