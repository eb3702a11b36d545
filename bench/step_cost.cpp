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
// 3D against 2D (spatialRows, also alone with --spatial): the same planar line (100 m, axial and bending
// springs with damping, an end mass, released 20 degrees off the vertical under a swaying top) stepped by
// the planar Simulator and by the 3D Simulator3 (the line in the x-z plane), n = 10, 100, 300, 1000:
// rk4 (2D absolute) at half the planar rk4 limit, and implicit midpoint with structured solves (2D
// recursive) at h = 1e-3 s. The two are interleaved in blocks of steps (thread CPU time), medians over
// the blocks, the ratio's spread over repeats; growth exponents over n = 100..1000. The 3D steps are then timed
// again alone (the same steps from the start, no planar run between the blocks): the growth exponent of the
// 3D step itself, without the planar run's data evicting the 3D run's from the caches at every block.
// Writes <out>/step_cost_3d.csv.
//
// The shipped scenes against a saved baseline (step_cost_check.h): --save-baseline writes
// out/bench/step_cost_baseline.csv (--baseline FILE), --compare prints the ratio and a verdict per scene
// (unchanged within --tolerance, default 3 %) and writes the table step_cost_check.
//
//   riser_sim_bench_step_cost [--out DIR] [--root DIR] [--target S] [--max-n N] [--quick] [--spatial]
//   riser_sim_bench_step_cost --save-baseline|--compare [--baseline FILE] [--scenes a,b] [--rounds K]
//                             [--target S] [--tolerance F] [--fail-on-change] [--root DIR]
// Tables: printed and written to out/bench/tables/step_cost.md, step_cost_3d.md (markdown_table.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "riser_sim/planar/forces/axial_spring.h"
#include "riser_sim/planar/forces/bending_spring.h"
#include "riser_sim/planar/forces/gravity.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/planar/simulator.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/simulator.h"
#include "markdown_table.h"
#include "step_cost_check.h"

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

// ---- 3D against 2D on one planar line ----

struct Line3 {
  LineProperties props;
  ModelOptions options;
  double length = 100.0, end_mass = 500.0, g = 9.81;
};

Line3 line3() {
  Line3 l;
  l.props.mass_per_length = 10.0;
  l.props.EA = 1e7;
  l.props.EI = 1e4;
  l.props.axial_damping = 1e4;
  l.props.bending_damping = 100.0;
  return l;
}

std::unique_ptr<TopMotion> sway() {
  return std::make_unique<SinusoidMotion>(Vec2(-1.0, 0.0), Vec2(1.0, 0.0), 10.0, 0.0);
}

// Straight line from the top at 20 degrees from straight down, at rest.
Kinematics released(const Model& m) {
  Kinematics kin(m.bodies());
  const double phi = -M_PI / 2 + 20.0 * M_PI / 180.0;
  Vec2 A = Vec2::Zero();
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = A;
    b.phi = phi;
    b.c = std::cos(phi);
    b.s = std::sin(phi);
    b.len = m.rfe(i).length;
    A = b.end();
  }
  return kin;
}

struct Pair3 {
  double us2 = 0.0, us3 = 0.0, ratio = 0.0, ratio_lo = 0.0, ratio_hi = 0.0, h = 0.0, newton2 = 0.0, newton3 = 0.0;
  double us3_alone = 0.0;  // the 3D run again over the same steps, alone (no planar run between its blocks)
  bool ok = false;
  std::string why;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One (n, integrator): planar Simulator and Simulator3 on the same line, blocks of steps interleaved.
Pair3 timePair(int n, bool implicit, double target) {
  Pair3 r;
  const Line3 l = line3();
  auto m2 = std::make_shared<Model>(l.length, n, l.props, l.options, l.end_mass, l.g);
  m2->addTerm(std::make_unique<Gravity>());
  m2->addTerm(std::make_unique<AxialSpring>());
  m2->addTerm(std::make_unique<BendingSpring>());
  auto m3 = std::make_shared<spatial::Model3>(l.length, n, l.props, l.options, l.end_mass, spatial::Vec3(0, 0, -l.g));
  m3->addTerm(std::make_unique<spatial::Gravity>());
  m3->addTerm(std::make_unique<spatial::AxialSpring>());
  m3->addTerm(std::make_unique<spatial::BendingSpring>());
  const Kinematics kin0 = released(*m2);
  SolverSettings st;
  st.integrator = implicit ? IntegratorKind::kMidpoint : IntegratorKind::kRk4;
  st.formulation = implicit ? FormulationKind::kRecursive : FormulationKind::kAbsolute;
  st.jacobian = implicit ? JacobianKind::kStructured : JacobianKind::kAuto;
  st.dt = 1e-3;
  try {
    if (!implicit) {
      Simulator probe(m2, sway(), st);
      probe.setInitialState(kin0, 0.0);
      st.dt = 0.5 * probe.stableStepEstimate();
    }
    r.h = st.dt;
    Simulator sim2(m2, sway(), st);
    sim2.setInitialState(kin0, 0.0);
    IntegratorOptions o;
    o.jacobian = JacobianKind::kStructured;
    spatial::Simulator3 sim3(m3, std::make_unique<spatial::PlanarMotion3>(sway()), st.integrator, o);
    sim3.reset(spatial::fromPlanar(kin0), 0.0);
    // Warm-up, then the block length from the cost of one step of each.
    double c0 = threadCpu();
    for (int k = 0; k < 3; ++k)
      if (!sim2.step()) throw std::runtime_error("2D: " + sim2.divergenceReason());
    const double w2 = (threadCpu() - c0) / 3;
    c0 = threadCpu();
    for (int k = 0; k < 3; ++k)
      if (!sim3.step(st.dt)) throw std::runtime_error("3D: step failed");
    const double w3 = (threadCpu() - c0) / 3;
    const int blocks = 15;
    const long per = std::max(3L, std::lround(target / blocks / (w2 + w3)));
    std::vector<double> t2, t3, ratio;
    const long newton2 = sim2.integrator().stats().newton, newton3 = sim3.integrator().stats().newton;
    for (int b = 0; b < blocks; ++b) {
      c0 = threadCpu();
      for (long k = 0; k < per; ++k)
        if (!sim2.step()) throw std::runtime_error("2D: " + sim2.divergenceReason());
      const double c1 = threadCpu();
      for (long k = 0; k < per; ++k)
        if (!sim3.step(st.dt)) throw std::runtime_error("3D: step failed");
      const double c2 = threadCpu();
      t2.push_back((c1 - c0) / per);
      t3.push_back((c2 - c1) / per);
      ratio.push_back(t3.back() / t2.back());
    }
    if (!sim3.state().allFinite()) throw std::runtime_error("3D: state not finite");
    const double steps = double(blocks * per);
    r.newton2 = double(sim2.integrator().stats().newton - newton2) / steps;
    r.newton3 = double(sim3.integrator().stats().newton - newton3) / steps;
    r.us2 = 1e6 * median(t2);
    r.us3 = 1e6 * median(t3);
    // The same 3D steps from the start again with nothing between the blocks: the interleaving keeps the
    // ratio robust to the machine's load drifting, but each block then starts with the planar run's data in
    // the caches, which at n = 1000 (3D data ~3.5 MB, beyond the 2 MB L2) costs the 3D step 5-15 %.
    spatial::Simulator3 alone(m3, std::make_unique<spatial::PlanarMotion3>(sway()), st.integrator, o);
    alone.reset(spatial::fromPlanar(kin0), 0.0);
    for (int k = 0; k < 3; ++k)
      if (!alone.step(st.dt)) throw std::runtime_error("3D alone: step failed");
    std::vector<double> t3a;
    for (int b = 0; b < blocks; ++b) {
      c0 = threadCpu();
      for (long k = 0; k < per; ++k)
        if (!alone.step(st.dt)) throw std::runtime_error("3D alone: step failed");
      t3a.push_back((threadCpu() - c0) / per);
    }
    r.us3_alone = 1e6 * median(t3a);
    r.ratio = r.us3 / r.us2;
    std::sort(ratio.begin(), ratio.end());
    r.ratio_lo = ratio[blocks / 4];
    r.ratio_hi = ratio[(3 * blocks) / 4];
    r.ok = true;
  } catch (const std::exception& e) {
    r.why = e.what();
  }
  return r;
}

void spatialRows(const std::string& out_dir, double target, int max_n, bool quick, const std::string& command) {
  bench::MarkdownTable t("step_cost_3d", command);
  std::vector<int> ns = {10, 100, 300, 1000};
  if (quick) ns = {10, 100};
  std::FILE* csv = std::fopen((out_dir + "/step_cost_3d.csv").c_str(), "w");
  if (csv)
    std::fprintf(csv,
                 "integrator,n,h,us_per_step_2d,us_per_step_3d,ratio,ratio_q1,ratio_q3,newton_2d,newton_3d,"
                 "us_per_step_3d_alone\n");
  std::printf("\n");
  t.printf(
      "3D against 2D, the same planar line (thread CPU time per step, interleaved blocks, medians; ratio "
      "3D/2D with its quartiles over the blocks; Newton iterations per step 2D / 3D; 3D alone: the same 3D "
      "steps run again with no planar run between its blocks):\n\n| integrator | n | h [s] | 2D [us] | "
      "3D [us] | ratio | ratio q1..q3 | Newton | 3D alone [us] |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const bool implicit : {false, true}) {
    const char* name = implicit ? "midpoint structured (2D recursive)" : "rk4 (2D absolute)";
    std::vector<double> xs, y2, y3, y3a;
    for (int n : ns) {
      if (n > max_n) continue;
      const Pair3 r = timePair(n, implicit, std::max(target, 0.5));
      if (!r.ok) {
        t.printf("| %s | %d | - | failed: %s | | | | | |\n", name, n, r.why.c_str());
        continue;
      }
      t.printf("| %s | %d | %.3g | %.3g | %.3g | %.2f | %.2f..%.2f | %.2f / %.2f | %.3g |\n", name, n, r.h, r.us2,
               r.us3, r.ratio, r.ratio_lo, r.ratio_hi, r.newton2, r.newton3, r.us3_alone);
      std::fflush(stdout);
      if (csv)
        std::fprintf(csv, "%s,%d,%.6g,%.6g,%.6g,%.4g,%.4g,%.4g,%.3g,%.3g,%.6g\n", implicit ? "midpoint" : "rk4", n, r.h,
                     r.us2, r.us3, r.ratio, r.ratio_lo, r.ratio_hi, r.newton2, r.newton3, r.us3_alone);
      if (n >= 100) xs.push_back(n + 1), y2.push_back(r.us2), y3.push_back(r.us3), y3a.push_back(r.us3_alone);
    }
    t.printf("| %s | exponent n = 100..1000 | | %.2f | %.2f | | | | %.2f |\n", name, slope(xs, y2), slope(xs, y3),
             slope(xs, y3a));
  }
  if (csv) std::fclose(csv);
  t.write();
  std::printf("\nwrote %s/step_cost_3d.csv\n", out_dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "out/bench", root = ".";
  double target = 0.3;
  int max_n = 1000;
  bool quick = false, spatial_only = false, save_baseline = false, compare = false, target_given = false;
  bool rounds_given = false;
  bench::StepCheckOptions check;
  check.command = bench::commandLine(argc, argv);
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--out") && more)
      out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--root") && more)
      root = argv[++i];
    else if (!std::strcmp(argv[i], "--target") && more)
      target = std::atof(argv[++i]), target_given = true;
    else if (!std::strcmp(argv[i], "--max-n") && more)
      max_n = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--spatial"))
      spatial_only = true;
    else if (!std::strcmp(argv[i], "--save-baseline"))
      save_baseline = true;
    else if (!std::strcmp(argv[i], "--compare"))
      compare = true;
    else if (!std::strcmp(argv[i], "--baseline") && more)
      check.baseline = argv[++i];
    else if (!std::strcmp(argv[i], "--rounds") && more)
      check.rounds = std::atoi(argv[++i]), rounds_given = true;
    else if (!std::strcmp(argv[i], "--tolerance") && more)
      check.tolerance = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--fail-on-change"))
      check.fail_on_change = true;
    else if (!std::strcmp(argv[i], "--scenes") && more) {
      std::string list = argv[++i], item;
      for (std::stringstream ss(list); std::getline(ss, item, ',');)
        if (!item.empty()) check.scenes.push_back(item);
    } else {
      std::fprintf(stderr,
                   "usage: riser_sim_bench_step_cost [--out DIR] [--root DIR] [--target S] [--max-n N] "
                   "[--quick] [--spatial]\n"
                   "       riser_sim_bench_step_cost --save-baseline|--compare [--baseline FILE] "
                   "[--scenes a,b] [--rounds K] [--target S] [--tolerance F] [--fail-on-change] [--root DIR]\n");
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
  }
  if (save_baseline || compare) {
    check.root = root;
    if (target_given) check.target = target;
    if (save_baseline && compare) {
      std::fprintf(stderr, "riser_sim_bench_step_cost: --save-baseline or --compare, not both\n");
      return 2;
    }
    if (compare && (rounds_given || target_given)) {
      std::fprintf(stderr,
                   "riser_sim_bench_step_cost: --compare replays the baseline's rounds and blocks: "
                   "--rounds and --target belong to --save-baseline\n");
      return 2;
    }
    if (!(check.tolerance > 0.0 && check.tolerance < 1.0)) {
      std::fprintf(stderr, "riser_sim_bench_step_cost: --tolerance must be in (0, 1), got %g\n", check.tolerance);
      return 2;
    }
    return save_baseline ? bench::saveStepCostBaseline(check) : bench::compareStepCost(check);
  }
  const std::string command = bench::commandLine(argc, argv);
  std::vector<int> ns = {10, 20, 40, 100, 200, 400, 1000};
  if (quick) ns = {10, 40, 100};
  std::filesystem::create_directories(out_dir);
  if (spatial_only) {
    spatialRows(out_dir, target, max_n, quick, command);
    return 0;
  }
  bench::MarkdownTable table("step_cost", command);
  std::FILE* csv = std::fopen((out_dir + "/step_cost.csv").c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "cannot write into %s\n", out_dir.c_str());
    return 1;
  }
  std::fprintf(csv, "scene,integrator,formulation,jacobian,n,h,steps,cpu_us_per_step,us_per_step_per_rfe\n");
  const int kConfigs_n = int(sizeof(kConfigs) / sizeof(kConfigs[0]));
  table.printf(
      "Cost of one step (thread CPU time, median of 3; the machine may be shared), growth exponent "
      "over n (J-lay: the n = 400 column is n = 300, its statics limit):\n\n| scene | integrator / formulation / solve "
      "| h [s] | ");
  for (int n : ns) table.printf("n = %d | ", n);
  table.printf("exponent |\n|---|---|---|");
  for (size_t k = 0; k < ns.size(); ++k) table.printf("---|");
  table.printf("---|\n");
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
      table.printf("| %s | %s / %s / %s | %s | ", which, c.integrator, c.formulation, c.jacobian,
                   c.h > 0 ? std::to_string(c.h).substr(0, 4).c_str() : "0.9x limit");
      for (size_t j = 0; j < ns.size(); ++j) {
        if (cost[k][j] == 0.0)
          table.printf("- | ");
        else if (cost[k][j] < 0.0)
          table.printf("failed | ");
        else {
          table.printf("%.3g us | ", 1e6 * cost[k][j]);
          xs.push_back(ns[j] + 1);
          ys.push_back(cost[k][j]);
        }
      }
      table.printf("%.2f |\n", slope(xs, ys));
    }
    std::fflush(stdout);
    ns = quick ? std::vector<int>{10, 40, 100} : std::vector<int>{10, 20, 40, 100, 200, 400, 1000};
  }
  std::fclose(csv);
  table.write();
  std::printf("\nwrote %s/step_cost.csv\n", out_dir.c_str());
  spatialRows(out_dir, target, max_n, quick, command);
  return 0;
}
