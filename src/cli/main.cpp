// riser_sim_cli: runs a scene offline (no roscore), writes an optional CSV time series and a JSON
// summary. Exit codes (cli_options.h): 0 ok, 1 internal error, 2 bad input, 3 diverged or initial statics
// failed, 4 an output could not be written.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <time.h>
#include <sstream>

#include "cli_options.h"
#include "modal_output.h"
#include "output_file.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "run_output.h"
#include "step_loop.h"

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
  if (opt.duration >= 0.0) scene.duration = opt.duration;  // 0: the statics alone
  for (const int k : opt.probe_rfes)
    if (k > scene.elements)
      return fail(kExitBadInput, "--probe-rfe: rfe " + std::to_string(k) + " does not exist (rfes 0.." +
                                     std::to_string(scene.elements) +
                                     ", line.elements = " + std::to_string(scene.elements) + ")");
  if (!(scene.duration / scene.solver.dt <= kMaxSceneSteps)) {  // run.duration itself is checked by the loader
    std::ostringstream why;
    why << "--duration: " << scene.duration / scene.solver.dt << " steps of solver.dt, more than " << kMaxSceneSteps;
    return fail(kExitBadInput, why.str());
  }
  info("scene '%s': n = %d, dt = %g s, %s/%s, duration %g s%s", scene.name.c_str(), scene.elements, scene.solver.dt,
       name(scene.solver.integrator), scene.space == SpaceKind::kSpatial ? "natural" : name(scene.solver.formulation),
       scene.duration, scene.space == SpaceKind::kSpatial ? ", space: spatial (3D)" : "");
  if (scene.top.type == MotionKind::kExternal)
    info("top.motion.type external: the top is held at top.position offline");
  if (opt.modes > 0) {  // statics + modes; a time run only when --duration is given too
    const int rc = runModes(scene, opt.modes, opt.modes_csv, opt.quiet);
    if (rc != kExitOk || opt.duration < 0.0) return rc;
  }

  std::unique_ptr<LineRun> run;
  LineRunInputs inputs;
  if (!opt.quiet) {  // a statics that takes a while says so every 2 s (its time is bounded: statics.h)
    double next = 2.0;
    inputs.statics_progress = [next](const std::string& stage, int iterations, double residual,
                                     double seconds) mutable {
      if (seconds < next) return;
      next = seconds + 2.0;
      std::fprintf(stderr, "riser_sim_cli: statics: %s, %d iterations, residual %.3g, %.0f s\n", stage.c_str(),
                   iterations, residual, seconds);
    };
  }
  try {
    run = buildLineRun(scene, inputs);
  } catch (const std::invalid_argument& e) {  // input the scene parser let through, or what the engine cannot run
    return fail(kExitBadInput, e.what());
  } catch (const std::runtime_error& e) {  // statics did not converge / not an equilibrium
    return fail(kExitDiverged, e.what());
  } catch (const std::exception& e) {
    return fail(kExitInternal, e.what());
  }
  const StartReport& init = run->start();
  {
    char rest[224] = "";
    if (init.has_rest_acceleration)
      std::snprintf(rest, sizeof(rest), "; largest acceleration at rest %g m/s^2 (bound %g)", init.initial_acceleration,
                    init.initial_acceleration_bound);
    if (init.has_twist_moment)
      std::snprintf(rest + std::strlen(rest), sizeof(rest) - std::strlen(rest),
                    "; largest moment on a spin at rest %g N m (bound %g)", init.initial_twist_moment,
                    init.initial_twist_moment_bound);
    info("initial state (%s): %s%s%s; end force (%g, %g, %g) N%s", name(scene.initial.type), init.about.c_str(),
         init.about.empty() ? "" : "; ", init.statics_message.c_str(), init.end_force.x(), init.end_force.y(),
         init.end_force.z(), rest);
  }
  info("%s", stabilityMessage(run->explicitFixedStep(), name(scene.solver.integrator), run->highestFrequency(),
                              run->stableStepEstimate(), run->dt())
                 .c_str());

  OutputFile csv;  // every row batch is checked: a full disk stops the run with exit code 4
  if (!opt.csv.empty()) {
    if (!csv.open("--csv", opt.csv)) return fail(kExitBadInput, csv.error());
    std::fprintf(csv.get(), "%s\n", csvHeader(opt.probe_rfes, run->bottomMoves(), run->hasTorsion()).c_str());
  }
  OutputFile range_file;  // written at the end; opened first so that a bad path fails before the run
  if (!opt.range_graph.empty() && !range_file.open("--range-graph", opt.range_graph))
    return fail(kExitBadInput, range_file.error());

  // Whole steps: the run ends at the first step at or past the duration (none for duration 0: the statics
  // alone); a row every `every` steps.
  const double dt = run->dt();
  const long total_steps =
      scene.duration > 0.0 ? std::max(1L, static_cast<long>(std::ceil(scene.duration / dt - 1e-9))) : 0L;
  const long every = outputStride(opt.output_dt, dt, std::max(1L, total_steps));

  RunOutputs last;
  SteppingTime time;
  // The range graph, fed every step: with --range-graph, and with --summary (its extremes' keys).
  std::unique_ptr<RangeGraph> range;
  const bool want_range = !opt.range_graph.empty() || opt.summary;
  // A sectioned line's summary: per-section extremes and the wave's bends (section_extremes.h).
  std::unique_ptr<SectionExtremes> sections;
  std::string diverged;
  try {
    if (opt.summary && !scene.sections.empty()) sections = std::make_unique<SectionExtremes>(scene, run->outputs());
    diverged = stepRun(*run, total_steps, every, csv, opt.probe_rfes, last, time, want_range ? &range : nullptr,
                       seabedPlane(scene), sections.get());
  } catch (const std::exception& e) {
    return fail(kExitInternal, e.what());
  }
  if (range_file.isOpen() && range) {  // the range of what ran, also when the run diverged
    writeRangeGraph(range_file.get(), *range);
    if (!range_file.close()) return fail(kExitWriteFailed, range_file.error());
  }

  const double wall_s = time.wall_s, cpu_s = time.cpu_s;
  const double sim_s = run->time();
  const double rtf = wall_s > 0.0 ? sim_s / wall_s : NAN;  // null without steps
  // The energy balance E - E0 - W closes to round-off on a resolved run (1e-7 on the J-lay at midpoint
  // h = 0.02 s); a scheme that damps what it does not resolve (rosenbrock2 at 0.02 s: 12 %) has moved
  // energy that the line never had, and its forces with it. Never "ok": status "warning" with the reason
  // in the summary and on stderr, exit 0 (the user chose the step; the run finished).
  // Forces with step-to-step noise above kForceNoiseWarning (force_noise.h) are not resolved either.
  const RunEnd end = runEnd(*run, total_steps, diverged, last.energy_drift, csv, !opt.csv.empty());
  const std::string& warning = end.warning;
  int rc = kExitOk;
  if (opt.summary) {
    const Integrator::Stats stats = run->integratorStats();  // what the steps cost
    const auto xyz = [](JsonLine& j, const std::string& key, const Vec3& v) {
      j.add(key + "_x", v.x()).add(key + "_y", v.y()).add(key + "_z", v.z());
    };
    JsonLine j;
    j.add("status", runStatus(end))
        .add("wall_s", wall_s)
        .add("cpu_s", cpu_s)
        .add("sim_s", sim_s)
        .add("steps", run->steps())
        .add("rtf", rtf)
        .add("rhs_evaluations", stats.rhs)
        .add("newton_iterations", stats.newton)
        .add("t_last", last.t)
        .add("x_top", last.top_point.x())
        .add("y_top", last.top_point.y())
        .add("z_top", last.top_point.z())
        .add("x_end", last.end_point.x())
        .add("y_end", last.end_point.y())
        .add("z_end", last.end_point.z());
    xyz(j, "top_force", last.top_force);
    xyz(j, "bottom_force", last.bottom_force);
    xyz(j, "top_moment", last.top_moment);
    xyz(j, "bottom_moment", last.bottom_moment);
    if (run->hasTopFlexJoint()) j.add("top_moment_max", run->maxTopMoment());
    if (run->hasBottomFlexJoint()) j.add("bottom_moment_max", run->maxBottomMoment());
    if (run->bottomMoves())
      j.add("x_bottom", last.bottom_point.x())
          .add("y_bottom", last.bottom_point.y())
          .add("z_bottom", last.bottom_point.z());
    if (run->hasTorsion()) j.add("top_twist", last.top_twist);
    for (size_t k = 0; k < last.attachment_points.size(); ++k) {  // attachments (scene order), at the end
      const std::string a = "attachment" + std::to_string(k);
      j.add(a + "_name", scene.attachments[k].name);
      xyz(j, a, last.attachment_points[k]);
      xyz(j, a + "_force", last.attachment_forces[k]);
    }
    j.add("tension_top", last.top_tension).add("tension_max", last.max_tension);
    if (range) {  // over every step of the run
      j.add("tension_max_s", range->tensionMaxS())
          .add("curvature_max", range->curvatureMax())
          .add("curvature_max_s", range->curvatureMaxS());
      if (range->hasSeabed())
        j.add("touchdown_s_min", range->touchdownMin()).add("touchdown_s_max", range->touchdownMax());
      if (sections) addSectionKeys(j, *sections, *range);
    }
    j.add("max_constraint_error", run->maxConstraintError())
        .add("energy_drift", last.energy_drift)
        .add("force_noise_top", run->forceNoise().total().top)
        .add("force_noise_max_axial", run->forceNoise().total().max_axial)
        .add("energy", last.energy)
        .add("work", last.work)
        .add("energy_scale", run->energyScale())
        .add("scene", scene.name)
        .add("space", run->spatial() ? "spatial" : "planar")
        .add("n", scene.elements)
        .add("dt", dt)
        .add("stable_dt_estimate", run->stableStepEstimate())
        .add("omega_max", run->highestFrequency())
        .add("integrator", name(scene.solver.integrator))
        .add("formulation", run->spatial() ? "natural" : name(scene.solver.formulation))
        .add("statics_iterations", init.statics_iterations)
        .add("statics_residual", init.statics_residual);
    xyz(j, "end_force", init.end_force);
    if (init.has_rest_acceleration)
      j.add("initial_acceleration", init.initial_acceleration)
          .add("initial_acceleration_bound", init.initial_acceleration_bound);
    if (init.has_twist_moment)
      j.add("initial_twist_moment", init.initial_twist_moment)
          .add("initial_twist_moment_bound", init.initial_twist_moment_bound);
    rc = finishRun(end, &j);
  } else {
    rc = finishRun(end, nullptr);
  }
  if (rc != kExitOk) return rc;
  info("done%s: %g s simulated in %.3f s of stepping (RTF %.3g), %ld steps; end at (%.6g, %.6g, %.6g) m",
       warning.empty() ? "" : " (with the warning above)", sim_s, wall_s, rtf, run->steps(), last.end_point.x(),
       last.end_point.y(), last.end_point.z());
  return kExitOk;
}
