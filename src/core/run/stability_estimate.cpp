#include "riser_sim/run/stability_estimate.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <sstream>

#include "riser_sim/scene/choices.h"

namespace riser_sim {

std::vector<Complex> ritzValues(int dim, int krylov, const std::function<void(const VecX&, VecX&)>& jv) {
  const int m = std::min(krylov, dim);
  MatX V = MatX::Zero(dim, m + 1), H = MatX::Zero(m + 1, m);
  // A start vector with every entry and a deterministic spread, so that no mode is missed.
  for (int i = 0; i < dim; ++i) V(i, 0) = ((i / 2) % 2 ? -1.0 : 1.0) * (1.0 + 0.37 * std::sin(1.7 * i));
  V.col(0).normalize();
  VecX w(dim), x(dim);
  int k = 0;
  for (; k < m; ++k) {
    x = V.col(k);
    jv(x, w);
    if (!w.allFinite()) break;
    for (int pass = 0; pass < 2; ++pass)  // modified Gram-Schmidt, twice for orthogonality
      for (int j = 0; j <= k; ++j) {
        const double h = V.col(j).dot(w);
        H(j, k) += h;
        w -= h * V.col(j);
      }
    H(k + 1, k) = w.norm();
    if (H(k + 1, k) <= 1e-14 * H.topLeftCorner(k + 1, k + 1).norm()) {  // invariant subspace: exact
      ++k;
      break;
    }
    V.col(k + 1) = w / H(k + 1, k);
  }
  std::vector<Complex> out;
  if (k == 0) return out;
  Eigen::EigenSolver<MatX> es(H.topLeftCorner(k, k), false);
  for (int i = 0; i < k; ++i) out.push_back(es.eigenvalues()[i]);
  return out;
}

double stabilityRadius(const std::function<Complex(Complex)>& R, double theta) {
  const Complex dir = std::polar(1.0, theta);
  // Walk out until |R| > 1, then bisect; the regions of the explicit schemes here lie within |z| < 10.
  constexpr double kStep = 0.01, kMax = 10.0;
  double lo = 0.0, r = kStep;
  for (; r <= kMax; r += kStep) {
    if (std::abs(R(r * dir)) > 1.0 + 1e-12) break;
    lo = r;
  }
  if (r > kMax) return kMax;
  double hi = r;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::abs(R(mid * dir)) > 1.0 + 1e-12 ? hi : lo) = mid;
  }
  return lo;
}

double largestStableStep(const std::vector<Complex>& eigenvalues, const std::function<Complex(Complex)>& R) {
  double h = std::numeric_limits<double>::infinity();
  for (const Complex& l : eigenvalues) {
    const double mag = std::abs(l);
    if (!(mag > 0.0) || !std::isfinite(mag)) continue;
    double theta = std::arg(l);                                                   // (-π, π]
    if (std::abs(theta) < M_PI / 2) theta = theta >= 0.0 ? M_PI / 2 : -M_PI / 2;  // growing: imaginary axis
    h = std::min(h, stabilityRadius(R, theta) / mag);
  }
  return h;
}

LinearisedSpectrum linearisedSpectrum(int p, const VecX& y, const std::function<void(const VecX&, VecX&)>& f,
                                      const std::function<Complex(Complex)>& R) {
  LinearisedSpectrum out;
  VecX dy0(y.size()), yp(y.size()), dyp(y.size());
  f(y, dy0);
  const double qscale = 1.0 + y.head(p).cwiseAbs().maxCoeff();
  const double vscale = 1.0 + y.segment(p, p).cwiseAbs().maxCoeff();
  // The largest |Ritz value| of A = ∂v'/∂q (v held): Arnoldi's outermost Ritz values converge much faster
  // than a power iteration on the clustered top modes of a long line (1 % low at 80 iterations on a
  // 20-rfe inextensible line, test_spatial_stability).
  const double eps_q = 1e-7 * qscale;
  const auto av = [&](const VecX& z, VecX& w) {
    yp = y;
    yp.head(p) += eps_q * z;
    f(yp, dyp);
    w = (dyp.segment(p, p) - dy0.segment(p, p)) / eps_q;
  };
  constexpr int kKrylov = 60;  // as the planar estimate: the outermost Ritz values settle well before
  double lambda = 0.0;
  for (const Complex& l : ritzValues(p, kKrylov, av))
    if (std::isfinite(std::abs(l))) lambda = std::max(lambda, std::abs(l));
  out.omega_max = std::sqrt(lambda);
  // Damping: the Ritz values of the whole first-order Jacobian, each against R in its direction.
  const int m = 2 * p;
  const auto jv = [&](const VecX& z, VecX& w) {
    const double eps = 1e-7 * std::max(qscale, vscale);
    yp = y;
    yp.head(m) += eps * z;
    f(yp, dyp);
    w = (dyp.head(m) - dy0.head(m)) / eps;
  };
  out.damped_step = largestStableStep(ritzValues(m, kKrylov, jv), R);
  return out;
}

std::string safeStepAdvice(double stable_step) {
  std::ostringstream advice;
  advice << "a safe solver.dt is " << 0.8 * stable_step << " s, or use solver.integrator "
         << name(IntegratorKind::kGeneralizedAlpha) << " / " << name(IntegratorKind::kMidpoint) << " (implicit) or "
         << name(IntegratorKind::kDopri5) << " (adaptive)";
  return advice.str();
}

std::string stepAboveLimitMessage(const std::string& scheme, double dt, double stable_step, double omega_max) {
  if (!(dt > stable_step)) return "";
  std::ostringstream why;
  why << "solver.dt " << dt << " s is above " << scheme << "'s stability limit ~" << stable_step
      << " s (highest frequency " << omega_max << " rad/s, damping included): " << safeStepAdvice(stable_step);
  return why.str();
}

std::string divergenceStabilityNote(const std::string& scheme, double dt, double stable_step, double omega_max) {
  std::ostringstream why;
  if (dt > 0.9 * stable_step)
    why << "; it is at or above " << scheme << "'s stability limit h ~ " << stable_step << " s (highest frequency "
        << omega_max << " rad/s): " << safeStepAdvice(stable_step);
  else
    why << " (" << scheme << "'s stability limit estimated at the initial state, h ~ " << stable_step
        << " s, is not exceeded: the line's highest frequency can grow with its tension during the run (a "
           "swing, a snap), or the input jumps; try solver.dt "
        << 0.5 * dt << " s, or solver.integrator dopri5 (adaptive) or midpoint (implicit))";
  return why.str();
}

}  // namespace riser_sim
