// riser_sim_bench_formulations: wall time per simulated second of the paper's Table 1 line (section 2.3:
// m_s = 1000 kg on L = 100 m, no bending, RK4, h = 1e-4 s) against n for the absolute, independent
// and recursive formulations; growth exponents by log-log least squares; a markdown table beside the
// paper's Table 1 times and a CSV.
//
//   riser_sim_bench_formulations [--runs N] [--target-wall S] [--clock cpu|wall] [--out FILE] [--quick]
//   riser_sim_bench_formulations --positions   (full 20 s runs, n = 10..50: x_s(20), y_s(20), ~4 min)
//
// Each timed run restarts from the static initial state and takes as many steps as fit in about
// --target-wall seconds (at most the full 20 s); the median of --runs runs is reported (thread CPU time
// by default: single-threaded, so equal to wall time on an idle machine; --clock wall for wall time).
// The dense independent formulation is O(n³): measured up to n = 100, scaled by n³ beyond (marked ~).
// Tables: printed and written to out/bench/tables/formulations.md, formulations_exponents.md (markdown_table.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "riser_sim/scene/scene.h"
#include "markdown_table.h"
#include "validation_util.h"

namespace {

using namespace riser_sim;

// The paper's Table 1 (20 s simulated at h = 1e-4 s) [s], n = 10, 20, 30, 40, 50, 100.
const int kPaperN[] = {10, 20, 30, 40, 50, 100};
const double kPaperAbsolute[] = {37, 60 + 23, 2 * 60 + 20, 3 * 60 + 30, 4 * 60 + 52, 14 * 60 + 23};
const double kPaperIndependent[] = {35, 3 * 60 + 18, 10 * 60 + 6, 23 * 60 + 13, 43 * 60 + 13, 5 * 3600 + 32 * 60 + 25};
constexpr double kSimDuration = 20.0;  // [s] the paper's run length
constexpr double kDt = 1e-4;           // [s] the paper's step
constexpr int kIndependentMaxN = 100;  // dense O(n³) solve: measured up to here, extrapolated beyond

Scene table1Scene(int n) { return validation::table1Scene(n, kDt); }

struct Row {
  std::string formulation;
  int n = 0;
  double per_step = 0.0;                           // median time per RK4 step on the reported clock [s]
  double wall_per_step = 0.0, cpu_per_step = 0.0;  // medians of both clocks [s]
  double dt = kDt;                                 // step used for the timing [s] (the paper's unless unstable there)
  long steps = 0;                                  // steps per timed run
  int runs = 0;
  bool measured = true;  // false: extrapolated from the fit
};

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

// CPU time of this thread [s]: the runs are single-threaded, so on an idle machine this equals the wall
// time, and on a shared one it is not inflated by other processes.
double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Times one formulation at one n; every run restarts from the same static state. The paper's
// h = 1e-4 s is beyond RK4's stability for the axial mode of short rfes (ω ≈ 4 sqrt(E/ρ) n / L:
// ω h ≈ 2.8 at n = 100); there h is halved until the run is stable and the cost per step is reported
// (it does not depend on h) together with the h used.
Row timeOne(const std::shared_ptr<Model>& model, const Scene& scene, const Kinematics& kin0, const std::string& f,
            int runs, double target_wall, bool use_wall) {
  SolverSettings settings = scene.solver;
  settings.formulation = riser_sim::toChoice<riser_sim::FormulationKind>(f);
  const long paper_steps = std::lround(kSimDuration / kDt);
  for (int halvings = 0; halvings < 12; ++halvings, settings.dt *= 0.5) {
    Simulator sim(model, buildTopMotion(scene.top), settings);
    // Calibrate: a few steps, then a longer probe, then as many steps as fit in target_wall.
    sim.setInitialState(kin0, 0.0);
    long probe = 20;
    auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < probe; ++k) sim.step();
    double per_step = seconds(std::chrono::steady_clock::now() - t0) / probe;
    if (per_step * 200 < target_wall) {
      probe = std::max<long>(200, long(0.1 * target_wall / per_step));
      t0 = std::chrono::steady_clock::now();
      for (long k = 0; k < probe; ++k) sim.step();
      per_step = seconds(std::chrono::steady_clock::now() - t0) / probe;
    }
    if (sim.diverged()) continue;
    const long steps = std::clamp<long>(long(target_wall / per_step), 10, paper_steps);
    std::vector<double> walls, cpus;
    bool diverged = false;
    for (int r = 0; r < runs && !diverged; ++r) {
      sim.setInitialState(kin0, 0.0);
      t0 = std::chrono::steady_clock::now();
      const double c0 = threadCpu();
      for (long k = 0; k < steps; ++k) sim.step();
      cpus.push_back(threadCpu() - c0);
      walls.push_back(seconds(std::chrono::steady_clock::now() - t0));
      diverged = sim.diverged();
    }
    if (diverged) continue;
    std::sort(walls.begin(), walls.end());
    std::sort(cpus.begin(), cpus.end());
    Row row;
    row.formulation = f;
    row.n = model->segments();
    row.per_step = (use_wall ? walls : cpus)[walls.size() / 2] / steps;
    row.wall_per_step = walls[walls.size() / 2] / steps;
    row.cpu_per_step = cpus[cpus.size() / 2] / steps;
    row.dt = settings.dt;
    row.steps = steps;
    row.runs = runs;
    return row;
  }
  throw std::runtime_error(f + " n = " + std::to_string(model->segments()) +
                           ": diverges even at h = " + std::to_string(settings.dt));
}

// Least-squares slope and intercept of log(t) against log(n).
struct Fit {
  double exponent = 0.0, log_c = 0.0;
  double at(double n) const { return std::exp(log_c + exponent * std::log(n)); }
};
Fit fitPowerLaw(const std::vector<double>& n, const std::vector<double>& t) {
  const int m = int(n.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < m; ++i) {
    const double x = std::log(n[i]), y = std::log(t[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  Fit f;
  f.exponent = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  f.log_c = (sy - f.exponent * sx) / m;
  return f;
}

// --positions: x_s(20), y_s(20) of the full Table 1 runs (h = 1e-4 s, 20 s) for n = 10..50.
const double kPaperXs[2][5] = {{-49.547, -49.551, -49.552, -49.552, -49.552},
                               {-49.549, -49.552, -49.553, -49.553, -49.553}};
const double kPaperYs[2][5] = {{-86.750, -86.763, -86.765, -86.765, -86.765},
                               {-86.750, -86.762, -86.765, -86.765, -86.765}};

int positionsTable(const std::vector<std::string>& forms, const std::string& out) {
  std::printf(
      "Table 1 end mass position after 20 s (h = %g s) [m]: paper (absolute; independent) and the three\n"
      "formulations here; last column: largest distance of independent/recursive from absolute.\n\n",
      kDt);
  std::printf(
      "| n | paper abs x_s, y_s | paper ind x_s, y_s | absolute | independent | recursive | max distance [m] |\n");
  std::printf("|---:|---|---|---|---|---|---:|\n");
  std::FILE* csv = std::fopen(out.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "riser_sim_bench_formulations: error: cannot write %s\n", out.c_str());
    return 1;
  }
  std::fprintf(csv, "n,formulation,x_s_20,y_s_20,seconds\n");
  const int ns[] = {10, 20, 30, 40, 50};
  for (int k = 0; k < 5; ++k) {
    const Scene scene = table1Scene(ns[k]);
    std::shared_ptr<Model> model = buildModel(scene);
    const StaticsResult st = solveStatics(*model, staticsProblem(scene), 0.0);
    if (!st.converged) {
      std::fprintf(stderr, "riser_sim_bench_formulations: error: statics for n = %d: %s\n", ns[k], st.message.c_str());
      return 3;
    }
    Vec2 end[3];
    for (int f = 0; f < 3; ++f) {
      SolverSettings settings = scene.solver;
      settings.formulation = riser_sim::toChoice<riser_sim::FormulationKind>(forms[f]);
      Simulator sim(model, buildTopMotion(scene.top), settings);
      sim.setInitialState(st.kin, 0.0);
      const auto t0 = std::chrono::steady_clock::now();
      if (!sim.advanceTo(kSimDuration)) {
        std::fprintf(stderr, "riser_sim_bench_formulations: error: %s n = %d: %s\n", forms[f].c_str(), ns[k],
                     sim.divergenceReason().c_str());
        return 3;
      }
      end[f] = sim.outputs().points.back();
      const double secs = seconds(std::chrono::steady_clock::now() - t0);
      std::fprintf(csv, "%d,%s,%.9f,%.9f,%.3f\n", ns[k], forms[f].c_str(), end[f].x(), end[f].y(), secs);
      std::fprintf(stderr, "  %-11s n = %d: (%.6f, %.6f) in %.1f s\n", forms[f].c_str(), ns[k], end[f].x(), end[f].y(),
                   secs);
    }
    const double d = std::max((end[1] - end[0]).norm(), (end[2] - end[0]).norm());
    std::printf("| %d | %.3f, %.3f | %.3f, %.3f | %.6f, %.6f | %.6f, %.6f | %.6f, %.6f | %.1e |\n", ns[k],
                kPaperXs[0][k], kPaperYs[0][k], kPaperXs[1][k], kPaperYs[1][k], end[0].x(), end[0].y(), end[1].x(),
                end[1].y(), end[2].x(), end[2].y(), d);
  }
  std::fclose(csv);
  std::fprintf(stderr, "wrote %s\n", out.c_str());
  return 0;
}

std::string clock(double s) {  // the paper's style: 37", 1'23", 5h32'25"
  char buf[64];
  if (s < 10.0) {
    std::snprintf(buf, sizeof buf, "%.2f\"", s);
  } else if (s < 60.0) {
    std::snprintf(buf, sizeof buf, "%.0f\"", s);
  } else if (s < 3600.0) {
    const long r = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld'%02ld\"", r / 60, r % 60);
  } else {
    const long r = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ldh%02ld'%02ld\"", r / 3600, (r / 60) % 60, r % 60);
  }
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  double target_wall = 0.5;
  std::string out = "out/bench/formulations.csv";
  bool quick = false, use_wall = false, positions = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "riser_sim_bench_formulations: error: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--runs") {
      runs = std::atoi(value().c_str());
    } else if (a == "--target-wall") {
      target_wall = std::atof(value().c_str());
    } else if (a == "--out") {
      out = value();
    } else if (a == "--quick") {
      quick = true;
    } else if (a == "--positions") {
      positions = true;
    } else if (a == "--clock") {
      const std::string c = value();
      if (c != "cpu" && c != "wall") {
        std::fprintf(stderr, "riser_sim_bench_formulations: error: --clock: '%s' (accepted: cpu, wall)\n", c.c_str());
        return 2;
      }
      use_wall = c == "wall";
    } else {
      std::fprintf(
          stderr,
          "usage: riser_sim_bench_formulations [--runs N>=1] [--target-wall S>0] [--clock cpu|wall] [--out FILE] "
          "[--quick] [--positions]\n");
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  if (runs < 1 || !(target_wall > 0.0)) {
    std::fprintf(stderr, "riser_sim_bench_formulations: error: --runs must be >= 1 and --target-wall > 0\n");
    return 2;
  }
  std::vector<int> ns = {10, 20, 30, 40, 50, 100, 200, 500, 1000};
  if (quick) ns = {10, 20, 50, 100, 200};
  const std::vector<std::string> forms = {"absolute", "independent", "recursive"};
  if (positions) {
    std::filesystem::path path(out);
    path.replace_filename("formulations_positions.csv");
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    return positionsTable(forms, path.string());
  }

  std::vector<Row> rows;
  for (int n : ns) {
    const Scene scene = table1Scene(n);
    std::shared_ptr<Model> model = buildModel(scene);
    const StaticsResult st = solveStatics(*model, staticsProblem(scene), 0.0);
    if (!st.converged) {
      std::fprintf(stderr, "riser_sim_bench_formulations: error: statics for n = %d: %s\n", n, st.message.c_str());
      return 3;
    }
    for (const std::string& f : forms) {
      if (f == "independent" && n > kIndependentMaxN) continue;
      try {
        rows.push_back(timeOne(model, scene, st.kin, f, runs, target_wall, use_wall));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "riser_sim_bench_formulations: error: %s\n", e.what());
        return 3;
      }
      const Row& r = rows.back();
      std::fprintf(stderr, "  %-11s n = %4d: %9.3f us CPU, %9.3f us wall per step, h = %g s (%ld steps x %d runs)\n",
                   f.c_str(), n, 1e6 * r.cpu_per_step, 1e6 * r.wall_per_step, r.dt, r.steps, r.runs);
    }
  }

  // Growth exponents over the measured points (cost per step, i.e. per simulated second at fixed h).
  Fit fit[3];
  int fit_max_n[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    std::vector<double> x, y;
    for (const Row& r : rows)
      if (r.formulation == forms[k] && r.measured) {
        x.push_back(r.n), y.push_back(r.per_step);
        fit_max_n[k] = std::max(fit_max_n[k], r.n);
      }
    fit[k] = fitPowerLaw(x, y);
  }
  std::vector<double> pn(std::begin(kPaperN), std::end(kPaperN));
  const Fit paper_abs = fitPowerLaw(pn, std::vector<double>(std::begin(kPaperAbsolute), std::end(kPaperAbsolute)));
  const Fit paper_ind =
      fitPowerLaw(pn, std::vector<double>(std::begin(kPaperIndependent), std::end(kPaperIndependent)));
  // Local exponent between the two largest measured n (the asymptotic order shows there).
  double local_p[3] = {0.0, 0.0, 0.0};
  const Row* last[3][2] = {{nullptr, nullptr}, {nullptr, nullptr}, {nullptr, nullptr}};
  for (int k = 0; k < 3; ++k) {
    for (const Row& r : rows)
      if (r.formulation == forms[k] && r.measured && (!last[k][1] || r.n > last[k][1]->n))
        last[k][0] = last[k][1], last[k][1] = &r;
    if (last[k][0])
      local_p[k] =
          std::log(last[k][1]->per_step / last[k][0]->per_step) / std::log(double(last[k][1]->n) / last[k][0]->n);
  }
  // Independent beyond kIndependentMaxN: the dense LDLT's n³ from the largest measured n.
  const Row* ind_last = last[1][1];
  for (int n : ns)
    if (n > kIndependentMaxN && ind_last) {
      Row r;
      r.formulation = "independent";
      r.n = n;
      r.per_step = ind_last->per_step * std::pow(double(n) / ind_last->n, 3.0);
      r.measured = false;
      r.runs = 0;
      rows.push_back(r);
    }

  auto find = [&](const std::string& f, int n) -> const Row* {
    for (const Row& r : rows)
      if (r.formulation == f && r.n == n) return &r;
    return nullptr;
  };
  const double paper_steps = kSimDuration / kDt;
  auto cell = [&](const std::string& f, int n) {
    const Row* r = find(f, n);
    if (!r) return std::string("–");
    return std::string(r->measured ? "" : "~") + clock(paper_steps * r->per_step) + (r->dt < kDt ? " *" : "");
  };

  const std::string command = riser_sim::bench::commandLine(argc, argv);
  riser_sim::bench::MarkdownTable table("formulations", command);
  riser_sim::bench::MarkdownTable exponents("formulations_exponents", command);
  table.printf(
      "Table 1 line (L = 100 m, m_s = 1000 kg, E = 1e11 Pa, no bending), RK4: %s time for %g s at\n"
      "h = %g s (%g steps), from the median of %d timed runs per cell (single thread; CPU time equals\n"
      "wall time on an idle machine). Paper: its Table 1 (2013 hardware, wall time).\n\n",
      use_wall ? "wall" : "CPU", kSimDuration, kDt, paper_steps, runs);
  table.printf(
      "| n | paper absolute | paper independent | absolute | independent | recursive | absolute / recursive |\n");
  table.printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : ns) {
    std::string pa = "–", pi = "–";
    for (int k = 0; k < 6; ++k)
      if (kPaperN[k] == n) pa = clock(kPaperAbsolute[k]), pi = clock(kPaperIndependent[k]);
    const Row* a = find("absolute", n);
    const Row* r = find("recursive", n);
    char ratio[32] = "–";
    if (a && r) std::snprintf(ratio, sizeof ratio, "%.2f", a->per_step / r->per_step);
    table.printf("| %d | %s | %s | %s | %s | %s | %s |\n", n, pa.c_str(), pi.c_str(), cell("absolute", n).c_str(),
                 cell("independent", n).c_str(), cell("recursive", n).c_str(), ratio);
  }
  table.printf("\n~ not run: the measured n = %d time scaled by (n/%d)^3 (dense LDLT).\n", kIndependentMaxN,
               kIndependentMaxN);
  table.printf(
      "\\* h = %g s is beyond RK4's stability for this line's axial mode at this n: timed at the largest\n"
      "  stable h = 1e-4/2^k (see the CSV's dt_s) and reported per %g steps (cost per step does not depend on h).\n",
      kDt, paper_steps);
  table.write();
  std::printf("\n");
  exponents.printf("Growth exponent p of time ~ n^p (log-log least squares over the measured n):\n\n");
  auto lastPair = [&](int k) {
    char buf[48] = "–";
    if (last[k][0]) std::snprintf(buf, sizeof buf, "%.2f (n = %d..%d)", local_p[k], last[k][0]->n, last[k][1]->n);
    return std::string(buf);
  };
  exponents.printf(
      "| formulation | measured p | n range | p at the two largest n | paper p (n = 10..100) |\n"
      "|---|---:|---|---|---:|\n");
  exponents.printf("| absolute | %.2f | %d..%d | %s | %.2f |\n", fit[0].exponent, ns.front(), fit_max_n[0],
                   lastPair(0).c_str(), paper_abs.exponent);
  exponents.printf("| independent | %.2f | %d..%d | %s | %.2f |\n", fit[1].exponent, ns.front(), fit_max_n[1],
                   lastPair(1).c_str(), paper_ind.exponent);
  exponents.printf("| recursive | %.2f | %d..%d | %s | – |\n", fit[2].exponent, ns.front(), fit_max_n[2],
                   lastPair(2).c_str());

  exponents.write();

  std::error_code ec;
  const std::filesystem::path path(out);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  std::FILE* csv = std::fopen(out.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "riser_sim_bench_formulations: error: cannot write %s\n", out.c_str());
    return 1;
  }
  std::fprintf(csv,
               "formulation,n,clock,us_per_step,time_for_20s_at_1e-4_s,cpu_us_per_step,wall_us_per_step,dt_s,measured,"
               "steps_per_run,runs,fit_exponent\n");
  for (const Row& r : rows) {
    const int k = int(std::find(forms.begin(), forms.end(), r.formulation) - forms.begin());
    std::fprintf(csv, "%s,%d,%s,%.6g,%.6g,%.6g,%.6g,%g,%d,%ld,%d,%.4f\n", r.formulation.c_str(), r.n,
                 use_wall ? "wall" : "cpu", 1e6 * r.per_step, paper_steps * r.per_step, 1e6 * r.cpu_per_step,
                 1e6 * r.wall_per_step, r.dt, r.measured ? 1 : 0, r.steps, r.runs, fit[k].exponent);
  }
  std::fclose(csv);
  std::fprintf(stderr, "wrote %s\n", out.c_str());
  return 0;
}
