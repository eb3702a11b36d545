#include "tradeoff_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "riser_sim/planar/run_builder.h"

namespace tradeoff {

using namespace riser_sim;

namespace {

constexpr double kProbeWall = 0.3;  // [s] of stepping before the cost is extrapolated
constexpr double kGridEps = 1e-7;   // [s] a step end this close to t_k is on the grid

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Records the force histories on the grid t_k (tradeoff_history.h): the outputs at a step end on t_k,
// or linear interpolation between the outputs before and after a step that crosses t_k.
class HistoryRecorder {
 public:
  HistoryRecorder(Measures& m, double duration) : m_(m), samples_(historySamples(duration)) {
    m_.top_tension.assign(samples_, NAN);  // sized here, before the timed stepping
    m_.max_axial.assign(samples_, NAN);
  }
  // Before a step to t1: keeps the outputs at its start if a grid point lies strictly inside it.
  void before(Simulator& sim, double t1) {
    t0_ = sim.time();
    if (next_ < samples_ && tk(next_) < t1 - kGridEps) before_ = values(sim);
  }
  // After the step (also at t = 0, before any step).
  void after(Simulator& sim) {
    const double t1 = sim.time();
    if (next_ >= samples_ || tk(next_) > t1 + kGridEps) return;
    const Vals v1 = values(sim);
    for (; next_ < samples_ && tk(next_) < t1 - kGridEps; ++next_) {
      const double w = (tk(next_) - t0_) / (t1 - t0_);
      put(next_, {(1.0 - w) * before_.T + w * v1.T, (1.0 - w) * before_.A + w * v1.A});
    }
    if (next_ < samples_ && std::abs(tk(next_) - t1) <= kGridEps) put(next_++, v1);
  }
  bool complete() const { return next_ == samples_; }

 private:
  struct Vals {
    double T, A;
  };
  static double tk(int k) { return k * kHistoryDt; }
  static Vals values(Simulator& sim) {
    const LineOutputs& o = sim.outputs();
    return {o.top_tension, o.max_tension};
  }
  void put(int k, const Vals& v) {
    m_.top_tension[k] = v.T;
    m_.max_axial[k] = v.A;
  }
  Measures& m_;
  int samples_, next_ = 0;
  double t0_ = 0.0;
  Vals before_{NAN, NAN};
};

Result runOnce(const Config& c, double max_run) {
  Result r;
  Scene s = applyConfig(c);
  std::unique_ptr<Simulator> sim;
  try {
    s.solver.dt = c.h > 0.0 ? c.h : 1e-3;
    sim = buildSimulator(s);
    r.limit = sim->stableStepEstimate();
    if (c.h <= 0.0) {  // -h x the limit, rounded down to a whole number of steps in the duration
      s.solver.dt = c.c->duration / std::ceil(c.c->duration / (-c.h * r.limit));
      sim = buildSimulator(s);
    }
  } catch (const std::exception& e) {
    r.status = "diverged";
    r.reason = std::string("setup: ") + e.what();
    return r;
  }
  r.h = s.solver.dt;
  const Case& k = *c.c;
  const long steps = std::lround(k.duration / r.h);
  std::chrono::steady_clock::duration wall{0};
  double cpu = 0.0;
  HistoryRecorder history(r.m, k.duration);
  history.after(*sim);  // t = 0
  for (long i = 0; i < steps; ++i) {
    history.before(*sim, sim->time() + r.h);
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = threadCpu();
    const bool ok = sim->step();
    cpu += threadCpu() - c0;
    wall += std::chrono::steady_clock::now() - t0;
    if (!ok) {
      r.status = "diverged";
      r.reason = sim->divergenceReason();
      return r;
    }
    history.after(*sim);
    const double w = std::chrono::duration<double>(wall).count();
    if (w > kProbeWall && i + 1 < steps && max_run > 0.0) {
      const double predicted = cpu * double(steps) / double(i + 1);
      if (predicted > max_run) {
        r.status = "skipped";
        r.reason = "predicted " + std::to_string(int(predicted)) + " s CPU > budget";
        r.cpu = predicted;
        return r;
      }
      max_run = 0.0;  // predicted within budget: no more checks
    }
  }
  if (!history.complete()) throw std::logic_error("tradeoff: the force history missed grid points");
  const LineOutputs& o = sim->outputs();
  r.status = "ok";
  r.steps = steps;
  r.m.probe = probeAt(o, k.scene(c.n).length, c.n, k.probe_s);
  if (k.probe_relative) r.m.probe -= o.points.front();
  r.drift = sim->energyDrift();
  r.wall = std::chrono::duration<double>(wall).count();
  r.cpu = cpu;
  r.stats = sim->integrator().stats();
  return r;
}

}  // namespace

Scene applyConfig(const Config& c) {
  Scene s = c.c->scene(c.n);
  s.solver.formulation = toChoice<FormulationKind>(c.formulation);
  s.solver.integrator = toChoice<IntegratorKind>(c.integrator);
  if (c.tol > 0.0) s.solver.tolerance = c.tol;
  s.solver.jacobian = toChoice<JacobianKind>(c.jacobian);
  if (!std::isnan(c.rho_inf)) {
    if (s.solver.integrator != IntegratorKind::kGeneralizedAlpha)
      throw std::invalid_argument("rho_inf: only generalized_alpha has solver.rho_inf");
    s.solver.rho_inf = c.rho_inf;
  }
  return s;
}

Result run(const Config& c, double max_run, double repeat_below) {
  std::vector<Result> rs{runOnce(c, max_run)};
  if (rs[0].status == "ok" && rs[0].wall < repeat_below) {
    rs.push_back(runOnce(c, 0.0));
    rs.push_back(runOnce(c, 0.0));
  }
  std::vector<double> w, u;
  for (const Result& r : rs) {
    w.push_back(r.wall);
    u.push_back(r.cpu);
  }
  std::sort(w.begin(), w.end());
  std::sort(u.begin(), u.end());
  Result out = rs[0];
  out.wall = w[w.size() / 2];
  out.cpu = u[u.size() / 2];
  out.runs = int(rs.size());
  return out;
}

}  // namespace tradeoff
