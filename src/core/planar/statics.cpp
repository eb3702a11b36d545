#include "riser_sim/planar/statics.h"

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <sstream>

#include "riser_sim/planar/forces/morison_drag.h"
#include "statics_residual.h"

namespace riser_sim {

using statics_detail::StaticResidual;
using statics_detail::StaticTerms;

namespace {

// The solve's clock, stage and progress report (StaticsProblem::progress, time_limit).
struct Budget {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::string stage = "from the first guess";
  int iterations = 0;
  bool out = false;  // the time limit was reached
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

// Damped Newton with a forward-difference Jacobian; Levenberg-Marquardt step when Newton stalls.
bool newton(StaticResidual& F, VecX& x, const StaticsProblem& p, int& iters, double& res, Budget& b) {
  const int n = F.size();
  VecX r(n), r1(n), x1(n);
  MatX J;
  F(x, r);
  res = r.lpNorm<Eigen::Infinity>();
  if (!std::isfinite(res)) return false;
  // Stagnation: 50 iterations without lowering the best residual by 1 % (contacts switching back and
  // forth); slow but steady progress (a line swept by a strong current) goes on.
  double best = res;
  int best_at = 0;
  for (iters = 0; iters < p.max_iterations && res > p.tolerance; ++iters) {
    ++b.iterations;
    if (p.progress) p.progress(b.stage, b.iterations, res, b.seconds());
    if (b.out || b.seconds() > p.time_limit) {
      b.out = true;
      return false;
    }
    if (res < 0.99 * best) best = res, best_at = iters;
    if (iters - best_at > 50) return false;
    F.jacobian(x, r, J);
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

// Continuous angles: the bending springs see φ_i - φ_{i-1}.
void unwrap(Kinematics& kin) {
  for (size_t i = 1; i < kin.size(); ++i)
    kin[i].phi -= 2.0 * M_PI * std::round((kin[i].phi - kin[i - 1].phi) / (2.0 * M_PI));
}

// Newton's starting point for the problem.
void firstGuess(const Model& model, const StaticsProblem& problem, const StaticTerms& terms, StaticResidual& F,
                VecX& x) {
  using Kind = StaticsProblem::Kind;
  const double L = model.length();
  Kinematics guess;
  Vec2 fe = Vec2::Zero();
  if (problem.kind == Kind::kHanging) {
    if (!statics_detail::hangingOnSeabedGuess(model, problem, terms, guess))
      guess = straightLine(model, problem.top, -M_PI / 2);
  } else if (problem.kind == Kind::kEndDisplaced) {
    const double dx = problem.end_dx;
    const double w = (model.endMass() + 0.5 * model.line().mass_per_length * L) * model.gravity();
    fe.x() = w * dx / std::sqrt(L * L - dx * dx);
    if (!statics_detail::displacedGuess(model, problem, terms, guess, fe.x()))
      guess = straightLine(model, problem.top, std::atan2(-std::sqrt(L * L - dx * dx), dx));
  } else if (!statics_detail::betweenPointsGuess(model, problem, terms, guess, fe)) {
    // Taut (or stretched) chord: straight, the anchor pulling along it.
    const Vec2 chord = problem.end_point - problem.top;
    guess = straightLine(model, problem.top, std::atan2(chord.y(), chord.x()));
    const double stretch = model.line().EA * std::max(chord.norm() / L - 1.0, 0.0);
    fe = chord.normalized() * stretch +
         Vec2(0.0, (model.endMass() + 0.5 * model.line().mass_per_length * L) * model.gravity());
  }
  unwrap(guess);
  F.fromKinematics(guess, x);
  F.setEndForce(fe, x);
}

// The scene keys that set up the problem, for failure messages.
std::string problemKeys(const Model& model, const StaticsProblem& p, const StaticTerms& terms) {
  using Kind = StaticsProblem::Kind;
  std::ostringstream o;
  o << "top at (" << p.top.x() << ", " << p.top.y() << "), line.length " << model.length() << " m";
  if (p.kind == Kind::kBetweenPoints)
    o << ", bottom.position (" << p.end_point.x() << ", " << p.end_point.y() << "), " << (p.end_point - p.top).norm()
      << " m from the top";
  if (p.kind == Kind::kEndDisplaced) o << ", initial.end_dx " << p.end_dx << " m";
  if (std::isfinite(terms.seabedLevel()))
    o << ", seabed.level " << terms.seabedLevel() << " m, seabed.stiffness_normal " << terms.seabedStiffness()
      << " N/m";
  return o.str();
}

}  // namespace

bool relaxationMayReach(const StaticsProblem& problem, const StaticsResult& failed) {
  return !failed.converged && failed.iterations > 0 && problem.kind != StaticsProblem::Kind::kEndDisplaced;
}

StaticsResult solveStaticsFrom(const Model& model, const StaticsProblem& problem, const Kinematics& guess,
                               const Vec2& end_force, double t) {
  StaticTerms terms(model, t);
  StaticResidual F(model, problem, terms, t);
  VecX x = VecX::Zero(F.size());
  Kinematics kin = guess;
  unwrap(kin);
  F.fromKinematics(kin, x);
  F.setEndForce(end_force, x);
  Budget budget;
  StaticsResult res;
  res.converged = newton(F, x, problem, res.iterations, res.residual, budget);
  res.kin.resize(model.bodies());
  F.toKinematics(x, res.kin);
  res.end_force = F.endForce(x);
  std::ostringstream msg;
  if (res.converged) {
    const EquilibriumCheck c = checkEquilibrium(model, problem, res.kin, res.end_force, t);
    res.converged = c.ok;
    if (c.ok)
      msg << "statics converged in " << res.iterations << " iterations from the given state, residual " << res.residual
          << " (tolerance " << problem.tolerance << ")";
    else
      msg << "statics from the given state: its solution (" << res.iterations << " iterations, residual "
          << res.residual << ") fails the check " << c.message;
  } else {
    msg << "statics did not converge from the given state in " << res.iterations << " iterations, residual "
        << res.residual << " (tolerance " << problem.tolerance << ")";
  }
  res.message = msg.str();
  return res;
}

Kinematics staticsFirstGuess(const Model& model, const StaticsProblem& problem, Vec2& end_force, double t) {
  StaticTerms terms(model, t);
  StaticResidual F(model, problem, terms, t);
  VecX x = VecX::Zero(F.size());
  firstGuess(model, problem, terms, F, x);
  Kinematics kin(model.bodies());
  F.toKinematics(x, kin);
  end_force = F.endForce(x);
  return kin;
}

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

namespace {

// One attempt: its solution (valid when converged), its cost and why it failed.
struct Attempt {
  bool converged = false;
  int iterations = 0;
  double residual = INFINITY;
  VecX x;
  std::string failure;  // empty when converged and checked
};

// Newton from the first guess; a displaced end that fails is retried by continuation in end_dx
// (without a seabed: the straight start would hang into it).
Attempt direct(const Model& model, const StaticsProblem& problem, const StaticTerms& terms, double t, Budget& b) {
  Attempt a;
  StaticResidual F(model, problem, terms, t);
  a.x = VecX::Zero(F.size());
  firstGuess(model, problem, terms, F, a.x);
  a.converged = newton(F, a.x, problem, a.iterations, a.residual, b);
  if (!a.converged && problem.kind == StaticsProblem::Kind::kEndDisplaced && !(terms.seabedStiffness() > 0.0)) {
    StaticsProblem step = problem;
    StaticResidual Fs(model, step, terms, t);
    VecX xs = VecX::Zero(Fs.size());
    Fs.fromKinematics(straightLine(model, problem.top, -M_PI / 2), xs);
    bool ok = true;
    for (int k = 1; k <= 20 && ok; ++k) {
      int it = 0;
      step.end_dx = problem.end_dx * k / 20.0;
      ok = newton(Fs, xs, step, it, a.residual, b);
      a.iterations += it;
    }
    if (ok) a.x = xs, a.converged = true;
  }
  return a;
}

// Seabed continuation: a solution on a soft seabed, then its normal stiffness raised to the scene's
// (x10^(1/2) per step, halved in the exponent when Newton fails), so the line settles onto the seabed
// along a path of equilibria instead of jumping into a stiff one. Starts from the first guess on a
// seabed 10^start_exp as stiff, or (start_exp = -inf) from the solution without the seabed at 1e-6.
Attempt raiseSeabed(const Model& model, const StaticsProblem& problem, StaticTerms& terms, double t, double e,
                    Attempt a, Budget& b);

Attempt seabedRamp(const Model& model, const StaticsProblem& problem, StaticTerms& terms, double t, double start_exp,
                   Budget& b) {
  const bool from_free = !std::isfinite(start_exp);
  const double e = from_free ? -6.0 : std::min(start_exp, 0.0);  // log10 of the stiffness factor
  StaticsProblem loose = problem;                                // the intermediate states need not be exact
  loose.tolerance = std::max(problem.tolerance, 1e-6);
  terms.scaleSeabed(from_free ? 0.0 : std::pow(10.0, e));
  Attempt a = direct(model, loose, terms, t, b);
  return raiseSeabed(model, problem, terms, t, e, std::move(a), b);
}

// The seabed's normal stiffness raised from 10^e of the scene's to the scene's along the path of equilibria,
// from the state a solved there (x10^(1/2) per step, halved in the exponent when Newton fails).
Attempt raiseSeabed(const Model& model, const StaticsProblem& problem, StaticTerms& terms, double t, double e,
                    Attempt a, Budget& b) {
  StaticsProblem loose = problem;
  loose.tolerance = std::max(problem.tolerance, 1e-6);
  double step = 0.5;
  StaticResidual F(model, problem, terms, t);
  while (a.converged && e < 0.0 && step > 1e-3) {
    const double next = std::min(e + step, 0.0);
    terms.scaleSeabed(std::pow(10.0, next));
    VecX x = a.x;
    int it = 0;
    double res = INFINITY;
    const bool ok = newton(F, x, next < 0.0 ? loose : problem, it, res, b);
    a.iterations += it;
    if (ok) {
      a.x = x, a.residual = res, e = next, step = std::min(2.0 * step, 1.0);
    } else {
      step *= 0.5;
    }
  }
  terms.scaleSeabed(1.0);
  if (e < 0.0) a.converged = false;
  return a;
}

// Where the stable equilibria followed from still water end before the full current (a fold of the path, or a
// loss of stability): the state reached, in the physical terms of the scene.
std::string currentLimit(const Model& model, const StaticsProblem& p, const StaticTerms& terms, const Kinematics& kin,
                         const Vec2& end_force) {
  using Kind = StaticsProblem::Kind;
  std::ostringstream o;
  double highest = -INFINITY;
  for (const BodyKinematics& b : kin) highest = std::max(highest, b.end().y());
  const double lean = std::atan2(std::abs(kin.back().end().x() - p.top.x()), p.top.y() - kin.back().end().y());
  o << "the end " << lean * 180.0 / M_PI << " deg from the vertical below the hang-off";
  double surface = INFINITY;
  for (const auto& term : model.terms())
    if (const auto* d = dynamic_cast<const MorisonDrag*>(term.get())) surface = d->water().spec().surface;
  if (highest > p.top.y() - 1e-3 * model.length())
    o << ", its highest point " << highest - p.top.y() << " m above the hang-off: in more current it would have to "
      << "stand above its hang-off, which no resting state does";
  else if (std::isfinite(surface) && surface < p.top.y() && highest > surface - 0.5 * model.segmentLength())
    o << ", a joint at the water surface (" << highest - surface << " m): in more current the drag lifts the line "
      << "out of the water, where neither drag nor buoyancy holds it";
  if (p.kind == Kind::kBetweenPoints)
    o << ", the anchor pulling " << end_force.norm() << " N (a pinned line: its tension between the hang-off and "
      << "the anchor holds no stable shape against more drag)";
  else if (p.kind == Kind::kEndDisplaced)
    o << ", the end held by " << end_force.x() << " N";
  if (std::isfinite(terms.seabedLevel())) {
    int laid = 0;
    for (const BodyKinematics& b : kin) laid += b.end().y() <= terms.seabedLevel() ? 1 : 0;
    o << ", " << laid << " joints on the seabed (their contacts switch as the drag drags them)";
  }
  return o.str();
}

}  // namespace

constexpr int kMaxRampFailures = 8;

// A continuation in loads (scale(s): the attachments' loads, StaticTerms::scaleAttachments, or the buoyancy,
// scaleBuoyancy): from none (solved by `start`) up to the scene's in steps (from the last state: Newton stays on
// the path) halved when Newton fails; with `check`, the end is checked as any solution (its stability included).
// failure: empty on success.
template <class Start, class Scale>
Attempt rampLoads(const Model& model, const StaticsProblem& problem, StaticTerms& terms, StaticResidual& F, double t,
                  Budget& budget, Start&& start, Scale&& scale, const std::string& what, bool check) {
  StaticsProblem loose = problem;
  loose.tolerance = std::max(problem.tolerance, 1e-6);
  scale(0.0);
  std::string none_failures;
  Attempt c = start(loose, none_failures);
  double s = 0.0, step = 0.25;
  Kinematics kin(model.bodies());
  // A path that refuses kMaxRampFailures steps stalls (contacts switching at a touch-down make Newton chatter
  // between nearby loads, each failure ~max_iterations): the caller's next path takes over.
  int failures = 0;
  if (c.converged) {
    while (s < 1.0 && step > 1e-3 && failures < kMaxRampFailures && !budget.out) {
      const double next = std::min(s + step, 1.0);
      scale(next);
      VecX x = c.x;
      int it = 0;
      double r = INFINITY;
      budget.stage = "with " + what + " ramped up, at " + std::to_string(next) + " of the scene's";
      const bool ok = newton(F, x, next < 1.0 ? loose : problem, it, r, budget);
      c.iterations += it;
      if (ok)
        c.x = x, c.residual = r, s = next, step = std::min(2.0 * step, 0.5);
      else
        step *= 0.5, ++failures;
    }
  }
  scale(1.0);
  std::ostringstream o;
  if (!c.converged) {
    o << "(without them: " << none_failures << ")";
  } else if (s < 1.0) {
    o << "(the stable equilibria end at " << s << " of their loads)";
  } else if (check) {
    F.toKinematics(c.x, kin);
    const EquilibriumCheck ch = checkEquilibrium(model, problem, kin, F.endForce(c.x), t);
    if (!ch.ok)
      o << "to a valid equilibrium: its solution (" << c.iterations << " iterations, residual " << c.residual
        << ") fails the check " << ch.message;
  }
  c.failure = o.str();
  return c;
}

StaticsResult solveStatics(const Model& model, const StaticsProblem& problem, double t) {
  using Kind = StaticsProblem::Kind;
  StaticsResult res;
  const double L = model.length();
  if (problem.kind == Kind::kEndDisplaced && !(std::abs(problem.end_dx) < L)) {
    res.message = "initial.end_dx: |end_dx| must be < line.length for a displaced initial state";
    return res;
  }
  const double span = (problem.end_point - problem.top).norm();
  if (problem.kind == Kind::kBetweenPoints && !model.options().axial_flexibility && !(span < L * (1.0 - 1e-9))) {
    std::ostringstream o;
    o << "bottom.position: " << span << " m from the top, not closer than line.length (" << L
      << " m): an inextensible line held at its full length has no equilibrium (infinite tension, or, straight "
         "down, no unique one)";
    res.message = o.str();
    return res;
  }
  StaticTerms terms(model, t);
  res.message = statics_detail::seabedGeometry(model, problem, terms);
  if (!res.message.empty()) return res;
  StaticResidual F(model, problem, terms, t);
  // Attempts in turn until one converges (and, when `check`, passes checkEquilibrium()). Without a seabed:
  // Newton from the first guess. With one: the stiffness ramped up from a soft seabed (contact points sinking
  // 1e-3 L under their share of the weight) starting from the first guess (fewer iterations than a
  // direct start on a stiff seabed: J-lay n = 400, 17 vs 48); Newton from the first guess; the
  // stiffness ramped up from the solution without the seabed.
  const char* names[] = {"from the first guess ", "with the seabed stiffness ramped up from the first guess ",
                         "with the seabed stiffness ramped up from the solution without the seabed "};
  const double k = terms.seabedStiffness();
  const double soft = std::log10(F.weight() / (model.bodies() + 1) / (1e-3 * L) / std::max(k, 1e-300));
  Budget budget;
  const auto attempts = [&](const StaticsProblem& prob, bool check, std::string& failures) {
    const int order[] = {1, 0, 2};
    Attempt a;
    for (int attempt : order) {
      if (budget.out) break;
      if (attempt != 0 && !(k > 0.0)) continue;
      if (attempt != 0 && !prob.continuation) continue;
      if (attempt == 1 && !(soft < 0.0)) continue;  // the seabed is soft already
      const int before = a.iterations;
      budget.stage = std::string(names[attempt]) + (terms.currentFactor() != 1.0 ? "in still water " : "");
      a = attempt == 0 ? direct(model, prob, terms, t, budget)
                       : seabedRamp(model, prob, terms, t, attempt == 1 ? soft : -INFINITY, budget);
      a.iterations += before;
      std::ostringstream o;
      if (a.converged && check) {
        Kinematics kin(model.bodies());
        F.toKinematics(a.x, kin);
        const EquilibriumCheck c = checkEquilibrium(model, prob, kin, F.endForce(a.x), t);
        if (!c.ok)
          o << "to a valid equilibrium: its solution (" << a.iterations << " iterations, residual " << a.residual
            << ") fails the check " << c.message;
      } else if (!a.converged) {
        o << "in " << a.iterations << " iterations, residual " << a.residual << " (tolerance " << prob.tolerance << ")";
      }
      a.failure = o.str();
      if (a.failure.empty()) break;
      failures += (failures.empty() ? "" : "; ") + std::string(names[attempt]) + a.failure;
    }
    return a;
  };
  // Continuations in the loads that shape a line in still water (buoys and clumps can pull Newton onto a folded
  // balance; a lazy wave's buoyant section from the catenary guess onto an upturned one): the line without them,
  // then their loads ramped up along the path of equilibria. `check`: the end is checked as any solution.
  const auto loadRamps = [&](const StaticsProblem& prob, bool check, std::string& failures) {
    Attempt a;
    a.failure = "no load to ramp";
    const auto start = [&](const StaticsProblem& p, std::string& f) { return attempts(p, false, f); };
    if (terms.hasAttachments() && !budget.out) {
      a = rampLoads(
          model, prob, terms, F, t, budget, start, [&](double s) { terms.scaleAttachments(s); },
          "the attachments' loads", check);
      if (a.failure.empty()) return a;
      failures += "; with the attachments' loads ramped up from none " + a.failure;
    }
    if (terms.hasBuoyantSection() && !budget.out) {
      a = rampLoads(
          model, prob, terms, F, t, budget, start, [&](double s) { terms.scaleBuoyancy(s); }, "the buoyancy", check);
      if (a.failure.empty()) return a;
      failures += "; with the buoyancy ramped up from none " + a.failure;
    }
    return a;
  };
  // Empty when the state of c passes checkEquilibrium(), else why (the continuations' ends).
  const auto checked = [&](const Attempt& c) {
    Kinematics kin(model.bodies());
    F.toKinematics(c.x, kin);
    const EquilibriumCheck ch = checkEquilibrium(model, problem, kin, F.endForce(c.x), t);
    std::ostringstream o;
    if (!ch.ok)
      o << "to a valid equilibrium: its solution (" << c.iterations << " iterations, residual " << c.residual
        << ") fails the check " << ch.message;
    return o.str();
  };
  std::string failures;
  Attempt a = attempts(problem, true, failures);
  if (!a.failure.empty() && problem.continuation && terms.hasCurrent() && !budget.out) {
    // Continuation in the current: the equilibrium in still water, then the current's drag (∝ speed²) ramped
    // up along the path of equilibria; the last state is checked as any solution.
    StaticsProblem loose = problem;
    loose.tolerance = std::max(problem.tolerance, 1e-6);
    terms.scaleCurrent(0.0);
    std::string still_failures;
    Attempt c = attempts(loose, false, still_failures);
    if (!c.converged && !budget.out) {  // the still-water shape through its own load ramps
      const Attempt r = loadRamps(loose, false, still_failures);
      if (r.failure.empty()) c = r;
    }
    // Each state on the path must stay stable (the line would leave an unstable one): a step that lands on an
    // unstable state is halved like one Newton fails on, so the path ends where it folds or loses stability.
    double s = 0.0, step = 0.25;  // the drag's fraction of the scene's
    std::string lost;             // why the last refused step's state was unstable
    Kinematics kin(model.bodies());
    if (c.converged) {
      for (; s < 1.0 && step > 1e-3 && !budget.out;) {
        const double next = std::min(s + step, 1.0);
        terms.scaleCurrent(std::sqrt(next));
        VecX x = c.x;
        int it = 0;
        double r = INFINITY;
        budget.stage =
            "with the current ramped up from still water, at " + std::to_string(std::sqrt(next)) + " of its speed";
        bool ok = newton(F, x, next < 1.0 ? loose : problem, it, r, budget);
        c.iterations += it;
        if (ok) {
          F.toKinematics(x, kin);
          const std::string u = statics_detail::stabilityCheck(model, problem, kin, F.endForce(x), t, std::sqrt(next));
          if (!u.empty()) ok = false, lost = u;
        }
        if (ok)
          c.x = x, c.residual = r, s = next, step = std::min(2.0 * step, 0.5);
        else
          step *= 0.5;
      }
    }
    terms.scaleCurrent(1.0);
    std::ostringstream o;
    if (!c.converged) {
      o << "in still water (" << still_failures << ")";
    } else if (s < 1.0) {
      F.toKinematics(c.x, kin);
      o << "beyond " << std::sqrt(s) << " x the current's speed (the stable equilibria from still water end there";
      if (!lost.empty()) o << ", the next one is unstable";
      o << ": " << currentLimit(model, problem, terms, kin, F.endForce(c.x)) << ")";
    } else {
      o << checked(c);
    }
    c.iterations += a.iterations;
    c.failure = o.str();
    if (c.failure.empty())
      a = c;
    else
      failures += "; with the current ramped up from still water " + c.failure;
  }
  if (!a.failure.empty() && problem.continuation && !budget.out) {
    const Attempt c = loadRamps(problem, true, failures);
    if (c.failure.empty()) a = c;
  }
  if (!a.failure.empty() && problem.continuation && k > 0.0 && !budget.out &&
      (terms.hasAttachments() || terms.hasBuoyantSection())) {
    // The load ramps on a seabed 10x softer (its contacts switch less as the touch-down moves: a lazy wave's
    // Newton chatters there), then its stiffness raised to the scene's; the end is checked as any solution.
    StaticsProblem loose = problem;
    loose.tolerance = std::max(problem.tolerance, 1e-6);
    terms.softenSeabed(0.1);
    std::string soft_failures;
    Attempt c = loadRamps(loose, false, soft_failures);
    terms.softenSeabed(1.0);
    const bool ramped = c.failure.empty();
    c.converged = ramped;
    c = raiseSeabed(model, problem, terms, t, -1.0, std::move(c), budget);
    std::ostringstream o;
    if (!ramped)
      o << "(" << (soft_failures.size() > 2 ? soft_failures.substr(2) : std::string("no load ramp converged")) << ")";
    else if (!c.converged)
      o << "(raising its stiffness from 0.1 of the scene's: the path of equilibria Newton follows ends before)";
    else
      o << checked(c);
    c.failure = o.str();
    if (c.failure.empty())
      a = c;
    else
      failures += "; with the loads ramped up on a seabed 10x softer, then its stiffness raised " + c.failure;
  }
  res.converged = a.failure.empty();
  res.iterations = a.iterations;
  res.residual = a.residual;
  res.kin.resize(model.bodies());
  F.toKinematics(a.x, res.kin);
  res.end_force = F.endForce(a.x);
  std::ostringstream msg;
  if (res.converged)
    msg << "statics converged in " << res.iterations << " iterations, residual " << res.residual << " (tolerance "
        << problem.tolerance << ")";
  else if (budget.out)
    msg << "statics stopped at the time limit (" << problem.time_limit << " s, " << budget.iterations
        << " Newton iterations) " << budget.stage << ": " << failures << "; try fewer line.elements, a looser "
        << "initial.tolerance, less current, or initial.type straight [" << problemKeys(model, problem, terms) << "]";
  else
    msg << "statics did not converge " << failures << " [" << problemKeys(model, problem, terms) << "]";
  res.message = msg.str();
  return res;
}

}  // namespace riser_sim
