// riser_sim_bench_tradeoff: speed against accuracy on the paper's Table 1 line (m_s = 1000 kg on
// L = 100 m, E = 1e11 Pa, no bending, released from 50 m to the side; 20 s simulated). Sweeps
// integrator x formulation x n x h (or tolerance) for the elastic line and the inextensible one, and
// measures against converged references:
//   - end position at t = 20 s: docs/validation.md's converged values (elastic -49.9183, -86.604
//     ± (0.6, 3) mm; inextensible, Richardson from n = 80/160, -49.91890, -86.59851);
//   - peak and RMS top tension over 0..20 s (sampled every 0.01 s): rk4 at n = 100, h = 0.5x its
//     stability limit (elastic) / 5e-3 s (inextensible), recursive formulation, computed here.
// Wall time: median of 3 runs (1 run when one takes more than 2 s), stepping only; the thread's CPU
// time beside it (equal to the wall time on an idle core, far less on a shared, loaded machine). Writes
// out/bench/tradeoff.csv and prints a table; bench/plot_tradeoff.py draws out/bench/pareto.png.
//
//   riser_sim_bench_tradeoff [--quick] [--out FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "riser_sim/scene.h"

namespace {
using namespace riser_sim;

constexpr double kDuration = 20.0;      // [s] Table 1
constexpr double kSampleDt = 0.01;      // [s] tension sampling
constexpr double kMedianBelow = 2.0;    // [s] runs shorter than this are repeated 3 times
// Converged end positions (docs/validation.md, "Table 1").
const Vec2 kRefElastic(-49.9183, -86.604);
const Vec2 kRefInextensible(-49.91890, -86.59851);

Scene table1(int n, bool axial) {
  Scene s;
  s.name = "table1";
  s.length = 100.0;
  s.elements = n;
  s.line = LineProperties::fromGeometry(0.05, 0.0, 1e11, 2000.0);
  s.options.bending = false;
  s.options.axial_flexibility = axial;
  s.end_mass = 1000.0;
  s.initial.type = "displaced";
  s.initial.end_dx = -50.0;
  return s;
}

struct Config {
  bool axial;
  std::string formulation, integrator;
  int n;
  double h;    // solver.dt (output step for dopri5) [s]
  double tol;  // dopri5 only
};

struct Result {
  bool ok = false;
  double wall = 0.0, cpu = 0.0;
  int runs = 0;
  Vec2 end = Vec2::Zero();
  double peak = 0.0, rms = 0.0, drift = 0.0, limit = 0.0;
  Integrator::Stats stats;
  std::string reason;
};

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

Result runOnce(const Config& c) {
  Scene s = table1(c.n, c.axial);
  s.solver.formulation = c.formulation;
  s.solver.integrator = c.integrator;
  s.solver.dt = c.h;
  if (c.tol > 0.0) s.solver.tolerance = c.tol;
  Result r;
  auto sim = buildSimulator(s);
  r.limit = sim->stableStepEstimate();
  std::chrono::steady_clock::duration wall{0};
  double cpu = 0.0, sum2 = 0.0;
  long samples = 0;
  double next = 0.0;
  const long steps = std::lround(kDuration / c.h);
  for (long k = 0; k < steps; ++k) {
    if (sim->time() >= next - 1e-9) {
      const double T = sim->outputs().top_tension;
      r.peak = std::max(r.peak, T);
      sum2 += T * T;
      ++samples;
      next += kSampleDt;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = threadCpu();
    const bool ok = sim->step();
    cpu += threadCpu() - c0;
    wall += std::chrono::steady_clock::now() - t0;
    if (!ok) {
      r.reason = sim->divergenceReason();
      return r;
    }
  }
  const LineOutputs& o = sim->outputs();
  r.ok = true;
  r.end = o.points.back() - o.points.front();
  r.rms = std::sqrt(sum2 / std::max(1L, samples));
  r.drift = sim->energyDrift();
  r.wall = std::chrono::duration<double>(wall).count();
  r.cpu = cpu;
  r.stats = sim->integrator().stats();
  return r;
}

Result run(const Config& c) {
  std::vector<Result> rs;
  rs.push_back(runOnce(c));
  if (rs[0].ok && rs[0].wall < kMedianBelow) {
    rs.push_back(runOnce(c));
    rs.push_back(runOnce(c));
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

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string out_path = "out/bench/tradeoff.csv";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out_path = argv[++i];
    else {
      std::fprintf(stderr, "usage: riser_sim_bench_tradeoff [--quick] [--out FILE]\n");
      return 2;
    }
  }
  std::filesystem::path p(out_path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());

  // Tension references (n = 100, recursive, rk4 well inside its limit).
  std::printf("references: converged end position (docs/validation.md); tensions from rk4, n = 100 ...\n");
  std::fflush(stdout);
  double ref_peak[2], ref_rms[2];
  for (int axial = 0; axial < 2; ++axial) {
    Scene s = table1(100, axial);
    s.solver.formulation = "recursive";
    auto sim = buildSimulator(s);
    const double h = axial ? 0.5 * sim->stableStepEstimate() : 5e-3;
    const Result r = runOnce({bool(axial), "recursive", "rk4", 100, quick ? (axial ? 1e-4 : 5e-3) : h, 0.0});
    ref_peak[axial] = r.peak;
    ref_rms[axial] = r.rms;
    std::printf("  %s: h = %.3g s, end (%.6f, %.6f), peak T %.2f N, RMS T %.2f N (%.1f s wall)\n",
                axial ? "elastic" : "inextensible", h, r.end.x(), r.end.y(), r.peak, r.rms, r.wall);
    std::fflush(stdout);
  }

  std::vector<Config> cfg;
  const std::vector<int> ns = quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 40, 100};
  for (int n : ns) {
    // Elastic line.
    for (const char* f : {"absolute", "recursive"}) {
      Scene s = table1(n, true);
      s.solver.formulation = f;
      const double lim = buildSimulator(s)->stableStepEstimate();
      for (double k : {0.9, 0.3})
        if (!(n == 100 && k < 0.5)) cfg.push_back({true, f, "rk4", n, k * lim, 0.0});
    }
    for (double tol : {1e-4, 1e-6, 1e-8})
      if (n <= 40 || tol == 1e-6) cfg.push_back({true, "recursive", "dopri5", n, 0.05, tol});
    for (double h : {5e-2, 2e-2, 1e-2, 4e-3, 2e-3}) cfg.push_back({true, "recursive", "rosenbrock2", n, h, 0.0});
    for (double h : {5e-2, 2e-2, 1e-2, 4e-3, 2e-3}) cfg.push_back({true, "recursive", "midpoint", n, h, 0.0});
    if (n <= 40)
      for (double h : {1e-2, 4e-3}) cfg.push_back({true, "absolute", "rosenbrock2", n, h, 0.0});
    // Inextensible line (the speed option): no axial frequency.
    {
      Scene s = table1(n, false);
      s.solver.formulation = "recursive";
      const double lim = buildSimulator(s)->stableStepEstimate();
      for (double h : {0.05, 0.02, 0.01, 0.005})
        if (h <= 0.9 * lim) cfg.push_back({false, "recursive", "rk4", n, h, 0.0});
    }
    for (double tol : {1e-3, 1e-5, 1e-7, 1e-9}) cfg.push_back({false, "recursive", "dopri5", n, 0.05, tol});
    for (double h : {0.05, 0.02, 0.01}) cfg.push_back({false, "recursive", "rosenbrock2", n, h, 0.0});
    for (double h : {0.05, 0.02, 0.01}) cfg.push_back({false, "recursive", "midpoint", n, h, 0.0});
  }
  if (!quick) {  // where affordable
    cfg.push_back({true, "recursive", "rosenbrock2", 200, 4e-3, 0.0});
    cfg.push_back({false, "recursive", "dopri5", 200, 0.05, 1e-5});
    cfg.push_back({false, "recursive", "dopri5", 1000, 0.05, 1e-5});
  }

  std::FILE* csv = std::fopen(out_path.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "cannot open %s\n", out_path.c_str());
    return 1;
  }
  std::fprintf(csv,
               "model,formulation,integrator,n,h,tolerance,status,wall_s,cpu_s,runs,rtf,substeps,rejected,rhs,"
               "jacobians,x_end,y_end,err_end_m,peak_T,rms_T,err_peak_rel,err_rms_rel,energy_drift,"
               "rk4_limit_h\n");
  std::printf("\n| model | formulation | integrator | n | h [s] | tol | wall [s] | RTF | end error [m] | peak T err | "
              "RMS T err | drift |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Config& c : cfg) {
    const Result r = run(c);
    const int a = c.axial ? 1 : 0;
    const Vec2 ref = c.axial ? kRefElastic : kRefInextensible;
    const double err = (r.end - ref).norm();
    const double ep = r.ok ? std::abs(r.peak - ref_peak[a]) / ref_peak[a] : NAN;
    const double er = r.ok ? std::abs(r.rms - ref_rms[a]) / ref_rms[a] : NAN;
    const char* model = c.axial ? "elastic" : "inextensible";
    const char* tol_s = c.integrator == "dopri5" ? "" : "-";
    char tol[32];
    if (c.integrator == "dopri5") std::snprintf(tol, sizeof(tol), "%.0e", c.tol);
    else std::snprintf(tol, sizeof(tol), "%s", tol_s);
    std::fprintf(csv, "%s,%s,%s,%d,%.6g,%s,%s,%.6g,%.6g,%d,%.6g,%ld,%ld,%ld,%ld,%.9g,%.9g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                 model, c.formulation.c_str(), c.integrator.c_str(), c.n, c.h, c.integrator == "dopri5" ? tol : "",
                 r.ok ? "ok" : "diverged", r.wall, r.cpu, r.runs, r.ok ? kDuration / r.wall : 0.0,
                 r.stats.substeps, r.stats.rejected, r.stats.rhs, r.stats.jacobians, r.end.x(), r.end.y(),
                 r.ok ? err : NAN, r.peak, r.rms, ep, er, r.drift, r.limit);
    std::fflush(csv);
    if (r.ok)
      std::printf("| %s | %s | %s | %d | %.3g | %s | %.4f | %.4f | %.2e | %.1e | %.1e | %.1e |\n", model,
                  c.formulation.c_str(), c.integrator.c_str(), c.n, c.h, tol, r.wall, r.cpu, err, ep, er, r.drift);
    else
      std::printf("| %s | %s | %s | %d | %.3g | %s | diverged: %.80s |\n", model, c.formulation.c_str(),
                  c.integrator.c_str(), c.n, c.h, tol, r.reason.c_str());
    std::fflush(stdout);
  }
  std::fclose(csv);
  std::printf("\nwrote %s\n", out_path.c_str());
  return 0;
}
