// linearStability(): the eigenvalues of the linearised first-order system (linear_stability.h).
#include "riser_sim/run/linear_stability.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace riser_sim {

namespace {

bool positiveDefinite(const MatX& A) { return Eigen::LLT<MatX>(A).info() == Eigen::Success; }

}  // namespace

std::string LinearStability::describe() const {
  if (stable) return "";
  std::ostringstream o;
  o.precision(4);
  o << "the equilibrium is unstable: ";
  if (!first_order) {
    o << "its stiffness (scaled to a unit diagonal, on the motions the end conditions allow) has the eigenvalue "
      << -growth << " below -" << bound << ": a static divergence (a balanced state, not a resting one, e.g. a "
      << "compressed, folded or upturned line)";
  } else if (frequency == 0.0) {
    o << unstable << " mode(s) of the linearisation with drag grow, the fastest as e^(" << growth
      << " t) [1/s] without oscillating (bound " << bound << "): a static divergence under the steady loads (e.g. "
      << "the line standing above its hang-off, or pushed over by the current)";
  } else {
    o << unstable << " mode(s) of the linearisation with drag grow, the fastest as e^(" << growth << " t) [1/s] at "
      << frequency << " rad/s (bound " << bound << "): a flutter the drag's damping does not suppress";
  }
  if (reduced) o << " (first-order modes from the " << kReducedModes << " lowest undamped modes)";
  return o.str();
}

LinearStability linearStability(const MatX& K_in, const MatX& C_in, const MatX& M_in, const MatX& N, double noise) {
  LinearStability res;
  MatX K = N.size() > 0 ? MatX(N.transpose() * K_in * N) : K_in;
  MatX M = N.size() > 0 ? MatX(N.transpose() * M_in * N) : M_in;
  MatX C = C_in.size() == 0 ? MatX::Zero(K.rows(), K.cols()) : N.size() > 0 ? MatX(N.transpose() * C_in * N) : C_in;
  const int p = static_cast<int>(K.rows());
  res.size = p;
  if (p == 0) return res;
  M = 0.5 * (M + M.transpose()).eval();
  // Jacobi scale d_i = 1/√|K_ii|: the finite-difference noise of entry (i, j) is ~ noise √|K_ii K_jj|.
  VecX d(p);
  for (int i = 0; i < p; ++i) d[i] = std::abs(K(i, i)) > 1e-300 ? 1.0 / std::sqrt(std::abs(K(i, i))) : 1.0;
  // The antisymmetric part below 100x that noise is noise (a conservative K is symmetric at an equilibrium):
  // dropped, so only a physical asymmetry (drag's follower load) reaches the first-order test.
  bool asymmetric = false;
  for (int j = 0; j < p; ++j)
    for (int i = 0; i < j; ++i) {
      const double a = 0.5 * (K(i, j) - K(j, i)), s = 0.5 * (K(i, j) + K(j, i));
      if (std::abs(a) * d[i] * d[j] <= 100.0 * noise) {
        K(i, j) = K(j, i) = s;
      } else {
        asymmetric = true;
      }
    }
  const MatX S = 0.5 * (K + K.transpose());
  MatX Sj = d.asDiagonal() * S * d.asDiagonal();
  // Neutral directions (a free spin, a rigid slide) at the noise floor pass.
  const double floor = 1e-9 + noise;
  Sj.diagonal().array() += floor;
  const bool s_definite = positiveDefinite(Sj);
  Sj.diagonal().array() -= floor;
  const MatX Cs = 0.5 * (C + C.transpose());
  const double cscale = Cs.diagonal().cwiseAbs().maxCoeff();
  const bool c_semidefinite = !(cscale > 0.0) || positiveDefinite(MatX(Cs + MatX::Identity(p, p) * (1e-9 * cscale)));
  if (!asymmetric && c_semidefinite) {
    // Symmetric K, C ≥ 0: stable iff K > 0 (the energy ½θ'ᵀMθ' + ½θᵀKθ does not grow).
    if (!s_definite) {
      Eigen::SelfAdjointEigenSolver<MatX> es(Sj, Eigen::EigenvaluesOnly);
      res.stable = false;
      res.growth = -es.eigenvalues()[0];
      res.bound = floor;
      for (int i = 0; i < p; ++i) res.unstable += es.eigenvalues()[i] < -floor ? 1 : 0;
    }
    return res;
  }
  res.first_order = true;
  // Mass-normalised: x = Lᵀ θ, M = L Lᵀ; K̃ = L⁻¹ K L⁻ᵀ, C̃ likewise.
  Eigen::LLT<MatX> llt(M);
  auto normalise = [&](MatX A) {
    llt.matrixL().solveInPlace(A);
    A.transposeInPlace();
    llt.matrixL().solveInPlace(A);
    return MatX(A.transpose());
  };
  MatX Kt = normalise(K), Ct = normalise(C);
  if (p > kDenseStabilityLimit) {
    // The lowest undamped modes of (K_sym, M): the drag's flutter and divergence live among the slow modes.
    Eigen::SelfAdjointEigenSolver<MatX> es(0.5 * (Kt + Kt.transpose()));
    const MatX V = es.eigenvectors().leftCols(kReducedModes);
    Kt = (V.transpose() * Kt * V).eval();
    Ct = (V.transpose() * Ct * V).eval();
    res.reduced = true;
  }
  const int q = static_cast<int>(Kt.rows());
  // ω_ref ≥ the largest frequency (Gershgorin): z = [ω_ref x, x'] keeps the system's norm ~ ω_ref.
  double w2 = 0.0;
  for (int i = 0; i < q; ++i) w2 = std::max(w2, Kt.row(i).cwiseAbs().sum());
  const double w = std::sqrt(std::max(w2, 1e-300));
  MatX A = MatX::Zero(2 * q, 2 * q);
  A.topRightCorner(q, q).diagonal().setConstant(w);
  A.bottomLeftCorner(q, q) = -Kt / w;
  A.bottomRightCorner(q, q) = -Ct;
  Eigen::EigenSolver<MatX> es(A, false);
  // Bound: the eigen-solve's round-off and K's noise (~1e-9 of its entries, 1e-8 ω_ref with margin), plus the
  // noise of a neutral direction's ω² (~ noise ω_ref² gives Re λ ~ √noise ω_ref) only where K_sym is not definite:
  // with K_sym > 0 no real λ ≥ 0 exists (λ²θᵀMθ + λθᵀCθ + θᵀKθ > 0). A flutter slower than a damping ratio of
  // -1e-5 (doubling in > 1e4 periods) counts as neutral: at rest in still water the drag's linear damping is 0
  // (the quadratic law's slope), while the drag itself removes energy at any finite amplitude.
  res.bound = 1e-8 * w + (s_definite ? 0.0 : std::sqrt(floor) * w);
  const double base = res.bound;
  double margin = -INFINITY;  // the worst eigenvalue's Re λ - its bound
  for (int i = 0; i < 2 * q; ++i) {
    const std::complex<double> l = es.eigenvalues()[i];
    const double bound = std::max(base, 1e-5 * std::abs(l.imag()));
    if (l.real() > bound) ++res.unstable;
    if (l.real() - bound > margin)
      margin = l.real() - bound, res.growth = l.real(), res.bound = bound, res.frequency = std::abs(l.imag());
  }
  if (res.frequency < 1e-9 * w) res.frequency = 0.0;
  res.stable = res.unstable == 0;
  return res;
}

}  // namespace riser_sim
