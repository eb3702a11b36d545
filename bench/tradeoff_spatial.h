// The 3D cases of the speed/accuracy sweep (riser_sim_bench_tradeoff --cases spatial_swing): the shipped
// config/scenes/spatial_swing.yaml (20 m steel pipe, 50 kg end mass, inextensible, bending; the top sways
// along an oblique line in x and y, the end released 4 m to the side in +y, so it swings in x and y) run for
// 20 s at n = 5, 10, 20 (the scene's n is 20), each integrator over a range of steps. Measured: the end
// point's distance at t = 20 s to a converged reference run at the same n (time-integration error only):
// rk4 at 0.5 ms, its convergence checked against rk4 at 1 ms (their distance, printed and written as
// ref_check_m, bounds the reference's own error ~15x over: rk4's error falls as h^4),
// and the thread CPU time of the stepping (median of 3). Targets (docs/benchmarks.md): within 1 cm in
// <= 0.02 s CPU, within 1 mm in <= 0.1 s CPU. Header-only: the sweep's executable is listed in
// cmake/bench.cmake.
#pragma once
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace tradeoff {
namespace spatial3 {

inline double threadCpu3() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

constexpr double kDuration = 20.0;                         // [s] simulated
constexpr double kRefStep = 5e-4;                          // [s] rk4's reference step (checked against twice it)
constexpr double kTarget1cm = 0.01, kTarget1cmCpu = 0.02;  // [m], [s]
constexpr double kTarget1mm = 0.001, kTarget1mmCpu = 0.1;  // [m], [s]

struct TradeRun3 {
  std::string status = "ok", reason;
  riser_sim::spatial::Vec3 end = riser_sim::spatial::Vec3::Zero();  // end point at kDuration [m]
  double cpu = 0.0;                                                 // [s] stepping, median of the repeats
  double limit = 0.0;                                               // rk4's estimated limit at this n [s]
  long steps = 0;
};

struct Setting3 {
  std::string integrator;
  double h = 0.0;        // solver.dt [s] (dopri5: the output step)
  double tol = NAN;      // dopri5
  double rho_inf = NAN;  // generalized_alpha
  double newton = NAN;   // midpoint, generalized_alpha: solver.newton_tolerance (NaN: the default)
  std::string label() const {
    char b[96];
    if (!std::isnan(newton))
      std::snprintf(b, sizeof(b), "%s newton %.0e", integrator.c_str(), newton);
    else if (!std::isnan(tol))
      std::snprintf(b, sizeof(b), "%s tol %.0e", integrator.c_str(), tol);
    else if (!std::isnan(rho_inf))
      std::snprintf(b, sizeof(b), "%s rho_inf=%g", integrator.c_str(), rho_inf);
    else
      std::snprintf(b, sizeof(b), "%s", integrator.c_str());
    return b;
  }
};

inline riser_sim::Scene scene3(const std::string& root, int n, const Setting3& s) {
  std::vector<std::string> o = {"line.elements=" + std::to_string(n), "solver.integrator=" + s.integrator,
                                "run.duration=" + std::to_string(kDuration)};
  char b[64];
  std::snprintf(b, sizeof(b), "solver.dt=%.17g", s.h);  // exact: the steps divide the duration
  o.push_back(b);
  if (!std::isnan(s.tol)) std::snprintf(b, sizeof(b), "solver.tolerance=%.3g", s.tol), o.push_back(b);
  if (!std::isnan(s.rho_inf)) std::snprintf(b, sizeof(b), "solver.rho_inf=%.3g", s.rho_inf), o.push_back(b);
  if (!std::isnan(s.newton)) std::snprintf(b, sizeof(b), "solver.newton_tolerance=%.3g", s.newton), o.push_back(b);
  return riser_sim::loadSceneFile(root + "/config/scenes/spatial_swing.yaml", o);
}

// One setting at n; repeats (median CPU) when a run takes less than 2 s.
inline TradeRun3 run3(const std::string& root, int n, const Setting3& s) {
  TradeRun3 r;
  std::vector<double> cpus;
  for (int rep = 0; rep < 3; ++rep) {
    riser_sim::spatial::Run3 run(scene3(root, n, s));
    r.limit = run.stableStepEstimate();
    const long steps = std::max(1L, std::lround(std::ceil(kDuration / run.dt() - 1e-9)));
    const double c0 = threadCpu3();
    bool ok = true;
    for (long k = 0; k < steps && ok; ++k) ok = run.step();
    cpus.push_back(threadCpu3() - c0);
    r.steps = run.steps();
    if (!ok) {
      r.status = "diverged";
      r.reason = run.divergenceReason();
      return r;
    }
    if (std::abs(run.time() - kDuration) > 1e-9) {  // the error is measured at one time for every run
      r.status = "skipped";
      r.reason = "does not end at t = " + std::to_string(kDuration);
      return r;
    }
    r.end = run.outputs().points.back();
    if (cpus.back() > 2.0) break;
  }
  std::sort(cpus.begin(), cpus.end());
  r.cpu = cpus[cpus.size() / 2];
  return r;
}

// The sweep: rk4 at 0.9, 0.5, 0.25 x its estimated limit; dopri5 at tolerances 1e-4..1e-8 with an output
// step of 10 ms (its steps end on it) and 1e-3..1e-6 at 0.1 s; the implicit schemes at h = 0.1 .. 0.002 s;
// midpoint with a looser Newton tolerance (1e-4, 1e-6) at h = 0.05 .. 0.01 s.
inline std::vector<Setting3> settings3(double rk4_limit) {
  std::vector<Setting3> out;
  // Steps that divide the duration: every run ends at exactly t = kDuration (the end moves ~1 m/s).
  for (const double f : {0.9, 0.5, 0.25}) out.push_back({"rk4", kDuration / std::ceil(kDuration / (f * rk4_limit))});
  for (const double tol : {1e-4, 1e-6, 1e-8}) out.push_back({"dopri5", 0.01, tol});
  for (const double tol : {1e-3, 1e-4, 1e-6}) out.push_back({"dopri5", 0.1, tol});
  for (const double h : {0.1, 0.05, 0.02, 0.01, 0.005, 0.002}) {
    out.push_back({"rosenbrock2", h});
    out.push_back({"midpoint", h});
    out.push_back({"generalized_alpha", h, NAN, 0.5});
    out.push_back({"generalized_alpha", h, NAN, 0.0});
  }
  for (const double newton : {1e-4, 1e-6})
    for (const double h : {0.05, 1.0 / 30.0, 0.025, 0.02, 0.01}) out.push_back({"midpoint", h, NAN, NAN, newton});
  return out;
}

// Runs the sweep, prints the table and the targets' verdicts, writes <out>/tradeoff_spatial.csv.
inline void sweep3(const std::string& root, const std::string& out_dir, const std::vector<int>& ns) {
  std::FILE* csv = std::fopen((out_dir + "/tradeoff_spatial.csv").c_str(), "w");
  if (csv)
    std::fprintf(csv,
                 "case,n,integrator,rho_inf,tolerance,h,status,steps,cpu_s,end_error_m,ref_check_m,"
                 "rk4_limit_s,newton_tolerance\n");
  std::printf("\n## spatial_swing (3D): end point at t = %g s vs rk4 at h = %g s (same n)\n", kDuration, kRefStep);
  for (const int n : ns) {
    const TradeRun3 ref = run3(root, n, {"rk4", kRefStep});
    const TradeRun3 twice = run3(root, n, {"rk4", 2.0 * kRefStep});
    if (ref.status != "ok" || twice.status != "ok") {
      std::printf("  n = %d: reference run %s: %s\n", n, ref.status.c_str(), (ref.reason + twice.reason).c_str());
      continue;
    }
    const double check = (ref.end - twice.end).norm();
    std::printf(
        "\n  n = %d: reference rk4 h = %g s (%.2f s CPU), its distance to rk4 at 2h: %.2e m; rk4 limit %.4g s\n", n,
        kRefStep, ref.cpu, check, ref.limit);
    std::printf(
        "  | n | setting | h [s] | status | CPU [s] | end error [m] | 1 cm in 0.02 s | 1 mm in 0.1 s |\n"
        "  |---|---|---|---|---|---|---|---|\n");
    for (const Setting3& s : settings3(ref.limit)) {
      const TradeRun3 r = run3(root, n, s);
      const double err = r.status == "ok" ? (r.end - ref.end).norm() : NAN;
      const bool t1 = err <= kTarget1cm && r.cpu <= kTarget1cmCpu, t2 = err <= kTarget1mm && r.cpu <= kTarget1mmCpu;
      std::printf("  | %d | %s | %.4g | %s | %.4f | %.2e | %s | %s |\n", n, s.label().c_str(), s.h, r.status.c_str(),
                  r.cpu, err, t1 ? "yes" : "-", t2 ? "yes" : "-");
      std::fflush(stdout);
      if (csv)
        std::fprintf(csv, "spatial_swing,%d,%s,%g,%g,%.9g,%s,%ld,%.6f,%.6g,%.3g,%.6g,%g\n", n, s.integrator.c_str(),
                     s.rho_inf, s.tol, s.h, r.status.c_str(), r.steps, r.cpu, err, check, ref.limit, s.newton);
    }
  }
  if (csv) std::fclose(csv);
}

}  // namespace spatial3
}  // namespace tradeoff
