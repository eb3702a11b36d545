// The shipped scenes' step cost against a saved baseline (step_cost_check.h).
#include "step_cost_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "markdown_table.h"
#include "riser_sim/scene/choices.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace bench {
namespace {

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The reference work: a fixed recurrence over 4096 doubles (32 KiB: in L1/L2 like a scene's state), with
// sqrt, sin and a division, as a step has. Returns a checksum so that it is not optimised away.
constexpr int kKernelSize = 4096;
constexpr int kKernelPasses = 200;  // one block: ~4 ms on the development machine
double kernelBlock(std::vector<double>& buf) {
  double acc = 0.0;
  for (int p = 0; p < kKernelPasses; ++p)
    for (int i = 0; i < kKernelSize; ++i) {
      const double x = buf[i];
      const double y = 0.999 * x + 1e-3 * std::sin(x) + 1e-6 * std::sqrt(x * x + 1.0) + 1e-9 / (1.0 + x * x);
      buf[i] = y;
      acc += y;
    }
  return acc;
}

struct Setup {
  std::string scene, space, integrator;
  int elements = 0;
  double dt = 0.0;
};

struct Measured {
  Setup setup;
  bool ok = false;
  std::string why;
  long warmup_steps = 0;  // stepped before the rounds (3, then enough to size the blocks)
  long steps_per_block = 0;
  int rounds = 0;
  double us_per_step = 0.0;  // median over the rounds [µs]
  double us_rel_se = 0.0;    // standard error of that median, relative
  double kernel_us = 0.0;    // median CPU per kernel pass [µs]
  double normalised = 0.0;   // median of (CPU per step) / (CPU per kernel pass)
  double rel_se = 0.0;       // standard error of that median, relative
};

struct Live {
  Measured m;
  std::unique_ptr<LineRun> run;
  std::vector<double> per_step, per_pass, q;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t k = v.size();
  return k % 2 ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

// Relative standard error of the median of v: 1.2533 σ / √k with σ = IQR / 1.349 (normal data).
double relativeSe(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t k = v.size();
  if (k < 4) return NAN;
  const double q1 = v[k / 4], q3 = v[(3 * k) / 4], med = median(v);
  return 1.2533 * (q3 - q1) / 1.349 / std::sqrt(double(k)) / med;
}

std::vector<std::string> shippedScenes(const std::string& root) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(root + "/config/scenes"))
    if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Builds each scene's run and steps its warm-up: the baseline's steps (replay), else 3 steps and then as many as
// take 20 ms of CPU, whose cost sizes the blocks for o.target.
std::vector<Live> prepare(const StepCheckOptions& o, const std::vector<std::string>& names,
                          const std::map<std::string, std::pair<long, long>>& replay) {
  std::vector<Live> live(names.size());
  for (size_t k = 0; k < names.size(); ++k) {
    Live& l = live[k];
    l.m.setup.scene = names[k];
    try {
      const Scene scene = loadSceneFile(o.root + "/config/scenes/" + names[k] + ".yaml");
      l.m.setup.space = scene.space == SpaceKind::kSpatial ? "spatial" : "planar";
      l.m.setup.integrator = name(scene.solver.integrator);
      l.m.setup.elements = scene.elements;
      l.m.setup.dt = scene.solver.dt;
      l.run = buildLineRun(scene);
      auto step = [&]() {
        if (!l.run->step()) throw std::runtime_error("warm-up: " + l.run->divergenceReason());
        ++l.m.warmup_steps;
      };
      const auto b = replay.find(names[k]);
      if (b != replay.end()) {
        while (l.m.warmup_steps < b->second.first) step();
        l.m.steps_per_block = b->second.second;
      } else {
        for (int i = 0; i < 3; ++i) step();
        const double c0 = threadCpu();
        long timed = 0;
        while (threadCpu() - c0 < 0.02 && timed < 100000) step(), ++timed;
        const double per = (threadCpu() - c0) / double(timed);
        l.m.steps_per_block = std::max(1L, std::lround(o.target / o.rounds / per));
      }
      l.m.ok = true;
    } catch (const std::exception& e) {
      l.m.why = e.what();
      l.run.reset();
    }
  }
  return live;
}

void measure(std::vector<Live>& live, int rounds) {
  std::vector<double> buf(kKernelSize);
  for (int i = 0; i < kKernelSize; ++i) buf[i] = 1e-3 * i;
  volatile double sink = kernelBlock(buf);  // warm-up
  for (int r = 0; r < rounds; ++r)
    for (Live& l : live) {
      if (!l.m.ok) continue;
      const double c0 = threadCpu();
      sink = sink + kernelBlock(buf);
      const double c1 = threadCpu();
      bool ok = true;
      for (long s = 0; s < l.m.steps_per_block && ok; ++s) ok = l.run->step();
      const double c2 = threadCpu();
      if (!ok) {
        l.m.ok = false;
        l.m.why = "round " + std::to_string(r + 1) + ": " + l.run->divergenceReason();
        continue;
      }
      const double pass = (c1 - c0) / kKernelPasses, step = (c2 - c1) / double(l.m.steps_per_block);
      l.per_pass.push_back(pass);
      l.per_step.push_back(step);
      l.q.push_back(step / pass);
    }
  for (Live& l : live) {
    if (!l.m.ok) continue;
    l.m.rounds = rounds;
    l.m.us_per_step = 1e6 * median(l.per_step);
    l.m.us_rel_se = relativeSe(l.per_step);
    l.m.kernel_us = 1e6 * median(l.per_pass);
    l.m.normalised = median(l.q);
    l.m.rel_se = relativeSe(l.q);
  }
}

const char* kHeader =
    "scene,space,elements,integrator,dt,warmup_steps,steps_per_block,rounds,us_per_step,us_rel_se,kernel_us,normalised,"
    "normalised_rel_se";
constexpr size_t kColumns = 13;

std::vector<Measured> readBaseline(const std::string& path, std::string& stamp_line) {
  std::ifstream f(path);
  if (!f)
    throw std::runtime_error("no baseline " + path +
                             " (make bench-baseline, or riser_sim_bench_step_cost --save-baseline)");
  std::vector<Measured> rows;
  std::string line;
  bool header = false;
  int lineno = 0;
  while (std::getline(f, line)) {
    ++lineno;
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (stamp_line.empty()) stamp_line = line.substr(std::min<size_t>(2, line.size()));
      continue;
    }
    if (!header) {
      if (line != kHeader) throw std::runtime_error(path + ": header is not '" + kHeader + "'");
      header = true;
      continue;
    }
    std::stringstream ss(line);
    std::vector<std::string> c;
    std::string cell;
    while (std::getline(ss, cell, ',')) c.push_back(cell);
    if (c.size() != kColumns)
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": " + std::to_string(kColumns) +
                               " columns expected");
    Measured m;
    try {
      m.setup = {c[0], c[1], c[3], std::stoi(c[2]), std::stod(c[4])};
      m.warmup_steps = std::stol(c[5]);
      m.steps_per_block = std::stol(c[6]);
      m.rounds = std::stoi(c[7]);
      m.us_per_step = std::stod(c[8]);
      m.us_rel_se = std::stod(c[9]);
      m.kernel_us = std::stod(c[10]);
      m.normalised = std::stod(c[11]);
      m.rel_se = std::stod(c[12]);
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": not a number where one belongs");
    }
    m.ok = m.warmup_steps >= 3 && m.steps_per_block > 0 && m.rounds >= 4 && m.normalised > 0.0 &&
           std::isfinite(m.rel_se) && std::isfinite(m.us_rel_se);
    if (!m.ok) throw std::runtime_error(path + ":" + std::to_string(lineno) + ": not a measured row");
    rows.push_back(m);
  }
  if (!header) throw std::runtime_error(path + ": empty");
  return rows;
}

std::string setupDiff(const Setup& a, const Setup& b) {
  char buf[200];
  if (a.space != b.space) return "space " + a.space + " -> " + b.space;
  if (a.elements != b.elements) return "n " + std::to_string(a.elements) + " -> " + std::to_string(b.elements);
  if (a.integrator != b.integrator) return a.integrator + " -> " + b.integrator;
  if (std::fabs(a.dt - b.dt) > 1e-12 * std::max(1.0, std::fabs(a.dt))) {
    std::snprintf(buf, sizeof buf, "dt %g -> %g s", a.dt, b.dt);
    return buf;
  }
  return "";
}

}  // namespace

int saveStepCostBaseline(const StepCheckOptions& o) {
  if (o.rounds < 4 || o.target <= 0.0) {
    std::fprintf(stderr, "step cost baseline: --rounds must be >= 4 and --target > 0\n");
    return 1;
  }
  const std::vector<std::string> names = o.scenes.empty() ? shippedScenes(o.root) : o.scenes;
  std::vector<Live> live = prepare(o, names, {});
  measure(live, o.rounds);
  std::filesystem::create_directories(std::filesystem::path(o.baseline).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(o.baseline).parent_path());
  std::ofstream f(o.baseline);
  f << "# " << o.command << " on " << stamp() << "\n" << kHeader << "\n";
  std::printf(
      "Step cost baseline (thread CPU per step, median of %d interleaved rounds; s.e. = standard error of "
      "the median):\n\n"
      "| scene | n | integrator | dt [s] | steps per block | CPU per step [us] | s.e. | per kernel pass | s.e. |\n"
      "|---|---|---|---|---|---|---|---|---|\n",
      o.rounds);
  int failed = 0;
  for (const Live& l : live) {
    const Measured& m = l.m;
    if (!m.ok) {
      std::printf("| %s | | | | | failed: %s | | | |\n", m.setup.scene.c_str(), m.why.c_str());
      ++failed;
      continue;
    }
    char row[512];
    std::snprintf(row, sizeof row, "%s,%s,%d,%s,%.9g,%ld,%ld,%d,%.6g,%.4g,%.6g,%.6g,%.4g", m.setup.scene.c_str(),
                  m.setup.space.c_str(), m.setup.elements, m.setup.integrator.c_str(), m.setup.dt, m.warmup_steps,
                  m.steps_per_block, m.rounds, m.us_per_step, m.us_rel_se, m.kernel_us, m.normalised, m.rel_se);
    f << row << "\n";
    std::printf("| %s | %d | %s | %g | %ld | %.3g | %.2f %% | %.4g | %.2f %% |\n", m.setup.scene.c_str(),
                m.setup.elements, m.setup.integrator.c_str(), m.setup.dt, m.steps_per_block, m.us_per_step,
                100.0 * m.us_rel_se, m.normalised, 100.0 * m.rel_se);
  }
  f.close();
  if (!f) {
    std::fprintf(stderr, "cannot write %s\n", o.baseline.c_str());
    return 1;
  }
  std::printf("\nwrote %s (%zu scenes, %d failed: not in the baseline)\n", o.baseline.c_str(), live.size() - failed,
              failed);
  return 0;
}

int compareStepCost(const StepCheckOptions& o) {
  std::string base_stamp;
  std::vector<Measured> base;
  try {
    base = readBaseline(o.baseline, base_stamp);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "step cost check: %s\n", e.what());
    return 1;
  }
  std::map<std::string, Measured> by_name;
  std::map<std::string, std::pair<long, long>> replay;  // warm-up steps, steps per block
  int rounds = 0;
  for (const Measured& m : base) {
    by_name[m.setup.scene] = m;
    replay[m.setup.scene] = {m.warmup_steps, m.steps_per_block};
    rounds = std::max(rounds, m.rounds);
  }
  std::vector<std::string> names = o.scenes, not_in_base;
  if (names.empty()) {
    for (const std::string& s : shippedScenes(o.root)) (by_name.count(s) ? names : not_in_base).push_back(s);
  } else {
    for (const std::string& s : o.scenes)
      if (!by_name.count(s)) not_in_base.push_back(s);
    names.erase(std::remove_if(names.begin(), names.end(), [&](const std::string& s) { return !by_name.count(s); }),
                names.end());
  }
  std::vector<Live> live = prepare(o, names, replay);
  // A scene whose setup changed is not compared (other work, not other code).
  for (Live& l : live) {
    const std::string diff = l.m.ok ? setupDiff(by_name[l.m.setup.scene].setup, l.m.setup) : "";
    if (!diff.empty()) {
      l.m.ok = false;
      l.m.why = "scene changed: " + diff;
    }
  }
  measure(live, rounds);

  MarkdownTable t("step_cost_check", o.command);
  t.printf(
      "Step cost of the shipped scenes against the baseline (%s): thread CPU per step, median of %d "
      "interleaved rounds; normalised = per pass of a fixed kernel timed before each block; ratios now / "
      "baseline ± 2 standard errors; verdict on the normalised ratio, tolerance %.0f %%.\n\n",
      base_stamp.c_str(), rounds, 100.0 * o.tolerance);
  t.printf(
      "| scene | n | integrator, dt [s] | baseline [us] | now [us] | ratio (CPU) | ratio (normalised) | verdict |\n"
      "|---|---|---|---|---|---|---|---|\n");
  int unchanged = 0, other = 0;
  std::string not_unchanged;
  for (const Live& l : live) {
    const Measured& b = by_name[l.m.setup.scene];
    const Measured& m = l.m;
    if (!m.ok) {
      t.printf("| %s | %d | %s, %g | %.3g | – | – | – | %s |\n", b.setup.scene.c_str(), b.setup.elements,
               b.setup.integrator.c_str(), b.setup.dt, b.us_per_step, m.why.c_str());
      ++other, not_unchanged += " " + b.setup.scene;
      continue;
    }
    const double r = m.normalised / b.normalised;
    const double se = r * std::hypot(m.rel_se, b.rel_se);
    const double dev = std::fabs(r - 1.0);
    const char* verdict;
    char why[120];
    if (!std::isfinite(se)) {
      verdict = "inconclusive";
      std::snprintf(why, sizeof why, " (too few rounds for a spread)");
    } else if (dev + 2.0 * se <= o.tolerance) {
      verdict = "**unchanged**";
      why[0] = '\0';
    } else if (dev - 2.0 * se > o.tolerance) {
      verdict = r > 1.0 ? "**slower**" : "**faster**";
      why[0] = '\0';
    } else {
      verdict = "inconclusive";
      std::snprintf(why, sizeof why, " (± %.1f %% of noise)", 200.0 * se);
    }
    if (std::string(verdict) == "**unchanged**")
      ++unchanged;
    else
      ++other, not_unchanged += " " + m.setup.scene;
    const double r_cpu = m.us_per_step / b.us_per_step;
    t.printf("| %s | %d | %s, %g | %.3g | %.3g | %.3f ± %.3f | %.3f ± %.3f | %s%s |\n", m.setup.scene.c_str(),
             m.setup.elements, m.setup.integrator.c_str(), m.setup.dt, b.us_per_step, m.us_per_step, r_cpu,
             2.0 * r_cpu * std::hypot(m.us_rel_se, b.us_rel_se), r, 2.0 * se, verdict, why);
  }
  for (const std::string& s : not_in_base) {
    t.printf("| %s | | | – | – | – | – | not in the baseline |\n", s.c_str());
    ++other, not_unchanged += " " + s;
  }
  t.printf("\n%d of %d scenes unchanged within %.0f %%%s%s.\n", unchanged, unchanged + other, 100.0 * o.tolerance,
           other ? "; not:" : "", not_unchanged.c_str());
  if (!t.write()) return 1;
  return o.fail_on_change && other ? 3 : 0;
}

}  // namespace bench
}  // namespace riser_sim
