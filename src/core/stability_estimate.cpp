#include "riser_sim/stability_estimate.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

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
    double theta = std::arg(l);  // (-π, π]
    if (std::abs(theta) < M_PI / 2) theta = theta >= 0.0 ? M_PI / 2 : -M_PI / 2;  // growing: imaginary axis
    h = std::min(h, stabilityRadius(R, theta) / mag);
  }
  return h;
}

}  // namespace riser_sim
