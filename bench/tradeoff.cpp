// riser_sim_bench_tradeoff: speed against accuracy. For each case (bench/tradeoff_cases.cpp:
// the paper's Table 1 line elastic and inextensible, the 170 m J-lay elastic and inextensible, the 500 m
// riser; and the 3D swing of tradeoff_spatial.h with its own table and tradeoff_spatial.csv) it first computes the
// references, then sweeps integrator x formulation x n x h (or tolerance) and measures each run against them: the probe
// point's position at the end of the run, the histories of the top tension and of the largest axial force every 0.1 s
// (tradeoff_history.h: RMS and max error against the reference's), the energy-balance error, wall and thread-CPU time
// (median of 3 for runs under 2 s). Runs predicted to exceed --max-run seconds are skipped and listed as such. The
// references' own convergence (each coarser reference run against the finest) is printed and written too. Writes
// <out>/tradeoff.csv and <out>/references.csv; prints tables. bench/plot_tradeoff.py draws the Pareto plots and picks
// the cheapest setting per accuracy target.
//
//   riser_sim_bench_tradeoff [--quick] [--out DIR] [--cases a,b] [--ns a,b] [--max-run S] [--root DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "riser_sim/integrators/integrator.h"
#include "tradeoff_run.h"
#include "tradeoff_spatial.h"

namespace {

using namespace tradeoff;

// How a scheme is swept (per n, on the recursive formulation unless said otherwise).
enum class Sweep {
  kStabilityLimit,  // explicit fixed step: 0.9x and 0.3x its estimated limit, 0.9x on absolute (n <= 100);
                    // inextensible lines also h = 0.05, 0.02, 0.01 s
  kTolerance,       // adaptive: tolerance 1e-4, 1e-6, 1e-8 (output step 10 ms)
  kImplicitSteps,   // implicit: h = 0.1, 0.05, 0.03 .. 0.002 s with the structured solves; n <= 40 also the dense
                    // Jacobian (h = 0.02, 0.005 s) and the absolute formulation (h = 0.01, 0.002 s)
};

struct Scheme {
  const char* integrator;  // a name of riser_sim::Choices<IntegratorKind>
  Sweep sweep;
  double rho_inf = NAN;  // solver.rho_inf of a scheme that has it (Config::rho_inf)
};

// The integrators swept, one line each; a new scheme is one more line. A name of the integrator table missing here is
// reported at the start (not swept).
const std::vector<Scheme> kSchemes = {
    {"rk4", Sweep::kStabilityLimit},
    {"dopri5", Sweep::kTolerance},
    {"rosenbrock2", Sweep::kImplicitSteps},
    {"midpoint", Sweep::kImplicitSteps},
    {"generalized_alpha", Sweep::kImplicitSteps, 0.5},
    {"generalized_alpha", Sweep::kImplicitSteps, 0.0},
};

void checkSchemes() {
  for (const Scheme& s : kSchemes) riser_sim::toChoice<riser_sim::IntegratorKind>(s.integrator);  // throws
  for (const auto& entry : riser_sim::Choices<riser_sim::IntegratorKind>::names) {
    const bool listed = std::any_of(kSchemes.begin(), kSchemes.end(),
                                    [&](const Scheme& s) { return std::string(s.integrator) == entry.second; });
    if (!listed)
      std::printf("warning: integrator '%s' is not in kSchemes (bench/tradeoff.cpp): not swept\n", entry.second);
  }
}

std::string schemeLabel(const std::string& integrator, double rho_inf) {
  if (std::isnan(rho_inf)) return integrator;
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s rho_inf=%g", integrator.c_str(), rho_inf);
  return buf;
}

struct Ref {
  Measures m;
  // The reference's own convergence: the largest difference of a coarser reference run to the finest.
  double spread_pos = 0.0;  // probe distance [m]
  HistoryError spread_top{0.0, 0.0}, spread_axial{0.0, 0.0};
  std::string source;
};

HistoryError worse(const HistoryError& a, const HistoryError& b) {
  return {std::max(a.rms, b.rms), std::max(a.max, b.max)};
}

// References of one case: the reference runs (no budget), the last one is the reference; each coarser
// run's probe distance and force-history errors against it are printed and written to references.csv.
Ref reference(const Case& c, std::FILE* csv) {
  Ref ref;
  std::vector<Result> rs;
  if (!c.note.empty()) std::printf("  %-20s %s\n", c.name.c_str(), c.note.c_str());
  for (const Case::RefRun& rr : c.ref_runs) {
    const Result r = run({&c, "recursive", rr.integrator, rr.n, rr.h, 0.0}, 0.0, 0.0);
    std::printf("  %-20s reference run: n = %d, %s, h = %.3g s: %s, %.1f s CPU\n", c.name.c_str(), rr.n,
                rr.integrator.c_str(), r.h, r.status.c_str(), r.cpu);
    std::fflush(stdout);
    if (r.status != "ok") throw std::runtime_error(c.name + ": reference run " + r.status + ": " + r.reason);
    rs.push_back(r);
  }
  const Result& last = rs.back();
  ref.m = last.m;
  std::printf(
      "\n  | %s: reference run | CPU [s] | probe to finest [mm] | top T RMS | top T max | max axial RMS | "
      "max axial max | peak top T [N] |\n  |---|---|---|---|---|---|---|---|\n",
      c.name.c_str());
  for (size_t k = 0; k < rs.size(); ++k) {
    const Result& r = rs[k];
    const Case::RefRun& rr = c.ref_runs[k];
    const double dpos = (r.m.probe - last.m.probe).norm();
    const HistoryError et = historyError(r.m.top_tension, last.m.top_tension);
    const HistoryError ea = historyError(r.m.max_axial, last.m.max_axial);
    if (k + 1 < rs.size()) {
      ref.spread_pos = std::max(ref.spread_pos, dpos);
      ref.spread_top = worse(ref.spread_top, et);
      ref.spread_axial = worse(ref.spread_axial, ea);
    }
    std::printf("  | %s, n = %d, h = %.3g s%s | %.1f | %.3g | %.2e | %.2e | %.2e | %.2e | %.0f |\n",
                rr.integrator.c_str(), rr.n, r.h, k + 1 == rs.size() ? " (reference)" : "", r.cpu, 1e3 * dpos, et.rms,
                et.max, ea.rms, ea.max, r.m.peak());
    std::fprintf(csv, "%s,%d,%s,%.6g,%s,%.9g,%.9g,%.6f,%.6f,%.3f,%.6g,%.6g,%.6g,%.6g,%.6g\n", c.name.c_str(), rr.n,
                 rr.integrator.c_str(), r.h, r.status.c_str(), r.m.probe.x(), r.m.probe.y(), r.m.peak(), r.m.rms(),
                 r.cpu, dpos, et.rms, et.max, ea.rms, ea.max);
  }
  std::ostringstream src;
  src << c.ref_runs.back().integrator << ", n = " << c.ref_runs.back().n << ", h = " << last.h << " s";
  ref.source = src.str();
  if (c.fixed_probe) {
    ref.m.probe = c.probe_ref;
    ref.spread_pos = c.probe_spread;
    ref.source = c.probe_source;
  }
  std::printf("\n  %-20s reference: probe (%.6f, %.6f) ± %.2g m (%s); forces: %s, n = %d, h = %.3g s (grid %g s)\n\n",
              c.name.c_str(), ref.m.probe.x(), ref.m.probe.y(), ref.spread_pos, ref.source.c_str(),
              c.ref_runs.back().integrator.c_str(), c.ref_runs.back().n, last.h, kHistoryDt);
  std::fflush(stdout);
  return ref;
}

// The runs of one case: per n, per scheme of kSchemes.
std::vector<Config> sweep(const Case& c, bool quick, const std::string& ns) {
  const bool axial = c.scene(10).options.axial_flexibility;
  std::vector<Config> cfg;
  const std::vector<double> hs = {0.1, 0.05, 0.03, 0.02, 0.01, 0.005, 0.002};
  for (int n : c.ns) {
    if (quick && n > 20) continue;
    if (!ns.empty() && ns.find("," + std::to_string(n) + ",") == std::string::npos) continue;
    for (const Scheme& s : kSchemes) {
      auto add = [&](const char* form, double h, double tol = 0.0, const char* jac = "auto") {
        cfg.push_back({&c, form, s.integrator, n, h, tol, jac, s.rho_inf});
      };
      switch (s.sweep) {
        case Sweep::kStabilityLimit:
          for (double k : {-0.9, -0.3}) add("recursive", k);
          if (n <= 100) add("absolute", -0.9);  // the paper's formulation
          if (!axial)
            for (double h : {0.05, 0.02, 0.01}) add("recursive", h);
          break;
        case Sweep::kTolerance:
          for (double tol : {1e-4, 1e-6, 1e-8}) add("recursive", 0.01, tol);
          break;
        case Sweep::kImplicitSteps:
          for (double h : hs) add("recursive", h);  // structured O(n) solves
          if (n <= 40)                              // the dense finite-difference Jacobian: same accuracy, cost O(p²)
            for (double h : {0.02, 0.005}) add("recursive", h, 0.0, "dense");
          if (n <= 40)  // absolute: dense Jacobian only, Baumgarte-held joints
            for (double h : {0.01, 0.002}) add("absolute", h);
          break;
      }
    }
  }
  return cfg;
}

}  // namespace

int runBench(int argc, char** argv) {
  bool quick = false;
  std::string out_dir = "out/bench", root = ".", only, ns;
  double max_run = 20.0;
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--out") && more)
      out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--root") && more)
      root = argv[++i];
    else if (!std::strcmp(argv[i], "--cases") && more)
      only = std::string(",") + argv[++i] + ",";
    else if (!std::strcmp(argv[i], "--max-run") && more)
      max_run = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--ns") && more)
      ns = std::string(",") + argv[++i] + ",";
    else {
      const bool help = !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h");
      std::string names;
      for (const Case& c : allCases(root)) names += (names.empty() ? "" : ", ") + c.name;
      names += ", spatial_swing (3D, n = 5, 10, 20)";
      std::fprintf(help ? stdout : stderr,
                   "usage: riser_sim_bench_tradeoff [--quick] [--out DIR] [--cases a,b] [--ns 10,20] [--max-run S] "
                   "[--root DIR]\n"
                   "  --quick      n <= 20 only\n"
                   "  --ns a,b     only these n (of 10, 20, 40, 100, 200, 1000)\n"
                   "  --out DIR    tradeoff.csv and references.csv go here (default out/bench)\n"
                   "  --cases a,b  only these cases (%s)\n"
                   "  --max-run S  skip a run predicted to take more than S s of CPU time (default 20)\n"
                   "  --root DIR   repository root (scene files; default .)\n",
                   names.c_str());
      return help ? 0 : 2;
    }
  }
  checkSchemes();
  std::filesystem::create_directories(out_dir);
  std::vector<Case> cases;
  for (const Case& c : allCases(root))
    if (only.empty() || only.find("," + c.name + ",") != std::string::npos) cases.push_back(c);
  // The 3D case (tradeoff_spatial.h) has its own sweep and table, first.
  const bool spatial = only.empty() || only.find(",spatial_swing,") != std::string::npos;
  if (cases.empty() && !spatial) {
    std::fprintf(stderr, "no case selected (--cases)\n");
    return 2;
  }
  if (spatial) {
    std::vector<int> ns3;
    for (const int n : {5, 10, 20})
      if ((ns.empty() || ns.find("," + std::to_string(n) + ",") != std::string::npos) && !(quick && n > 10))
        ns3.push_back(n);
    spatial3::sweep3(root, out_dir, ns3);
    std::printf("\nwrote %s/tradeoff_spatial.csv\n", out_dir.c_str());
    if (cases.empty()) return 0;
  }

  std::FILE* refs = std::fopen((out_dir + "/references.csv").c_str(), "w");
  std::FILE* csv = std::fopen((out_dir + "/tradeoff.csv").c_str(), "w");
  if (!refs || !csv) {
    std::fprintf(stderr, "cannot write into %s\n", out_dir.c_str());
    return 1;
  }
  // Force-history errors against the finest reference run (grid kHistoryDt; tradeoff_history.h).
  std::fprintf(refs,
               "case,n,integrator,h,status,probe_x,probe_y,peak_T,rms_T,cpu_s,dist_pos_m,err_top_rms,"
               "err_top_max,err_axial_rms,err_axial_max\n");
  std::printf("references (recursive formulation; force histories every %g s, errors against the last run):\n",
              kHistoryDt);
  std::map<std::string, Ref> ref;
  for (const Case& c : cases) {
    ref[c.name] = reference(c, refs);
    std::fflush(refs);
  }
  std::fclose(refs);

  // err_top_*: top tension, err_axial_*: largest axial force, history errors (rms, max) against the
  // reference; ref_*: the reference's own convergence (largest error of a coarser reference run).
  std::fprintf(csv,
               "case,formulation,integrator,rho_inf,jacobian,n,h,tolerance,status,wall_s,cpu_s,runs,rtf_cpu,steps,"
               "substeps,rejected,rhs,jacobians,probe_x,probe_y,err_pos_m,ref_spread_m,peak_T,rms_T,err_top_rms,"
               "err_top_max,err_axial_rms,err_axial_max,ref_top_rms,ref_top_max,ref_axial_rms,ref_axial_max,"
               "energy_drift,rk4_limit_h,us_per_step_per_rfe,reason\n");
  std::printf(
      "\nforce errors: RMS = rms(T - Tref) / rms(Tref), max = max|T - Tref| / max|Tref| on the %g s grid\n"
      "\n| case | formulation | integrator | solve | n | h [s] | tol | CPU [s] | wall [s] | RTF (CPU) | "
      "position error [m] | top T RMS | top T max | max axial RMS | max axial max | energy drift |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      kHistoryDt);
  for (const Case& c : cases) {
    const Ref& R = ref[c.name];
    for (const Config& k : sweep(c, quick, ns)) {
      const Result r = run(k, max_run);
      const bool ok = r.status == "ok";
      const double err = ok ? (r.m.probe - R.m.probe).norm() : NAN;
      const HistoryError et = ok ? historyError(r.m.top_tension, R.m.top_tension) : HistoryError{};
      const HistoryError ea = ok ? historyError(r.m.max_axial, R.m.max_axial) : HistoryError{};
      const double per = ok ? 1e6 * r.cpu / double(std::max(1L, r.steps)) / double(k.n + 1) : NAN;
      char tol[16] = "", rho[16] = "";
      if (k.integrator == "dopri5") std::snprintf(tol, sizeof(tol), "%.0e", k.tol);
      if (!std::isnan(k.rho_inf)) std::snprintf(rho, sizeof(rho), "%g", k.rho_inf);
      const std::string integ = schemeLabel(k.integrator, k.rho_inf);
      // The linear solve actually used (auto: structured on the chain formulations, dense on absolute).
      const bool implicit =
          riser_sim::isImplicitIntegrator(riser_sim::toChoice<riser_sim::IntegratorKind>(k.integrator));
      const std::string solve = !implicit                     ? "-"
                                : k.jacobian != "auto"        ? k.jacobian
                                : k.formulation == "absolute" ? "dense"
                                                              : "structured";
      std::string reason = r.reason;
      for (char& ch : reason)
        if (ch == ',' || ch == '\n') ch = ';';
      std::fprintf(csv,
                   "%s,%s,%s,%s,%s,%d,%.6g,%s,%s,%.6g,%.6g,%d,%.6g,%ld,%ld,%ld,%ld,%ld,%.9g,%.9g,%.6g,%.3g,%.6f,%.6f,"
                   "%.6g,%.6g,%.6g,%.6g,%.3g,%.3g,%.3g,%.3g,%.6g,%.6g,%.4g,%s\n",
                   c.name.c_str(), k.formulation.c_str(), k.integrator.c_str(), rho, solve.c_str(), k.n, r.h, tol,
                   r.status.c_str(), r.wall, r.cpu, r.runs, ok ? c.duration / r.cpu : 0.0, r.steps, r.stats.substeps,
                   r.stats.rejected, r.stats.rhs, r.stats.jacobians, r.m.probe.x(), r.m.probe.y(), err, R.spread_pos,
                   r.m.peak(), r.m.rms(), et.rms, et.max, ea.rms, ea.max, R.spread_top.rms, R.spread_top.max,
                   R.spread_axial.rms, R.spread_axial.max, r.drift, r.limit, per, reason.c_str());
      std::fflush(csv);
      if (ok)
        std::printf(
            "| %s | %s | %s | %s | %d | %.3g | %s | %.4f | %.4f | %.0f | %.2e | %.1e | %.1e | %.1e | %.1e | %.1e |\n",
            c.name.c_str(), k.formulation.c_str(), integ.c_str(), solve.c_str(), k.n, r.h, tol, r.cpu, r.wall,
            c.duration / r.cpu, err, et.rms, et.max, ea.rms, ea.max, r.drift);
      else
        std::printf("| %s | %s | %s | %s | %d | %.3g | %s | %s: %.70s |\n", c.name.c_str(), k.formulation.c_str(),
                    integ.c_str(), solve.c_str(), k.n, r.h, tol, r.status.c_str(), reason.c_str());
      std::fflush(stdout);
    }
  }
  std::fclose(csv);
  std::printf("\nwrote %s/tradeoff.csv, %s/references.csv\n", out_dir.c_str(), out_dir.c_str());
  return 0;
}

int main(int argc, char** argv) {
  try {
    return runBench(argc, argv);
  } catch (const std::exception& e) {  // a bad Config or a failed reference run
    std::fprintf(stderr, "riser_sim_bench_tradeoff: %s\n", e.what());
    return 1;
  }
}
