// riser_sim_cli: runs a scene offline (no roscore), writes an optional CSV time series and a JSON
// summary. Exit codes (cli_options.h): 0 ok, 1 internal error, 2 bad input, 3 diverged or initial statics
// failed, 4 an output could not be written.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <time.h>
#include <sstream>

#include "cli_options.h"
#include "modal_output.h"
#include "output_file.h"
#include "riser_sim/run_builder.h"
#include "riser_sim/scene.h"
#include "riser_sim/scene_yaml.h"
#include "run_output.h"
#include "step_loop.h"
#include "spatial_run.h"

namespace {

}  // namespace

int main(int argc, char** argv) {
  using namespace riser_sim;
  using namespace riser_sim::cli;

  CliOptions opt;
  try {
    opt = parseOptions(argc, argv);
  } catch (const UsageError& e) {
    return fail(kExitBadInput, e.what());
  }
  if (opt.help) {
    OutputFile out;
    out.useStdout();
    std::fputs(usage().c_str(), stdout);
    return out.close() ? kExitOk : fail(kExitWriteFailed, out.error());
  }
  const auto info = [&](const char* fmt, auto... args) {
    if (opt.quiet) return;
    std::fputs("riser_sim_cli: ", stderr);
    std::fprintf(stderr, fmt, args...);
    std::fputc('\n', stderr);
  };

  Scene scene;
  try {
    scene = loadSceneFile(opt.scene, opt.overrides);
  } catch (const SceneError& e) {
    return fail(kExitBadInput, e.what());
  }
  if (opt.duration > 0.0) scene.duration = opt.duration;
  for (const int k : opt.probe_rfes)
    if (k > scene.elements)
      return fail(kExitBadInput, "--probe-rfe: rfe " + std::to_string(k) + " does not exist (rfes 0.." +
                                     std::to_string(scene.elements) + ", line.elements = " +
                                     std::to_string(scene.elements) + ")");
  if (!(scene.duration / scene.solver.dt <= kMaxSceneSteps)) {  // run.duration itself is checked by the loader
    std::ostringstream why;
    why << "--duration: " << scene.duration / scene.solver.dt << " steps of solver.dt, more than " << kMaxSceneSteps;
    return fail(kExitBadInput, why.str());
  }
  info("scene '%s': n = %d, dt = %g s, %s/%s, duration %g s%s", scene.name.c_str(), scene.elements, scene.solver.dt,
       name(scene.solver.integrator), scene.space == SpaceKind::kSpatial ? "natural" : name(scene.solver.formulation),
       scene.duration, scene.space == SpaceKind::kSpatial ? ", space: spatial (3D)" : "");
  if (scene.top.type == MotionKind::kExternal) info("top.motion.type external: the top is held at top.position offline");
  if (scene.space == SpaceKind::kSpatial) return runSpatial(scene, opt);  // the 3D path: spatial_run.cpp
  if (opt.modes > 0) {  // statics + modes; a time run only when --duration is given too
    const int rc = runModes(scene, opt.modes, opt.modes_csv, opt.quiet);
    if (rc != kExitOk || opt.duration <= 0.0) return rc;
  }

  std::unique_ptr<Simulator> sim;
  StaticsResult statics;
  try {
    sim = buildSimulator(scene, &statics);
  } catch (const std::invalid_argument& e) {  // input the scene parser let through
    return fail(kExitBadInput, e.what());
  } catch (const std::runtime_error& e) {  // statics did not converge
    return fail(kExitDiverged, e.what());
  } catch (const std::exception& e) {
    return fail(kExitInternal, e.what());
  }
  info("initial state (%s): %s; end force (%g, %g) N", name(scene.initial.type), statics.message.c_str(),
       statics.end_force.x(), statics.end_force.y());
  info("%s", stabilityMessage(sim->integrator().explicitFixedStep(), name(scene.solver.integrator),
                              sim->highestFrequency(), sim->stableStepEstimate(), sim->dt())
                 .c_str());

  OutputFile csv;  // every row batch is checked: a full disk stops the run with exit code 4
  if (!opt.csv.empty()) {
    if (!csv.open("--csv", opt.csv)) return fail(kExitBadInput, csv.error());
    std::fprintf(csv.get(), "%s\n", csvHeader(opt.probe_rfes).c_str());
  }

  // Whole steps: the run ends at the first step at or past the duration; a row every `every` steps.
  const double dt = sim->dt();
  const long total_steps = std::max(1L, static_cast<long>(std::ceil(scene.duration / dt - 1e-9)));
  const long every = outputStride(opt.output_dt, dt, total_steps);

  Sample last;
  SteppingTime time;
  const std::string diverged = stepRun(
      *sim, total_steps, every, csv, [&] { return takeSample(*sim, opt.probe_rfes); },
      [](const Sample& s) { return allFinite(s); }, [](std::FILE* f, const Sample& s) { writeCsvRow(f, s); }, last,
      time);

  const double wall_s = time.wall_s, cpu_s = time.cpu_s;
  const double sim_s = sim->time();
  const double rtf = wall_s > 0.0 ? sim_s / wall_s : NAN;
  // The energy balance E - E0 - W closes to round-off on a resolved run (1e-7 on the J-lay at midpoint
  // h = 0.02 s); a scheme that damps what it does not resolve (rosenbrock2 at 0.02 s: 12 %) has moved
  // energy that the line never had, and its forces with it. Never "ok": status "warning" with the reason
  // in the summary and on stderr, exit 0 (the user chose the step; the run finished).
  // Forces with step-to-step noise above kForceNoiseWarning (force_noise.h) are not resolved either.
  const RunEnd end = runEnd(*sim, total_steps, diverged, last.energy_drift, csv, !opt.csv.empty());
  const std::string& warning = end.warning;
  int rc = kExitOk;
  const Integrator::Stats stats = sim->integrator().stats();  // what the steps cost
  if (opt.summary) {
    JsonLine j;
    j.add("status", runStatus(end))
        .add("wall_s", wall_s)
        .add("cpu_s", cpu_s)
        .add("sim_s", sim_s)
        .add("steps", sim->steps())
        .add("rtf", rtf)
        .add("rhs_evaluations", stats.rhs)
        .add("newton_iterations", stats.newton)
        .add("t_last", last.t)
        .add("x_end", last.x_end)
        .add("y_end", last.y_end)
        .add("tension_top", last.tension_top)
        .add("tension_max", last.tension_max)
        .add("max_constraint_error", sim->maxConstraintError())
        .add("energy_drift", last.energy_drift)
        .add("force_noise_top", sim->forceNoise().total().top)
        .add("force_noise_max_axial", sim->forceNoise().total().max_axial)
        .add("scene", scene.name)
        .add("n", scene.elements)
        .add("dt", dt)
        .add("stable_dt_estimate", sim->stableStepEstimate())
        .add("omega_max", sim->highestFrequency())
        .add("integrator", name(scene.solver.integrator))
        .add("formulation", name(scene.solver.formulation))
        .add("statics_iterations", statics.iterations)
        .add("statics_residual", statics.residual)
        .add("end_force_x", statics.end_force.x())
        .add("end_force_y", statics.end_force.y());
    rc = finishRun(end, &j);
  } else {
    rc = finishRun(end, nullptr);
  }
  if (rc != kExitOk) return rc;
  info("done%s: %g s simulated in %.3f s of stepping (RTF %.3g), %ld steps; end at (%.6g, %.6g) m", warning.empty() ? "" : " (with the warning above)",
       sim_s, wall_s, rtf, sim->steps(), last.x_end, last.y_end);
  return kExitOk;
}
