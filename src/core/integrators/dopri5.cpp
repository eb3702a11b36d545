#include "riser_sim/integrators/dopri5.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace riser_sim {

namespace {
// Dormand-Prince 5(4) tableau.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// Error coefficients: b - b̂ (5th minus embedded 4th order).
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                 e7 = -1.0 / 40;
// PI controller (Hairer II.4, Gustafsson): h_new = h * safety * err^-alpha * err_old^beta.
constexpr double kBeta = 0.04, kAlpha = 0.2 - 0.75 * kBeta, kSafety = 0.9, kFacMin = 0.2, kFacMax = 10.0;
// Substeps in one call (one solver.dt): a stiff line at a tight tolerance takes tens to hundreds; 1e5 means
// solver.dt is far beyond the dynamics (e.g. 100 s on a steel line) and the call would block its caller (the
// node's loop) for seconds to minutes.
constexpr long kMaxSubstepsPerCall = 100000;
}  // namespace

void Dopri5::reset(const StateLayout& layout) {
  const int n = layout.size;
  for (VecX* v : {&k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &tmp_, &y1_, &err_, &y_last_}) v->setZero(n);
  controlled_ = std::min(n, 2 * layout.positions);
  h_ = 0.0;
  err_old_ = 1e-4;
  fsal_valid_ = false;
  failure_.clear();
  stats_ = Stats();
}

double Dopri5::errorNorm(const VecX& y0, const VecX& y1) const {
  const double tol = options_.tolerance;
  double s = 0.0;
  for (int i = 0; i < controlled_; ++i) {
    const double sc = tol + tol * std::max(std::abs(y0[i]), std::abs(y1[i]));
    const double r = err_[i] / sc;
    s += r * r;
  }
  return std::sqrt(s / controlled_);
}

// Hairer's starting step (II.4): from |y|, |f| and a trial Euler step. The norms are taken without the
// tolerance factor (sc = 1 + |y|, then / tol): with tol = 1e-300 the scaled norms would overflow to
// inf / inf = NaN; this way h stays finite and tiny, and step() reports the underflow with numbers.
double Dopri5::initialStep(OdeSystem& sys, double t, const VecX& y, double h_max) {
  const double tol = options_.tolerance;
  double d0 = 0.0, d1 = 0.0;
  for (int i = 0; i < controlled_; ++i) {
    const double sc = 1.0 + std::abs(y[i]);
    d0 += (y[i] / sc) * (y[i] / sc);
    d1 += (k1_[i] / sc) * (k1_[i] / sc);
  }
  d0 = std::sqrt(d0 / controlled_);  // |y| / tol in Hairer's terms: d0 / tol
  d1 = std::sqrt(d1 / controlled_);
  double h0 = (d0 < 1e-5 * tol || d1 < 1e-5 * tol) ? 1e-6 : 0.01 * d0 / d1;
  if (!(h0 > 0.0)) h0 = 1e-6;  // d1 not finite: the first substep shrinks from here
  h0 = std::min(h0, h_max);
  tmp_ = y + h0 * k1_;
  sys.rhs(t + h0, tmp_, k2_);
  ++stats_.rhs;
  double d2 = 0.0;
  for (int i = 0; i < controlled_; ++i) {
    const double sc = 1.0 + std::abs(y[i]);
    const double r = (k2_[i] - k1_[i]) / sc;
    d2 += r * r;
  }
  d2 = std::sqrt(d2 / controlled_) / h0;
  const double dmax = std::max(d1, d2);  // / tol in Hairer's terms
  double h1 = dmax <= 1e-15 * tol ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 * tol / dmax, 0.2);
  if (!(h1 > 0.0)) h1 = h0;  // dmax not finite
  return std::min({100.0 * h0, h1, h_max});
}

bool Dopri5::step(OdeSystem& sys, double t, VecX& y, double H) {
  const double t_end = t + H;
  // FSAL: k1 is f(t, y) from the last accepted substep if nothing changed since.
  if (!(fsal_valid_ && t == t_last_ && y == y_last_)) {
    sys.rhs(t, y, k1_);
    ++stats_.rhs;
    fsal_valid_ = true;
  }
  if (!(h_ > 0.0)) h_ = initialStep(sys, t, y, H);
  bool last_rejected = false;
  long substeps = 0;
  while (t < t_end) {
    double h = h_;
    const double left = t_end - t;
    bool final = false;
    if (h >= left * (1.0 - 1e-12)) {
      h = left;
      final = true;
    } else if (h > 0.5 * left) {  // avoid a sliver: split what is left in two
      h = 0.5 * left;
    }
    if (++substeps > kMaxSubstepsPerCall) {
      char buf[200];
      std::snprintf(buf, sizeof(buf),
                    "dopri5: more than %ld substeps (h = %.3g s) in one solver.dt = %g s at t = %.9g s",
                    kMaxSubstepsPerCall, h, H, t);
      failure_ = buf;
      return false;
    }
    if (!(h > 1e-14 * std::max(1.0, std::abs(t))) || !std::isfinite(h)) {
      char buf[240];
      if (std::isfinite(h))
        std::snprintf(buf, sizeof(buf),
                      "dopri5: step size underflow (h = %.3g s, below 1e-14 max(1, |t|)) at t = %.9g s: "
                      "solver.tolerance = %g cannot be met; loosen solver.tolerance",
                      h, t, options_.tolerance);
      else
        std::snprintf(buf, sizeof(buf),
                      "dopri5: the step size controller produced a non-finite step at t = %.9g s "
                      "(solver.tolerance = %g); loosen solver.tolerance",
                      t, options_.tolerance);
      failure_ = buf;  // y keeps the last accepted substep: finite; the caller stops on failure()
      return false;
    }
    tmp_ = y + h * a21 * k1_;
    sys.rhs(t + c2 * h, tmp_, k2_);
    tmp_ = y + h * (a31 * k1_ + a32 * k2_);
    sys.rhs(t + c3 * h, tmp_, k3_);
    tmp_ = y + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    sys.rhs(t + c4 * h, tmp_, k4_);
    tmp_ = y + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    sys.rhs(t + c5 * h, tmp_, k5_);
    tmp_ = y + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    sys.rhs(t + h, tmp_, k6_);
    y1_ = y + h * (b1 * k1_ + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_);
    const double t_new = final ? t_end : t + h;
    sys.rhs(t_new, y1_, k7_);
    stats_.rhs += 6;
    err_ = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
    double err = errorNorm(y, y1_);
    if (!std::isfinite(err)) err = 1e10;  // a stage blew up: shrink hard
    if (err <= 1.0) {
      // Accept; PI controller for the next step.
      double fac = kSafety * std::pow(std::max(err, 1e-10), -kAlpha) * std::pow(err_old_, kBeta);
      fac = std::clamp(fac, kFacMin, last_rejected ? 1.0 : kFacMax);
      err_old_ = std::max(err, 1e-4);
      y.swap(y1_);
      k1_.swap(k7_);  // FSAL
      t = t_new;
      ++stats_.substeps;
      // Keep the controller's step, not the one clipped to the output grid.
      if (!final || h >= h_)
        h_ = h * fac;
      else
        h_ = std::max(h_, h * fac);
      last_rejected = false;
    } else {
      const double fac = std::max(kFacMin, kSafety * std::pow(err, -kAlpha));
      h_ = h * fac;
      ++stats_.rejected;
      last_rejected = true;
    }
  }
  // The last stage was f(t_end, y) (FSAL): reused by the next step when it starts from (t_end, y).
  y_last_ = y;
  t_last_ = t_end;
  return true;
}

}  // namespace riser_sim
