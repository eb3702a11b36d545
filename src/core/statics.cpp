#include "riser_sim/statics.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "riser_sim/chain_kinematics.h"
#include "riser_sim/force_term.h"

namespace riser_sim {

namespace {

// Unknowns: per rfe (Δ_i if axial) and φ_i, then the end-force unknowns of the problem.
class StaticResidual {
 public:
  StaticResidual(const Model& m, const StaticsProblem& p, double t) : model_(m), prob_(p), t_(t) {
    axial_ = m.options().axial_flexibility;
    per_ = axial_ ? 2 : 1;
    extra_ = p.kind == StaticsProblem::Kind::kHanging ? 0 : (p.kind == StaticsProblem::Kind::kEndDisplaced ? 1 : 2);
    kin_.resize(m.bodies());
    Q_.setZero(m.dofs());
    weight_ = std::max(m.totalMass() * std::abs(m.gravity()), 1e-9);
  }
  int size() const { return per_ * model_.bodies() + extra_; }

  void toKinematics(const VecX& x, Kinematics& kin) const {
    chainKinematics(model_, prob_.top, Vec2::Zero(), x.data(), nullptr, kin);
  }
  void fromKinematics(const Kinematics& kin, VecX& x) const {
    for (int i = 0; i < model_.bodies(); ++i) {
      if (axial_) x[per_ * i] = kin[i].delta;
      x[per_ * i + per_ - 1] = kin[i].phi;
    }
  }
  Vec2 endForce(const VecX& x) const {
    const int o = per_ * model_.bodies();
    if (extra_ == 1) return Vec2(x[o], 0.0);
    if (extra_ == 2) return Vec2(x[o], x[o + 1]);
    return Vec2::Zero();
  }

  // Scaled residual: generalised forces in independent coordinates / weight (moments / weight·L),
  // geometric end conditions / L.
  void operator()(const VecX& x, VecX& r) {
    toKinematics(x, kin_);
    Q_.setZero();
    addTermForces(model_, nullptr, kin_, t_, Q_);  // no history: the seabed's tangential springs are free
    const int nb = model_.bodies();
    Q_.segment<4>(4 * (nb - 1)) += pointForce(kin_[nb - 1], model_.rfe(nb - 1).length, 1.0, endForce(x));
    Vec2 below = Vec2::Zero();  // net force on the rfes beyond rfe i
    const double L = model_.length();
    for (int i = nb - 1; i >= 0; --i) {
      const BodyKinematics& b = kin_[i];
      const Vec4 q = Q_.segment<4>(4 * i);
      if (axial_) r[per_ * i] = (q[kDelta] + b.e().dot(below)) / weight_;
      r[per_ * i + per_ - 1] = (q[kPhi] + b.len * b.nrm().dot(below)) / (weight_ * L);
      below += q.head<2>();
    }
    const int o = per_ * nb;
    const Vec2 end = kin_[nb - 1].end();
    if (extra_ == 1) r[o] = (end.x() - prob_.top.x() - prob_.end_dx) / L;
    if (extra_ == 2) r.segment<2>(o) = (end - prob_.end_point) / L;
  }

  const Model& model_;
  const StaticsProblem& prob_;
  double t_;
  bool axial_;
  int per_, extra_;
  Kinematics kin_;
  VecX Q_;
  double weight_;
};

// Damped Newton with a forward-difference Jacobian; Levenberg-Marquardt step when Newton stalls.
bool newton(StaticResidual& F, VecX& x, const StaticsProblem& p, int& iters, double& res) {
  const int n = F.size();
  VecX r(n), r1(n), x1(n);
  MatX J(n, n);
  F(x, r);
  res = r.lpNorm<Eigen::Infinity>();
  for (iters = 0; iters < p.max_iterations && res > p.tolerance; ++iters) {
    for (int j = 0; j < n; ++j) {
      const double typical = j < F.per_ * F.model_.bodies() ? 1e-3 : F.weight_;
      const double h = 1e-7 * std::max(std::abs(x[j]), typical);
      x1 = x;
      x1[j] += h;
      F(x1, r1);
      J.col(j) = (r1 - r) / h;
    }
    VecX dx = J.partialPivLu().solve(-r);
    double alpha = 1.0, res1 = INFINITY;
    for (int k = 0; k < 12; ++k, alpha *= 0.5) {
      x1 = x + alpha * dx;
      F(x1, r1);
      res1 = r1.norm();
      if (std::isfinite(res1) && res1 < (1.0 - 1e-4 * alpha) * r.norm()) break;
    }
    if (!(res1 < r.norm())) {  // Levenberg-Marquardt fallback
      const MatX JtJ = J.transpose() * J;
      const VecX g = J.transpose() * r;
      double mu = 1e-6 * JtJ.diagonal().maxCoeff();
      for (int k = 0; k < 20; ++k, mu *= 10.0) {
        MatX A = JtJ;
        A.diagonal() += mu * (JtJ.diagonal().array() + 1e-30).matrix();
        x1 = x - A.ldlt().solve(g);
        F(x1, r1);
        res1 = r1.norm();
        if (std::isfinite(res1) && res1 < r.norm()) break;
      }
      if (!(res1 < r.norm())) return false;
    }
    x = x1;
    r = r1;
    res = r.lpNorm<Eigen::Infinity>();
  }
  return res <= p.tolerance;
}

// Shape of an inextensible catenary for the displaced-end problem, used as Newton's starting point:
// horizontal force H at the end, vertical end load Ve, weight w per length; on a seabed the last part
// lies flat. Returns false when no such shape fits.
bool catenaryGuess(const Model& model, const StaticsProblem& p, Kinematics& kin, double& end_force) {
  const double L = model.length(), X = std::abs(p.end_dx);
  // Net weight per length from the terms themselves (a horizontal line just below the top, at rest).
  Kinematics probe = straightLine(model, p.top - Vec2(0.0, 1e-6), 0.0);
  VecX Q = VecX::Zero(model.dofs());
  double level = -INFINITY;
  for (const auto& term : model.terms())
    if (!std::isfinite(term->seabedLevel())) term->addForces(model, nullptr, probe, 0.0, Q);
  for (const auto& term : model.terms()) level = std::max(level, term->seabedLevel());
  double W = 0.0;
  for (int i = 0; i < model.bodies(); ++i) W -= Q[4 * i + kY];
  const double Ve = model.endMass() * model.gravity();
  const double w = (W - Ve) / L;
  if (!(w > 0.0)) return false;
  const double h = p.top.y() - level + 1e-3;  // height above the seabed (+1 mm into it, so it bears)
  const int m = 4000;
  // Horizontal extent of the shape for H; fills 'lay' (length on the seabed).
  auto extent = [&](double H, double& lay) {
    const double a = H / w;
    lay = 0.0;
    if (std::isfinite(h) && h > 0.0) {
      const double ss = a * std::sqrt(std::pow(h / a + 1.0, 2) - 1.0);
      if (ss < L) {
        lay = L - ss;
        return a * std::asinh(ss / a) + lay;
      }
    }
    double x = 0.0;
    for (int k = 0; k < m; ++k) {
      const double s = (k + 0.5) * L / m;
      x += L / m / std::sqrt(1.0 + std::pow((Ve + w * s) / H, 2));
    }
    return x;
  };
  double lo = 1e-6 * w * L, hi = 1e6 * w * L, lay = 0.0;
  if (extent(lo, lay) > X || extent(hi, lay) < X) return false;
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (extent(mid, lay) < X ? lo : hi) = mid;
  }
  const double H = hi;
  extent(H, lay);
  // Points from the end (σ = 0) up to the top, then shifted so the top is at p.top.
  std::vector<Vec2> pts(m + 1);
  pts[0] = Vec2::Zero();
  for (int k = 0; k < m; ++k) {
    const double s = (k + 0.5) * L / m;
    const double V = s < lay ? 0.0 : (lay > 0.0 ? w * (s - lay) : Ve + w * s);
    const Vec2 dir = Vec2(H, V).normalized();
    pts[k + 1] = pts[k] + L / m * Vec2(-dir.x() * (p.end_dx < 0 ? -1.0 : 1.0), dir.y());
  }
  const Vec2 shift = p.top - pts[m];
  auto at = [&](double sigma) {  // arc length from the top
    const double f = (L - sigma) / L * m;
    const int k = std::min(std::max(static_cast<int>(f), 0), m - 1);
    return Vec2(pts[k] + (f - k) * (pts[k + 1] - pts[k]) + shift);
  };
  end_force = p.end_dx < 0 ? -H : H;
  kin = straightLine(model, p.top, 0.0);
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const Vec2 d = at(r.s_begin + r.length) - at(r.s_begin);
    kin[i].phi = std::atan2(d.y(), d.x());
  }
  return true;
}

}  // namespace

Kinematics straightLine(const Model& model, const Vec2& top, double phi) {
  Kinematics kin(model.bodies());
  Vec2 A = top;
  for (int i = 0; i < model.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = A;
    b.phi = phi;
    b.c = std::cos(phi);
    b.s = std::sin(phi);
    b.len = model.rfe(i).length;
    A = b.end();
  }
  return kin;
}

StaticsResult solveStatics(const Model& model, const StaticsProblem& problem, double t) {
  StaticResidual F(model, problem, t);
  const int nb = model.bodies();
  const double L = model.length();
  VecX x = VecX::Zero(F.size());
  Kinematics guess;
  using Kind = StaticsProblem::Kind;
  if (problem.kind == Kind::kHanging) {
    guess = straightLine(model, problem.top, -M_PI / 2);
  } else if (problem.kind == Kind::kEndDisplaced) {
    const double dx = problem.end_dx;
    if (std::abs(dx) >= L) {
      StaticsResult res;
      res.message = "initial.end_dx: |end_dx| must be < line.length for a displaced initial state";
      return res;
    }
    const double w = (model.endMass() + 0.5 * model.line().mass_per_length * L) * model.gravity();
    double fx = w * dx / std::sqrt(L * L - dx * dx);
    if (!catenaryGuess(model, problem, guess, fx))
      guess = straightLine(model, problem.top, std::atan2(-std::sqrt(L * L - dx * dx), dx));
    x[F.per_ * nb] = fx;
  } else {  // between points: straight chord, or a V of two straight halves when slack
    const Vec2 chord = problem.end_point - problem.top;
    const double c = chord.norm();
    guess = straightLine(model, problem.top, std::atan2(chord.y(), chord.x()));
    if (c < L) {
      // Inextensible catenary through both points: solve end(F) = chord for the end force F.
      const double w = model.line().mass_per_length * model.gravity(), Wm = model.endMass() * model.gravity();
      auto endOf = [&](const Vec2& Fe, double s) {
        const double H = std::max(std::abs(Fe.x()), 1e-9 * w * L);
        const double V0 = Wm - Fe.y() + w * L, Vs = Wm - Fe.y() + w * (L - s);
        return Vec2(Fe.x() / w * (std::asinh(V0 / H) - std::asinh(Vs / H)),
                    -(std::hypot(H, V0) - std::hypot(H, Vs)) / w);
      };
      Vec2 Fe(w * L * chord.x() / L, 0.5 * w * L);
      for (int it = 0; it < 100; ++it) {
        const Vec2 r = endOf(Fe, L) - chord;
        if (r.norm() < 1e-12 * L) break;
        Mat2 J;
        for (int j = 0; j < 2; ++j) {
          Vec2 F1 = Fe;
          const double h = 1e-7 * std::max(std::abs(Fe[j]), w * L);
          F1[j] += h;
          J.col(j) = (endOf(F1, L) - chord - r) / h;
        }
        const Vec2 dF = -J.inverse() * r;
        double a = 1.0;
        while (a > 1e-3 && (endOf(Fe + a * dF, L) - chord).norm() > r.norm()) a *= 0.5;
        Fe += a * dF;
      }
      for (int i = 0; i < nb; ++i) {
        const double sm = model.rfe(i).s_begin + 0.5 * model.rfe(i).length;
        guess[i].phi = std::atan2(-(Wm - Fe.y() + w * (L - sm)), Fe.x());
      }
      x[F.per_ * nb] = Fe.x();
      x[F.per_ * nb + 1] = Fe.y();
    }
  }
  for (int i = 1; i < nb; ++i)  // continuous angles: the bending springs see φ_i - φ_{i-1}
    guess[i].phi -= 2.0 * M_PI * std::round((guess[i].phi - guess[i - 1].phi) / (2.0 * M_PI));
  F.fromKinematics(guess, x);
  StaticsResult res;
  bool ok = newton(F, x, problem, res.iterations, res.residual);
  if (!ok && problem.kind == Kind::kEndDisplaced) {  // continuation in the end offset
    StaticsProblem step = problem;
    StaticResidual Fs(model, step, t);
    VecX xs = VecX::Zero(Fs.size());
    Fs.fromKinematics(straightLine(model, problem.top, -M_PI / 2), xs);
    int it = 0;
    ok = true;
    for (int k = 1; k <= 20 && ok; ++k) {
      step.end_dx = problem.end_dx * k / 20.0;
      ok = newton(Fs, xs, step, it, res.residual);
      res.iterations += it;
    }
    x = xs;
  }
  res.converged = ok;
  res.kin.resize(nb);
  F.toKinematics(x, res.kin);
  res.end_force = F.endForce(x);
  std::ostringstream msg;
  msg << (ok ? "statics converged" : "statics did not converge") << " in " << res.iterations
      << " iterations, residual " << res.residual << " (tolerance " << problem.tolerance << ")";
  res.message = msg.str();
  return res;
}

}  // namespace riser_sim
