// riser_sim_bench_tradeoff: speed against accuracy. For each case (bench/tradeoff_cases.cpp:
// the paper's Table 1 line elastic and inextensible, the 170 m J-lay elastic and inextensible, the 500 m
// riser) it first computes the references, then sweeps integrator x formulation x n x h (or tolerance)
// and measures each run against them: the probe point's position at the end of the run, the peak and
// RMS top tension over the run (sampled at every step, at most every 10 ms), the energy-balance error,
// wall and thread-CPU time (median of 3 for runs under 2 s). Runs predicted to exceed --max-run seconds
// are skipped and listed as such. Writes <out>/tradeoff.csv and <out>/references.csv; prints tables.
// bench/plot_tradeoff.py draws the Pareto plots and picks the cheapest setting per accuracy target.
//
//   riser_sim_bench_tradeoff [--quick] [--out DIR] [--cases a,b] [--ns a,b] [--max-run S] [--root DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "riser_sim/integrator.h"
#include "tradeoff_run.h"

namespace {

using namespace tradeoff;

struct Ref {
  Measures m;
  double spread_pos = 0.0, spread_peak = 0.0, spread_rms = 0.0;
  std::string source;
};

// References of one case: the reference runs (no budget), the last one is the reference.
Ref reference(const Case& c, std::FILE* csv) {
  Ref ref;
  std::vector<Result> rs;
  for (const Case::RefRun& rr : c.ref_runs) {
    const Result r = run({&c, "recursive", rr.integrator, rr.n, rr.h, 0.0}, 0.0, 0.0);
    std::printf("  %-20s reference run: n = %d, %s, h = %.3g s: %s, probe (%.6f, %.6f), peak T %.1f N, RMS T %.1f N, "
                "%.1f s CPU\n",
                c.name.c_str(), rr.n, rr.integrator.c_str(), r.h, r.status.c_str(), r.m.probe.x(), r.m.probe.y(),
                r.m.peak, r.m.rms, r.cpu);
    std::fprintf(csv, "%s,%d,%s,%.6g,%s,%.9g,%.9g,%.6f,%.6f,%.3f\n", c.name.c_str(), rr.n, rr.integrator.c_str(),
                 r.h, r.status.c_str(), r.m.probe.x(), r.m.probe.y(), r.m.peak, r.m.rms, r.cpu);
    std::fflush(stdout);
    rs.push_back(r);
  }
  const Result& last = rs.back();
  ref.m = last.m;
  std::ostringstream src;
  src << c.ref_runs.back().integrator << ", n = " << c.ref_runs.back().n << ", h = " << last.h << " s";
  ref.source = src.str();
  for (size_t k = 0; k + 1 < rs.size(); ++k) {  // largest difference to the coarser runs
    const Result& other = rs[k];
    ref.spread_pos = std::max(ref.spread_pos, (last.m.probe - other.m.probe).norm());
    ref.spread_peak = std::max(ref.spread_peak, std::abs(last.m.peak - other.m.peak) / last.m.peak);
    ref.spread_rms = std::max(ref.spread_rms, std::abs(last.m.rms - other.m.rms) / last.m.rms);
  }
  if (c.fixed_probe) {
    ref.m.probe = c.probe_ref;
    ref.spread_pos = c.probe_spread;
    ref.source = c.probe_source;
  }
  std::printf("  %-20s reference: probe (%.6f, %.6f) ± %.2g m (%s); peak T %.1f N ± %.1g, RMS T %.1f N ± %.1g\n",
              c.name.c_str(), ref.m.probe.x(), ref.m.probe.y(), ref.spread_pos, ref.source.c_str(), ref.m.peak,
              ref.spread_peak, ref.m.rms, ref.spread_rms);
  std::fflush(stdout);
  return ref;
}

std::vector<Config> sweep(const Case& c, bool quick, const std::string& ns) {
  const bool axial = c.scene(10).options.axial_flexibility;
  std::vector<Config> cfg;
  const std::vector<double> hs = {0.1, 0.05, 0.02, 0.01, 0.005, 0.002};
  for (int n : c.ns) {
    if (quick && n > 20) continue;
    if (!ns.empty() && ns.find("," + std::to_string(n) + ",") == std::string::npos) continue;
    for (double k : {-0.9, -0.3}) cfg.push_back({&c, "recursive", "rk4", n, k, 0.0});
    if (n <= 100) cfg.push_back({&c, "absolute", "rk4", n, -0.9, 0.0});  // the paper's formulation
    if (!axial)
      for (double h : {0.05, 0.02, 0.01}) cfg.push_back({&c, "recursive", "rk4", n, h, 0.0});
    for (double tol : {1e-4, 1e-6, 1e-8}) cfg.push_back({&c, "recursive", "dopri5", n, 0.01, tol});
    for (const char* integ : {"rosenbrock2", "midpoint", "generalized_alpha"})  // structured O(n) solves
      for (double h : hs) cfg.push_back({&c, "recursive", integ, n, h, 0.0});
    if (n <= 40)  // the same schemes with the dense finite-difference Jacobian: same accuracy, cost O(p²)
      for (const char* integ : {"rosenbrock2", "midpoint"})
        for (double h : {0.02, 0.005}) cfg.push_back({&c, "recursive", integ, n, h, 0.0, "dense"});
    if (n <= 40)  // absolute: dense Jacobian only, Baumgarte-held joints
      for (const char* integ : {"rosenbrock2", "midpoint"})
        for (double h : {0.01, 0.002}) cfg.push_back({&c, "absolute", integ, n, h, 0.0});
  }
  return cfg;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string out_dir = "out/bench", root = ".", only, ns;
  double max_run = 20.0;
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--out") && more) out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--root") && more) root = argv[++i];
    else if (!std::strcmp(argv[i], "--cases") && more) only = std::string(",") + argv[++i] + ",";
    else if (!std::strcmp(argv[i], "--max-run") && more) max_run = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--ns") && more) ns = std::string(",") + argv[++i] + ",";
    else {
      const bool help = !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h");
      std::fprintf(help ? stdout : stderr,
                   "usage: riser_sim_bench_tradeoff [--quick] [--out DIR] [--cases a,b] [--ns 10,20] [--max-run S] "
                   "[--root DIR]\n"
                   "  --quick      n <= 20 only\n"
                   "  --ns a,b     only these n (of 10, 20, 40, 100, 200, 1000)\n"
                   "  --out DIR    tradeoff.csv and references.csv go here (default out/bench)\n"
                   "  --cases a,b  only these cases (table1_elastic, table1_inextensible, jlay_elastic,\n"
                   "               jlay_inextensible, riser500)\n"
                   "  --max-run S  skip a run predicted to take more than S s of CPU time (default 20)\n"
                   "  --root DIR   repository root (scene files; default .)\n");
      return help ? 0 : 2;
    }
  }
  std::filesystem::create_directories(out_dir);
  std::vector<Case> cases;
  for (const Case& c : allCases(root))
    if (only.empty() || only.find("," + c.name + ",") != std::string::npos) cases.push_back(c);
  if (cases.empty()) {
    std::fprintf(stderr, "no case selected (--cases)\n");
    return 2;
  }

  std::FILE* refs = std::fopen((out_dir + "/references.csv").c_str(), "w");
  std::FILE* csv = std::fopen((out_dir + "/tradeoff.csv").c_str(), "w");
  if (!refs || !csv) {
    std::fprintf(stderr, "cannot write into %s\n", out_dir.c_str());
    return 1;
  }
  std::fprintf(refs, "case,n,integrator,h,status,probe_x,probe_y,peak_T,rms_T,cpu_s\n");
  std::printf("references (recursive formulation):\n");
  std::map<std::string, Ref> ref;
  for (const Case& c : cases) ref[c.name] = reference(c, refs);
  std::fclose(refs);

  std::fprintf(csv,
               "case,formulation,integrator,jacobian,n,h,tolerance,status,wall_s,cpu_s,runs,rtf_cpu,steps,substeps,rejected,"
               "rhs,jacobians,probe_x,probe_y,err_pos_m,ref_spread_m,peak_T,rms_T,err_peak_rel,err_rms_rel,"
               "energy_drift,rk4_limit_h,us_per_step_per_rfe,reason\n");
  std::printf("\n| case | formulation | integrator | solve | n | h [s] | tol | CPU [s] | wall [s] | RTF (CPU) | "
              "position error [m] | peak T err | RMS T err | energy drift |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    const Ref& R = ref[c.name];
    for (const Config& k : sweep(c, quick, ns)) {
      const Result r = run(k, max_run);
      const bool ok = r.status == "ok";
      const double err = ok ? (r.m.probe - R.m.probe).norm() : NAN;
      const double ep = ok ? std::abs(r.m.peak - R.m.peak) / R.m.peak : NAN;
      const double er = ok ? std::abs(r.m.rms - R.m.rms) / R.m.rms : NAN;
      const double per = ok ? 1e6 * r.cpu / double(std::max(1L, r.steps)) / double(k.n + 1) : NAN;
      char tol[16] = "";
      if (k.integrator == "dopri5") std::snprintf(tol, sizeof(tol), "%.0e", k.tol);
      // The linear solve actually used (auto: structured on the chain formulations, dense on absolute).
      const bool implicit = riser_sim::isImplicitIntegrator(riser_sim::toChoice<riser_sim::IntegratorKind>(k.integrator));
      const std::string solve = !implicit ? "-" : k.jacobian != "auto" ? k.jacobian
                                : k.formulation == "absolute" ? "dense" : "structured";
      std::string reason = r.reason;
      for (char& ch : reason)
        if (ch == ',' || ch == '\n') ch = ';';
      std::fprintf(csv,
                   "%s,%s,%s,%s,%d,%.6g,%s,%s,%.6g,%.6g,%d,%.6g,%ld,%ld,%ld,%ld,%ld,%.9g,%.9g,%.6g,%.3g,%.6f,%.6f,%.6g,"
                   "%.6g,%.6g,%.6g,%.4g,%s\n",
                   c.name.c_str(), k.formulation.c_str(), k.integrator.c_str(), solve.c_str(), k.n, r.h, tol,
                   r.status.c_str(), r.wall, r.cpu, r.runs, ok ? c.duration / r.cpu : 0.0, r.steps, r.stats.substeps, r.stats.rejected,
                   r.stats.rhs, r.stats.jacobians, r.m.probe.x(), r.m.probe.y(), err, R.spread_pos, r.m.peak, r.m.rms,
                   ep, er, r.drift, r.limit, per, reason.c_str());
      std::fflush(csv);
      if (ok)
        std::printf("| %s | %s | %s | %s | %d | %.3g | %s | %.4f | %.4f | %.0f | %.2e | %.1e | %.1e | %.1e |\n",
                    c.name.c_str(), k.formulation.c_str(), k.integrator.c_str(), solve.c_str(), k.n, r.h, tol, r.cpu,
                    r.wall, c.duration / r.cpu, err, ep, er, r.drift);
      else
        std::printf("| %s | %s | %s | %s | %d | %.3g | %s | %s: %.70s |\n", c.name.c_str(), k.formulation.c_str(),
                    k.integrator.c_str(), solve.c_str(), k.n, r.h, tol, r.status.c_str(), reason.c_str());
      std::fflush(stdout);
    }
  }
  std::fclose(csv);
  std::printf("\nwrote %s/tradeoff.csv, %s/references.csv\n", out_dir.c_str(), out_dir.c_str());
  return 0;
}
