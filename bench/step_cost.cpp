// riser_sim_bench_step_cost: cost of one step against n for each integrator x formulation x linear
// solve (is every step O(n)?), on three scenes: the 170 m J-lay with every hydro term it has
// (gravity, axial and bending springs, buoyancy, Morison drag, added mass, internal fluid mass and flow
// u = 5 m/s, seabed contact; n <= 300: its statics fail at n = 256, 320, 400, 500), the 500 m riser with
// drag, added mass and a 5 m/s internal flow, and the Table 1 line (no water). The static initial state
// is solved once per scene and n. Each configuration steps from it for about --target seconds of thread
// CPU time (at least 5 steps; the step count
// includes the implicit schemes' Jacobian work: structured = relinearised every step, dense = one
// finite-difference Jacobian + LU per solver.jacobian_interval (default 0.1 s = 10 steps of h = 0.01 s),
// timed over whole such periods; dopri5: per accepted substep);
// median of 3. The growth exponent is the log-log least-squares slope over the measured n.
// Writes <out>/step_cost.csv.
//
//   riser_sim_bench_step_cost [--out DIR] [--root DIR] [--target S] [--max-n N] [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "riser_sim/scene.h"
#include "riser_sim/scene_yaml.h"

namespace {

using namespace riser_sim;

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Config {
  const char* integrator;
  const char* formulation;
  const char* jacobian;  // auto | structured | dense
  double h;              // [s]; <= 0: -h x rk4's estimated limit
  int max_n;             // larger n are not measured (dense: O(p³) refresh)
};

// rk4's cost per step does not depend on h; it runs at 0.9x its limit so that the run stays finite.
const Config kConfigs[] = {
    {"rk4", "recursive", "auto", -0.9, 100000},
    {"rk4", "absolute", "auto", -0.9, 100000},
    {"dopri5", "recursive", "auto", 0.01, 100000},  // per accepted substep (their number depends on n)
    {"rosenbrock2", "recursive", "structured", 0.01, 100000},
    {"midpoint", "recursive", "structured", 0.01, 100000},
    {"generalized_alpha", "recursive", "structured", 0.01, 100000},
    {"rosenbrock2", "independent", "structured", 0.01, 200},  // O(n³) evaluations
    {"rosenbrock2", "recursive", "dense", 0.01, 400},
    {"midpoint", "recursive", "dense", 0.01, 400},
    {"rosenbrock2", "absolute", "dense", 0.01, 400},
};

Scene sceneOf(const std::string& which, const std::string& root, int n) {
  Scene s;
  if (which == "jlay") {
    s = loadSceneFile(root + "/config/scenes/paper_jlay_170m.yaml");
    s.internal_fluid.velocity = 5.0;  // the flow term too
  } else if (which == "riser500") {
    s = loadSceneFile(root + "/config/scenes/paper_riser_500m.yaml");
    s.internal_fluid.density = 840.0;
    s.internal_fluid.velocity = 5.0;
  } else {
    s.name = "table1";
    s.length = 100.0;
    s.line = LineProperties::fromGeometry(0.05, 0.0, 1e11, 2000.0);
    s.options.bending = false;
    s.end_mass = 1000.0;
    s.initial.type = InitialKind::kDisplaced;
    s.initial.end_dx = -50.0;
  }
  s.elements = n;
  return s;
}

// A scene at one n with its static state, shared by every configuration.
struct Prepared {
  Scene scene;
  std::shared_ptr<Model> model;
  Kinematics kin;
};

struct Timing {
  bool ok = false;
  double cpu_per_step = 0.0;  // [s]
  double h = 0.0;
  long steps = 0;
  std::string why;
};

std::unique_ptr<Simulator> simulator(const Prepared& p, const SolverSettings& settings) {
  auto sim = std::make_unique<Simulator>(p.model, buildTopMotion(p.scene.top), settings);
  sim->setInitialState(p.kin, 0.0);
  return sim;
}

Timing timeOnce(const Prepared& p, const Config& c, double target) {
  Timing t;
  SolverSettings settings = p.scene.solver;
  settings.integrator = riser_sim::toChoice<riser_sim::IntegratorKind>(c.integrator);
  settings.formulation = riser_sim::toChoice<riser_sim::FormulationKind>(c.formulation);
  settings.jacobian = riser_sim::toChoice<riser_sim::JacobianKind>(c.jacobian);
  settings.dt = c.h > 0.0 ? c.h : 1e-4;
  try {
    auto sim = simulator(p, settings);
    if (c.h <= 0.0) {
      settings.dt = -c.h * sim->stableStepEstimate();
      sim = simulator(p, settings);
    }
    t.h = settings.dt;
    // Dense: whole refresh periods (solver.jacobian_interval / h steps hold one Jacobian + LU).
    const long period = std::lround(settings.jacobian_interval / settings.dt);
    const long min_steps = std::string(c.jacobian) == "dense" ? std::max(5L, period) : 5;
    const double c0 = threadCpu();
    double used = 0.0;
    while ((used < target || t.steps < min_steps) && t.steps < 100000) {
      if (!sim->step()) {
        t.why = sim->divergenceReason();
        return t;
      }
      ++t.steps;
      used = threadCpu() - c0;
    }
    // dopri5: per accepted substep (its output step holds many).
    const long substeps = sim->integrator().stats().substeps;
    t.cpu_per_step = used / double(std::string(c.integrator) == "dopri5" ? std::max(1L, substeps) : t.steps);
    t.ok = true;
  } catch (const std::exception& e) {
    t.why = e.what();
  }
  return t;
}

// Least-squares slope of log y against log x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const int m = int(x.size());
  if (m < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < m; ++i) {
    const double a = std::log(x[i]), b = std::log(y[i]);
    sx += a, sy += b, sxx += a * a, sxy += a * b;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "out/bench", root = ".";
  double target = 0.3;
  int max_n = 1000;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--out") && more) out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--root") && more) root = argv[++i];
    else if (!std::strcmp(argv[i], "--target") && more) target = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--max-n") && more) max_n = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else {
      std::fprintf(stderr, "usage: riser_sim_bench_step_cost [--out DIR] [--root DIR] [--target S] [--max-n N] "
                           "[--quick]\n");
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
  }
  std::vector<int> ns = {10, 20, 40, 100, 200, 400, 1000};
  if (quick) ns = {10, 40, 100};
  std::filesystem::create_directories(out_dir);
  std::FILE* csv = std::fopen((out_dir + "/step_cost.csv").c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "cannot write into %s\n", out_dir.c_str());
    return 1;
  }
  std::fprintf(csv, "scene,integrator,formulation,jacobian,n,h,steps,cpu_us_per_step,us_per_step_per_rfe\n");
  const int kConfigs_n = int(sizeof(kConfigs) / sizeof(kConfigs[0]));
  std::printf("Cost of one step (thread CPU time, median of 3; the machine may be shared), growth exponent "
              "over n (J-lay: the n = 400 column is n = 300, its statics limit):\n\n| scene | integrator / formulation / solve | h [s] | ");
  for (int n : ns) std::printf("n = %d | ", n);
  std::printf("exponent |\n|---|---|---|");
  for (size_t k = 0; k < ns.size(); ++k) std::printf("---|");
  std::printf("---|\n");
  for (const char* which : {"jlay", "riser500", "table1"}) {
    const int scene_max_n = std::string(which) == "jlay" ? 300 : max_n;
    // cost[config][n index] (0: not measured, < 0: failed)
    std::vector<std::vector<double>> cost(kConfigs_n, std::vector<double>(ns.size(), 0.0));
    for (size_t j = 0; j < ns.size(); ++j) {
      const int n = std::min(ns[j], scene_max_n);
      if (ns[j] > scene_max_n && (j == 0 || ns[j - 1] >= scene_max_n)) continue;
      Prepared p;
      p.scene = sceneOf(which, root, n);
      p.model = buildModel(p.scene);
      const StaticsResult st = solveStatics(*p.model, staticsProblem(p.scene), 0.0);
      if (!st.converged) {
        std::fprintf(stderr, "%s n = %d: %s\n", which, n, st.message.c_str());
        continue;
      }
      p.kin = st.kin;
      for (int k = 0; k < kConfigs_n; ++k) {
        const Config& c = kConfigs[k];
        if (n > c.max_n || n > max_n) continue;
        std::vector<double> per;
        Timing last;
        for (int r = 0; r < 3; ++r) {
          last = timeOnce(p, c, target);
          if (!last.ok) break;
          per.push_back(last.cpu_per_step);
        }
        if (!last.ok) {
          cost[k][j] = -1.0;
          std::fprintf(stderr, "%s %s/%s/%s n = %d: %s\n", which, c.integrator, c.formulation, c.jacobian, n,
                       last.why.c_str());
          continue;
        }
        std::sort(per.begin(), per.end());
        const double med = per[per.size() / 2];
        cost[k][j] = med;
        std::fprintf(csv, "%s,%s,%s,%s,%d,%.6g,%ld,%.6g,%.6g\n", which, c.integrator, c.formulation, c.jacobian, n,
                     last.h, last.steps, 1e6 * med, 1e6 * med / (n + 1));
        std::fflush(csv);
      }
      ns[j] = n;  // the jlay cap: the column shows the n measured
    }
    for (int k = 0; k < kConfigs_n; ++k) {
      const Config& c = kConfigs[k];
      std::vector<double> xs, ys;
      std::printf("| %s | %s / %s / %s | %s | ", which, c.integrator, c.formulation, c.jacobian,
                  c.h > 0 ? std::to_string(c.h).substr(0, 4).c_str() : "0.9x limit");
      for (size_t j = 0; j < ns.size(); ++j) {
        if (cost[k][j] == 0.0) std::printf("- | ");
        else if (cost[k][j] < 0.0) std::printf("failed | ");
        else {
          std::printf("%.3g us | ", 1e6 * cost[k][j]);
          xs.push_back(ns[j] + 1);
          ys.push_back(cost[k][j]);
        }
      }
      std::printf("%.2f |\n", slope(xs, ys));
    }
    std::fflush(stdout);
    ns = quick ? std::vector<int>{10, 40, 100} : std::vector<int>{10, 20, 40, 100, 200, 400, 1000};
  }
  std::fclose(csv);
  std::printf("\nwrote %s/step_cost.csv\n", out_dir.c_str());
  return 0;
}
