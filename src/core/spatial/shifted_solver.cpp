#include "riser_sim/spatial/shifted_solver.h"

#include <cmath>
#include <utility>

#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

namespace {
// LU with partial pivoting of an N x N block in place (unit lower L below the diagonal, U on and above;
// row k was swapped with piv[k] at step k), on fixed-size column-major loops.
template <int N>
void luFactor(Eigen::Matrix<double, N, N>& A, int* piv) {
  double* a = A.data();
  for (int k = 0; k < N; ++k) {
    int p = k;
    double best = std::abs(a[k + N * k]);
    for (int i = k + 1; i < N; ++i)
      if (std::abs(a[i + N * k]) > best) best = std::abs(a[i + N * k]), p = i;
    piv[k] = p;
    if (p != k)
      for (int j = 0; j < N; ++j) std::swap(a[k + N * j], a[p + N * j]);
    const double inv = 1.0 / a[k + N * k];
    for (int i = k + 1; i < N; ++i) a[i + N * k] *= inv;
    for (int j = k + 1; j < N; ++j) {
      const double akj = a[k + N * j];
      if (akj == 0.0) continue;
      for (int i = k + 1; i < N; ++i) a[i + N * j] -= a[i + N * k] * akj;
    }
  }
}

// b <- A⁻¹ b with luFactor's A, piv.
template <int N>
void luSolve(const Eigen::Matrix<double, N, N>& A, const int* piv, double* b) {
  const double* a = A.data();
  for (int k = 0; k < N; ++k)
    if (piv[k] != k) std::swap(b[k], b[piv[k]]);
  for (int k = 0; k < N; ++k) {
    const double bk = b[k];
    if (bk == 0.0) continue;
    for (int i = k + 1; i < N; ++i) b[i] -= a[i + N * k] * bk;
  }
  for (int k = N - 1; k >= 0; --k) {
    b[k] /= a[k + N * k];
    const double bk = b[k];
    for (int i = 0; i < k; ++i) b[i] -= a[i + N * k] * bk;
  }
}

using Row3 = ShiftedSolver3::Row3;
// G x for x with 7 rows (A, Δ, e).
template <typename X>
Eigen::Matrix<double, 3, X::ColsAtCompileTime> mul(const Row3& G, const Eigen::MatrixBase<X>& x) {
  return G.a * x.template topRows<3>() + G.d * x.row(kDelta3) + G.b * x.template bottomRows<3>();
}
// Gᵀ l for l with 3 rows.
template <typename X>
Eigen::Matrix<double, 7, X::ColsAtCompileTime> mulT(const Row3& G, const Eigen::MatrixBase<X>& l) {
  Eigen::Matrix<double, 7, X::ColsAtCompileTime> out;
  out.template topRows<3>() = G.a * l;
  out.row(kDelta3) = G.d.transpose() * l;
  out.template bottomRows<3>() = G.b * l;
  return out;
}
// x G for x with 3 columns.
template <typename X>
Eigen::Matrix<double, X::RowsAtCompileTime, 7> rmul(const Eigen::MatrixBase<X>& x, const Row3& G) {
  Eigen::Matrix<double, X::RowsAtCompileTime, 7> out;
  out.template leftCols<3>() = G.a * x;
  out.col(kDelta3) = x * G.d;
  out.template rightCols<3>() = G.b * x;
  return out;
}
Row3 combine(const Row3& g, double cp, const Row3& p, double cr, const Row3& r) {
  return Row3{g.a + cp * p.a + cr * r.a, g.b + cp * p.b + cr * r.b, g.d + cp * p.d + cr * r.d};
}

// The first Nr rows of A⁻¹ (A overwritten by its LU): N solves on unit columns.
template <int N, int Nr>
void invRows(Eigen::Matrix<double, N, N>& A, Eigen::Matrix<double, Nr, N>& out) {
  int piv[N];
  luFactor<N>(A, piv);
  for (int j = 0; j < N; ++j) {
    double col[N] = {};
    col[j] = 1.0;
    luSolve<N>(A, piv, col);
    for (int i = 0; i < Nr; ++i) out(i, j) = col[i];
  }
}
}  // namespace

ShiftedSolver3::ShiftedSolver3(const Model3& model, double stabilization)
    : model_(model),
      omega_(stabilization),
      nb_(model.bodies()),
      nq_(model.dofs()),
      nt_(model.hasTorsion() ? model.bodies() : 0),
      vo_(nq_ + nt_),
      axial_(model.options().axial_flexibility) {
  body_.resize(nb_ + 1);  // + the pinned end's block (used when the bottom is pinned)
  for (Body& B : body_) {
    B.Kup.setZero();
    B.gE = B.pE = B.rE = B.Gam = Row3();
    for (Vec7* v : {&B.gu, &B.pu, &B.ru}) v->setZero();
    B.Wt.setZero();
    B.Wd.setZero();
    B.Up.setZero();
    B.Ri.setZero();
    B.RN.setZero();
    B.Xmu.setZero();
    B.x.setZero();
  }
  S_.resize(nb_);
  M_.assign(nb_, Mat7::Zero());
  turn_.assign(nb_, Mat3::Identity());
  b_turned_.setZero(2 * (nq_ + nt_));
  t_diag_.assign(nt_, 1.0);
  t_mul_.assign(nt_, 0.0);
}

template <typename In, typename Out>
void ShiftedSolver3::applyPhi(int i, const In& v, Out& out) const {
  out.template topRows<3>() = (1.0 / s_) * mul(body_[i - 1].Gam, v);
  out.template bottomRows<4>().noalias() = -body_[i].RN * v;
}

// Backward sweep from the free (or pinned) end. The rfes below i act on rfe i's momentum rows as
// -g_iᵀ λ_{i+1} + Up_i x_{i+1} = S_{i+1} x_i + s_{i+1}. Per rfe, with W = H_i + S_{i+1}: the joint row gives
// x_A,i = (ρ_i + Γ_{i-1} x_{i-1}) / s, the Δ-e rows and the unit-length row a 5x5 system R for (u_i, ν_i), so
// x_i = Φ_i x_{i-1} + f_i, and the A rows give λ_i = -(W_A Φ_i + Lo_A) x_{i-1} + ℓ_i, hence S_i. A pinned end's
// λ_n = μ rides along linearly (T: s_{i+1}'s dependence on μ) and is fixed by its row after the forward pass.
void ShiftedSolver3::factor(double c) {
  const double s = (1.0 + omega_ * c) * (1.0 + omega_ * c), c2 = c * c;
  s_ = s;
  for (int i = 0; i < nb_; ++i) {
    Body& B = body_[i];
    B.Gam = combine(B.gE, c, B.pE, c2, B.rE);
    if (i + 1 < nb_) B.Up = (c * S_.C_sub[i + 1]).transpose() + c2 * B.Kup;
  }
  Mat7 Snext = Mat7::Zero();
  Mat73 T = Mat73::Zero();
  if (pinned_) T = -mulT(body_[nb_ - 1].gE, Mat3::Identity());
  Mat5 R;
  Eigen::Matrix<double, 4, 7> N;
  Mat7 Phi, W;
  for (int i = nb_ - 1; i >= 0; --i) {
    Body& B = body_[i];
    W = M_[i] + c * S_.C_diag[i] + c2 * S_.K_diag[i] + Snext;
    B.Wt = W.topRows<3>();
    B.Wd = W.block<4, 3>(kDelta3, kA);
    R.topLeftCorner<4, 4>() = W.block<4, 4>(kDelta3, kDelta3);
    R.block<4, 1>(0, 4) = B.gu.segment<4>(kDelta3);
    R.block<1, 4>(4, 0) = (B.gu + c * B.pu + c2 * B.ru).segment<4>(kDelta3).transpose();
    R(4, 4) = 0.0;
    invRows<5, 4>(R, B.Ri);
    Eigen::Matrix<double, 3, 7> Lam;
    if (i > 0) {
      const Body& P = body_[i - 1];
      N = rmul((1.0 / s) * B.Wd, P.Gam);
      N.block<3, 3>(1, kE) += c * S_.C_sub[i] + c2 * S_.K_sub[i];
      B.RN.noalias() = B.Ri.leftCols<4>() * N;  // N's row 5 (the unit-length row) is zero
      Phi.topRows<3>() = rmul((1.0 / s) * Mat3::Identity(), P.Gam);
      Phi.bottomRows<4>() = -B.RN;
      Lam.noalias() = -(B.Wt * Phi);
      Snext = mulT(P.gE, -Lam);
      Snext.bottomRows<3>().noalias() += P.Up * Phi.bottomRows<3>();
    }
    if (pinned_) {  // f_i's and s_i's dependence on μ
      B.Xmu.topRows<3>().setZero();
      B.Xmu.bottomRows<4>().noalias() = -(B.Ri.leftCols<4>() * T.bottomRows<4>());
      if (i > 0) {
        Eigen::Matrix<double, 3, 3> Tl = -T.topRows<3>();
        Tl.noalias() -= B.Wt * B.Xmu;
        const Body& P = body_[i - 1];
        T = mulT(P.gE, -Tl);
        T.bottomRows<3>().noalias() += P.Up * B.Xmu.bottomRows<3>();
      }
    }
  }
  if (pinned_) {  // ∂x_i/∂μ forward, then the end row's Schur complement
    Mat73 X;
    for (int i = 1; i < nb_; ++i) {
      applyPhi(i, body_[i - 1].Xmu, X);
      body_[i].Xmu += X;
    }
    Sm_inv_ = mul(body_[nb_ - 1].Gam, body_[nb_ - 1].Xmu).inverse();
  }
  if (nt_ > 0) {  // spins: diagonal J_i + s (joints at i), off-diagonal -s between spinning rows i, i+1
    const double s = c * twistDamping(model_) + c * c * twistStiffness(model_);
    const int f0 = firstSpin(model_);  // 0: rfe 0 spins (free top; a top spring adds c c_t + c² k_t)
    for (int i = f0; i < nt_; ++i) {
      const int joints = (i > 0 ? 1 : 0) + (i + 1 < nt_ ? 1 : 0);
      const TorsionProperties& t = model_.torsion();
      t_diag_[i] = polarInertia(model_, i) + s * joints + (i == 0 ? c * t.top_damping + c * c * t.top_stiffness : 0.0);
      if (i > f0) {
        t_mul_[i] = -s / t_diag_[i - 1];
        t_diag_[i] -= t_mul_[i] * -s;
      }
    }
  }
  c_ = c;
  factored_ = true;
}

// M_i v: from the rfe's few numbers (the solve reads 64 B per rfe instead of the 7x7 block), or M_ with
// added mass.
template <typename V>
Vec7 ShiftedSolver3::massTimes(int i, const V& v) const {
  if (added_) return M_[i] * v;
  const Body& B = body_[i];
  const Vec3 vA = v.template head<3>(), ve = v.template tail<3>();
  const double vd = v[kDelta3];
  Vec7 out;
  out.head<3>() = B.m * vA + (B.mk * vd) * B.e + B.S * ve;
  out[kDelta3] = axial_ ? B.mk * B.e.dot(vA) + (B.mk * B.e.squaredNorm()) * vd + B.Sk * B.e.dot(ve) : vd;
  out.tail<3>() = B.S * vA + (B.Sk * vd) * B.e + B.I * ve;
  return out;
}

// Right side of block blk: rows g b_v - c r b_q, then M b_v - c K b_q, then the unit-length row.
void ShiftedSolver3::assembleRhs(int blk, const VecX& b, const VecX& b_rates, Vec11& r) const {
  const double c = c_, w2 = omega_ * omega_;
  auto bq = [&](int i) { return b.segment<7>(kDofPerBody3 * i); };
  auto bv = [&](int i) { return b_rates.segment<7>(vo_ + kDofPerBody3 * i); };
  r.setZero();
  if (blk > 0) {
    const Body& P = body_[blk - 1];
    r.head<3>() = c * mul(P.rE, bq(blk - 1)) - mul(P.gE, bv(blk - 1));
  }
  if (blk == nb_) return;  // the pinned end's block
  const Body& B = body_[blk];
  r.head<3>() += bv(blk).segment<3>(kA) - (c * w2) * bq(blk).segment<3>(kA);
  Vec7 kq = S_.K_diag[blk] * bq(blk);
  if (blk > 0) kq.tail<3>().noalias() += S_.K_sub[blk] * bq(blk - 1).tail<3>();
  if (blk + 1 < nb_) kq.tail<3>().noalias() += B.Kup * bq(blk + 1).tail<3>();
  r.segment<7>(3) = massTimes(blk, bv(blk)) - c * kq;
  r[10] = B.gu.dot(bv(blk)) - c * B.ru.dot(bq(blk));
}

// b's rates (entries vo_.. of b_turned_) in the linearisation's frame: e_i' by R_iᵀ, A_{i+1}' - A_i' by
// R_iᵀ (A_0' and Δ' as they are).
const VecX& ShiftedSolver3::turnedBack(const VecX& b) {
  b_turned_.segment<3>(vo_ + kA) = b.segment<3>(vo_ + kA);
  for (int i = 0; i < nb_; ++i) {
    const int v = vo_ + kDofPerBody3 * i;
    const Mat3& R = turn_[i];
    b_turned_[v + kDelta3] = b[v + kDelta3];
    b_turned_.segment<3>(v + kE).noalias() = R.transpose() * b.segment<3>(v + kE);
    if (i + 1 < nb_)
      b_turned_.segment<3>(v + kDofPerBody3 + kA) =
          b_turned_.segment<3>(v + kA) + R.transpose() * (b.segment<3>(v + kDofPerBody3 + kA) - b.segment<3>(v + kA));
  }
  return b_turned_;
}

void ShiftedSolver3::solve(const VecX& b, VecX& x) {
  const VecX& b_rates = turning_ ? turnedBack(b) : b;  // the director and joint rates' entries read from it
  Vec11 r;
  Vec7 snext = Vec7::Zero(), phi;
  Eigen::Matrix<double, 5, 1> y;
  for (int i = nb_ - 1; i >= 0; --i) {  // backward: f_i (x_i's constant part), s_i
    Body& B = body_[i];
    assembleRhs(i, b, b_rates, r);
    phi = r.segment<7>(3) - snext;
    const Vec3 a = (1.0 / s_) * r.head<3>();
    y.head<4>() = phi.segment<4>(kDelta3);
    y.head<4>().noalias() -= B.Wd * a;
    y[4] = r[10];
    B.x.head<3>() = a;
    B.x.tail<4>().noalias() = B.Ri * y;
    if (i > 0) {
      Vec3 l = phi.head<3>();
      l.noalias() -= B.Wt * B.x;
      const Body& P = body_[i - 1];
      snext = mulT(P.gE, -l);
      snext.tail<3>().noalias() += P.Up * B.x.tail<3>();
    }
  }
  Vec7 px;
  for (int i = 1; i < nb_; ++i) {  // forward: x_i = Φ_i x_{i-1} + f_i
    applyPhi(i, body_[i - 1].x, px);
    body_[i].x += px;
  }
  if (pinned_) {
    assembleRhs(nb_, b, b_rates, r);
    const Vec3 mu = -(Sm_inv_ * (r.head<3>() + mul(body_[nb_ - 1].Gam, body_[nb_ - 1].x)));
    for (int i = 0; i < nb_; ++i) body_[i].x.noalias() += body_[i].Xmu * mu;
  }
  Vec3 y_prev = Vec3::Zero(), x_prev = Vec3::Zero();  // turning: A_{i-1}' in the kept frame, and turned
  for (int i = 0; i < nb_; ++i) {
    Vec7& xv = body_[i].x;
    if (turning_) {  // and forward again
      xv.tail<3>() = turn_[i] * xv.tail<3>();
      const Vec3 y = xv.head<3>();
      if (i > 0) xv.head<3>() = x_prev + turn_[i - 1] * (y - y_prev);
      y_prev = y;
      x_prev = xv.head<3>();
    }
    x.segment<7>(vo_ + kDofPerBody3 * i) = xv;
    x.segment<7>(kDofPerBody3 * i) = b.segment<7>(kDofPerBody3 * i) + c_ * xv;
  }
  if (nt_ == 0) return;
  // Spins: rows firstSpin()..n (a held rfe 0: x = b there), r_i = J_i b_ω,i - c (K_t b_θ)_i, then Thomas.
  const double k = twistStiffness(model_), s = c_ * twistDamping(model_) + c_ * c_ * k;
  const int f0 = firstSpin(model_);
  auto bth = [&](int i) { return i >= f0 && i < nt_ ? b[nq_ + i] : 0.0; };
  x[nq_] = b[nq_];
  x[vo_ + nq_] = b[vo_ + nq_];
  for (int i = f0; i < nt_; ++i) {
    double kq = i > 0 ? k * (bth(i) - bth(i - 1)) : model_.torsion().top_stiffness * bth(0);
    if (i + 1 < nt_) kq += k * (bth(i) - bth(i + 1));
    double r = polarInertia(model_, i) * b[vo_ + nq_ + i] - c_ * kq;
    if (i > f0) r -= t_mul_[i] * x[vo_ + nq_ + i - 1];
    x[vo_ + nq_ + i] = r;
  }
  for (int i = nt_ - 1; i >= f0; --i) {
    double r = x[vo_ + nq_ + i];
    if (i + 1 < nt_) r += s * x[vo_ + nq_ + i + 1];
    x[vo_ + nq_ + i] = r / t_diag_[i];
  }
  for (int i = f0; i < nt_; ++i) x[nq_ + i] = b[nq_ + i] + c_ * x[vo_ + nq_ + i];
}

}  // namespace spatial
}  // namespace riser_sim
