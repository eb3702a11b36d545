#include "riser_sim/integrators/implicit_integrators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace riser_sim {

namespace {
// Forward-difference step for column j: sqrt(machine epsilon) relative, with a floor of 1e-8 units.
constexpr double kFdRel = 1.49e-8, kFdFloor = 1e-8;
// Newton: |Δz_i| <= tol (1 + |z_i|) on q and v, or that bound on the error the contraction rate predicts
// after the increment (η/(1-η) max |Δz_i|/(1 + |z_i|)); tol = IntegratorOptions::newton_tolerance, by
// default 1e-11: tight enough that long runs do not drift (round-off of 100 m positions is ~1e-14 m).
constexpr int kNewtonMaxIter = 12;
// The rate test trusts contraction rates below this only (a larger one is not yet linear convergence).
constexpr double kNewtonMaxRate = 0.5;
}  // namespace

void ImplicitIntegrator::reset(const StateLayout& layout) {
  const int n = layout.size;
  n_ = n;
  p_ = layout.positions;
  if (p_ <= 0 || 2 * p_ > n)
    throw std::invalid_argument("implicit integrator: the state must be [q; v; rest] with q not empty");
  m_ = 2 * p_;
  structured_ = options_.jacobian == JacobianKind::kStructured;
  if (!structured_ && options_.jacobian != JacobianKind::kDense)
    throw std::invalid_argument("implicit integrator: jacobian must be structured or dense");
  const int pd = structured_ ? 0 : p_;  // dense workspaces only when used
  Aq_.setZero(pd, pd);
  Av_.setZero(pd, pd);
  S_.setZero(pd, pd);
  lu_ = Eigen::PartialPivLU<MatX>(pd);
  for (VecX* v : {&f0_, &fp_, &yp_, &y_end_}) v->setZero(n);
  bu_.setZero(p_);
  u_.setZero(p_);
  jac_valid_ = f0_valid_ = false;
  c_ = -1.0;
  failure_.clear();
  stats_ = Stats();
}

void ImplicitIntegrator::jacobian(OdeSystem& sys, double t, const VecX& y, const VecX& f0) {
  if (structured_) {
    sys.linearize(t, y);
    ++stats_.jacobians;
    jac_valid_ = true;
    jac_t_ = t;
    c_ = -1.0;
    return;
  }
  yp_ = y;
  for (int j = 0; j < m_; ++j) {
    const double e = std::max(kFdRel * std::abs(y[j]), kFdFloor);
    yp_[j] = y[j] + e;
    const double ej = yp_[j] - y[j];  // the step actually taken
    sys.rhs(t, yp_, fp_);
    yp_[j] = y[j];
    MatX& A = j < p_ ? Aq_ : Av_;
    A.col(j < p_ ? j : j - p_) = (fp_.segment(p_, p_) - f0.segment(p_, p_)) / ej;
  }
  stats_.rhs += m_;
  ++stats_.jacobians;
  jac_valid_ = true;
  jac_t_ = t;
  c_ = -1.0;  // refactor
}

void ImplicitIntegrator::factor(OdeSystem& sys, double c) {
  if (structured_) {
    sys.factorShifted(c);
    c_ = c;
    ++stats_.factorizations;
    return;
  }
  S_.noalias() = -c * Av_;
  S_.noalias() -= (c * c) * Aq_;
  S_.diagonal().array() += 1.0;
  lu_.compute(S_);
  c_ = c;
  ++stats_.factorizations;
}

void ImplicitIntegrator::solve(OdeSystem& sys, const VecX& b, VecX& x) {
  if (structured_) {
    sys.solveShifted(b, x);
    return;
  }
  bu_ = b.segment(p_, p_);
  bu_.noalias() += c_ * (Aq_ * b.head(p_));
  u_ = lu_.solve(bu_);
  x.head(p_) = b.head(p_) + c_ * u_;
  x.segment(p_, p_) = u_;
}

void ImplicitIntegrator::startValue(OdeSystem& sys, double t, const VecX& y) {
  if (structured_ && !sys.hasShiftedSolve())
    throw std::logic_error("implicit integrator: structured solves requested from a system without them");
  if (f0_valid_ && t == t_end_ && y == y_end_) return;
  sys.rhs(t, y, f0_);
  ++stats_.rhs;
  f0_valid_ = true;
}

void ImplicitIntegrator::fail(const char* what, double t, VecX& y) {
  char buf[200];
  std::snprintf(buf, sizeof(buf), "%s: %s at t = %.9g s", name().c_str(), what, t);
  failure_ = buf;
  (void)y;  // y keeps the last good state: outputs stay finite, the caller stops on failure()
}

// ---------------------------------------------------------------------------------------------

void OneStageImplicit::reset(const StateLayout& layout) {
  const double tol = options_.newton_tolerance;
  if (!(tol > 0.0 && tol <= kMaxNewtonTolerance)) {
    char got[32];
    std::snprintf(got, sizeof(got), "%g", tol);
    throw std::invalid_argument(name() + ": solver.newton_tolerance must be in (0, 1e-3], got " + got);
  }
  ImplicitIntegrator::reset(layout);
  const int n = layout.size;
  for (VecX* v : {&z_, &fz_, &g_, &dz_, &d_[0], &d_[1], &d_[2], &y_save_, &f_save_}) v->setZero(n);
  equal_steps_ = 0;
}

// The predictor's weights: with increments d_k = y_{1-k} - y_{-k}, a d1 + b d2 + c d3 = θ (y1 - y0) when
// the increments are linear in k (d_k = d0 - kδ: a + b + c = θ, a + 2b + 3c = 0) and when y_k = r^k
// (d_k = (r - 1) r^-k: a r² + b r + c = θ r³). Determinant (1 - r)², nonzero for r <= 0. Midpoint: (½, ½, -½);
// r = 0: (2θ, -θ, 0), the quadratic extrapolation.
OneStageImplicit::OneStageImplicit(const IntegratorOptions& options, double theta, double kappa, double stiff_root)
    : ImplicitIntegrator(options), theta_(theta), kappa_(kappa) {
  const double r = stiff_root;
  if (!(r >= -1.0 && r <= 0.0)) throw std::invalid_argument("implicit integrator: stiff root must be in [-1, 0]");
  Eigen::Matrix3d A;
  A << 1.0, 1.0, 1.0, 1.0, 2.0, 3.0, r * r, r, 1.0;
  weights_ = A.partialPivLu().solve(Eigen::Vector3d(theta, 0.0, theta * r * r * r));
}

// Solves z = base + c f(t + θh, z), c = κh, on the first 2p entries; fz_ = f(t + θh, z) at exit.
bool OneStageImplicit::newton(OdeSystem& sys, double t, const VecX& y0, const VecX& base, double h) {
  const double tz = t + theta_ * h, c = kappa_ * h, tol = options_.newton_tolerance;
  // Predictor (see the class): from the last equal steps' increments when this step follows them, else y0.
  if (equal_steps_ > 0 && t == t_end_ && y0 == y_end_ && h == h_prev_) {
    if (equal_steps_ == 3 && weighted_)
      z_.head(m_) =
          y0.head(m_) + weights_[0] * d_[0].head(m_) + weights_[1] * d_[1].head(m_) + weights_[2] * d_[2].head(m_);
    else
      z_.head(m_) = y0.head(m_) + theta_ * d_[0].head(m_);
    sys.rhs(tz, z_, fz_);
    ++stats_.rhs;
  } else {
    z_ = y0;  // first iterate = one linearly implicit step, stable for the stiff modes
    fz_ = f0_;
  }
  double r_prev = 0.0;
  for (int it = 0; it < kNewtonMaxIter; ++it) {
    g_.head(m_) = base.head(m_) + c * fz_.head(m_) - z_.head(m_);  // -residual
    if (!g_.head(m_).allFinite()) return false;
    solve(sys, g_, dz_);
    z_.head(m_) += dz_.head(m_);
    sys.rhs(tz, z_, fz_);
    ++stats_.rhs;
    ++stats_.newton;
    double r = 0.0;  // scaled size of the increment
    for (int i = 0; i < m_; ++i) r = std::max(r, std::abs(dz_[i]) / (1.0 + std::abs(z_[i])));
    if (!std::isfinite(r)) return false;
    bool done = r <= tol;
    double margin = r / tol;
    // Linear convergence at rate η: the error left after this iterate is about η/(1-η) r (Hairer-Wanner);
    // asked of it with a factor 10 to spare (the dense Jacobian's slower rates misjudge it otherwise).
    if (it > 0) {
      const double eta = r / r_prev;
      if (eta < kNewtonMaxRate) {
        const double left = eta / (1.0 - eta) * r;
        done = done || left <= 0.1 * tol;
        margin = std::min(margin, left / (0.1 * tol));
      }
    }
    if (done) {
      last_newton_.solves = it + 1;
      last_newton_.margin = margin;
      return true;
    }
    r_prev = r;
  }
  return false;
}

// One step of h from (t, y) with f0_ = f(t, y) current; false if Newton fails.
bool OneStageImplicit::single(OdeSystem& sys, double t, VecX& y, double h) {
  const double c = kappa_ * h;
  bool fresh = false;
  if (jacobianStale(t)) {
    jacobian(sys, t, y, f0_);
    fresh = true;
  }
  if (c_ != c) factor(sys, c);
  const VecX& base = stageBase(y, h);
  bool ok = newton(sys, t, y, base, h);
  if (!ok && !fresh) {  // stale Jacobian: refresh once and retry
    jacobian(sys, t, y, f0_);
    factor(sys, c);
    ok = newton(sys, t, y, base, h);
  }
  if (!ok) {
    equal_steps_ = 0;
    return false;
  }
  // Which start was nearer this step's stage, for the next step: the weighted one, or the last increment
  // carried on (the better one on the swing scene: docs/integrators.md).
  if (equal_steps_ == 3 && h == h_prev_) {  // squared 2-norms: one pass, no division
    const double a = weights_[0], b = weights_[1], c = weights_[2];
    double e_lin = 0.0, e_w = 0.0;
    for (int i = 0; i < m_; ++i) {
      const double dz = y[i] - z_[i], lin = dz + theta_ * d_[0][i], w = dz + a * d_[0][i] + b * d_[1][i] + c * d_[2][i];
      e_lin += lin * lin;
      e_w += w * w;
    }
    weighted_ = e_w <= e_lin;
  }
  // The increments move down one place (d_[2] is reused for the new one: no allocation).
  equal_steps_ = (equal_steps_ > 0 && h == h_prev_) ? std::min(equal_steps_ + 1, 3) : 1;
  h_prev_ = h;
  d_[2].swap(d_[1]);
  d_[1].swap(d_[0]);
  d_[0].head(m_) = y.head(m_);
  advance(y, h);
  d_[0].head(m_) = y.head(m_) - d_[0].head(m_);
  ++stats_.substeps;
  // End evaluation: the next step's f0 (and the last stage the simulator's divergence check reads).
  sys.rhs(t + h, y, f0_);
  ++stats_.rhs;
  return true;
}

bool OneStageImplicit::step(OdeSystem& sys, double t, VecX& y, double h) {
  // Structured solves with the predictor at hand use no f(t, y) after a projection (the system linearises
  // at its own evaluations): it is made only for a retry in substeps or a scheme's history. Otherwise
  // f0_ is the last step's end evaluation, or f(t, y) is made (the forces changed).
  bool lazy = structured_ && equal_steps_ > 0 && t == t_end_ && h == h_prev_ && y == y_end_ &&
              (f0_valid_ || f0_projected_) && !historyNeedsF0(t, y);
  if (!lazy) {
    startValue(sys, t, y);
    f_save_ = f0_;
  }
  beginStep(t, y);
  // Newton out of reach (a large h on a stiff, undamped mode): 2, 4, ... kMaxPieces equal substeps.
  y_save_ = y;
  saveHistory();
  bool ok = false;
  for (int pieces = 1; pieces <= kMaxPieces && !ok; pieces *= 2) {
    if (pieces > 1) {
      y = y_save_;
      if (lazy) {  // the substeps start without a predictor: f(t, y) now (kept when still valid)
        startValue(sys, t, y);
        f_save_ = f0_;
        lazy = false;
      }
      f0_ = f_save_;
      restoreHistory();
      ++stats_.rejected;
    }
    const double hp = h / pieces;
    ok = true;
    for (int k = 0; k < pieces && ok; ++k) ok = single(sys, t + k * hp, y, hp);
  }
  if (!ok) {
    y = y_save_;
    restoreHistory();
    f0_valid_ = false;
    fail("Newton did not converge, even on h / 8", t, y);
    return false;
  }
  f0_valid_ = true;
  f0_projected_ = false;
  y_end_ = y;
  t_end_ = t + h;
  return true;
}

// ---------------------------------------------------------------------------------------------

namespace {
double checkedRhoInf(double rho_inf) {
  if (!(rho_inf >= 0.0 && rho_inf <= 1.0))
    throw std::invalid_argument("generalized_alpha: solver.rho_inf must be in [0, 1], got " + std::to_string(rho_inf));
  return rho_inf;
}
double alphaM(double rho) { return (3.0 - rho) / (2.0 * (1.0 + rho)); }
double alphaF(double rho) { return 1.0 / (1.0 + rho); }
double gammaOf(double rho) { return 0.5 + alphaM(rho) - alphaF(rho); }
}  // namespace

GeneralizedAlpha::GeneralizedAlpha(const IntegratorOptions& options)
    : OneStageImplicit(options, alphaF(checkedRhoInf(options.rho_inf)),
                       alphaF(options.rho_inf) * gammaOf(options.rho_inf) / alphaM(options.rho_inf), -options.rho_inf),
      rho_inf_(options.rho_inf),
      alpha_m_(alphaM(options.rho_inf)),
      alpha_f_(alphaF(options.rho_inf)),
      gamma_(gammaOf(options.rho_inf)) {}

void GeneralizedAlpha::reset(const StateLayout& layout) {
  OneStageImplicit::reset(layout);
  const int n = layout.size;
  for (VecX* v : {&ydot_, &ydot_save_, &b_}) v->setZero(n);
  ydot_valid_ = false;
}

// ẏ0 = f(t, y0) at a start, after restart() or when y is not where the last step left it. t may differ
// from the last step's t + h by round-off (a caller counting k h): ẏ is kept then - a reset to f(t, y) at
// every step turns the scheme into another, first-order one (measured on the pendulum: order ~1, and
// |R| → 0.875 instead of 0.5 at ρ∞ = 0.5).
bool GeneralizedAlpha::historyNeedsF0(double t, const VecX& y) const {
  const bool continues = std::abs(t - t_end_) <= 1e-12 * std::max(std::abs(t), std::abs(t_end_));
  return !(ydot_valid_ && continues && y == y_end_);
}

void GeneralizedAlpha::beginStep(double t, const VecX& y) {
  if (!historyNeedsF0(t, y)) return;
  ydot_ = f0_;
  ydot_valid_ = true;
}

// b = y0 + d ẏ0, d = αf h (αm - γ) / αm (0 at ρ∞ = 1: the midpoint rule).
const VecX& GeneralizedAlpha::stageBase(const VecX& y0, double h) {
  const double d = alpha_f_ * h * (alpha_m_ - gamma_) / alpha_m_;
  b_.head(m_) = y0.head(m_) + d * ydot_.head(m_);
  return b_;
}

// ẏ1 = (f(z) - (1 - αm) ẏ0) / αm, y1 = y0 + h ẏ0 + γ h (ẏ1 - ẏ0) = y0 + e ẏ0 + g f(z) with
// e = h (αm - γ) / αm, g = γ h / αm (on q, v: y0 + (z - y0) / αf; on W the same rule, explicitly).
void GeneralizedAlpha::advance(VecX& y, double h) {
  const double e = h * (alpha_m_ - gamma_) / alpha_m_, g = gamma_ * h / alpha_m_;
  y += e * ydot_ + g * fz_;
  ydot_ = (fz_ - (1.0 - alpha_m_) * ydot_) * (1.0 / alpha_m_);
}

// ---------------------------------------------------------------------------------------------

void Rosenbrock2::reset(const StateLayout& layout) {
  ImplicitIntegrator::reset(layout);
  const int n = layout.size;
  for (VecX* v : {&k1_, &k2_, &f2_}) v->setZero(n);
}

bool Rosenbrock2::step(OdeSystem& sys, double t, VecX& y, double h) {
  static const double kGamma = 1.0 + 1.0 / std::sqrt(2.0);
  startValue(sys, t, y);
  if (jacobianStale(t)) jacobian(sys, t, y, f0_);
  if (c_ != kGamma * h) factor(sys, kGamma * h);
  solve(sys, f0_, k1_);
  k1_.tail(n_ - m_) = f0_.tail(n_ - m_);  // explicit entries (W): plain stages
  yp_ = y + h * k1_;
  sys.rhs(t + h, yp_, f2_);
  ++stats_.rhs;
  f2_ -= 2.0 * k1_;
  solve(sys, f2_, k2_);
  k2_.tail(n_ - m_) = f2_.tail(n_ - m_);
  yp_ = y + (1.5 * h) * k1_ + (0.5 * h) * k2_;
  if (!yp_.allFinite()) {
    fail("state not finite", t, y);
    return false;
  }
  y.swap(yp_);
  ++stats_.substeps;
  sys.rhs(t + h, y, f0_);
  ++stats_.rhs;
  f0_valid_ = true;
  y_end_ = y;
  t_end_ = t + h;
  return true;
}

}  // namespace riser_sim
