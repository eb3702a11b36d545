#include "spatial_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "output_file.h"
#include "run_output.h"
#include "spatial_modes.h"
#include "step_loop.h"

namespace riser_sim {
namespace cli {

namespace {
// Columns of spatialSample() before the probes.
constexpr const char* kSpatialColumns =
    "t,x_top,y_top,z_top,x_end,y_end,z_end,top_fx,top_fy,top_fz,bottom_fx,bottom_fy,bottom_fz,top_mx,top_my,top_mz,"
    "bottom_mx,bottom_my,bottom_mz,tension_top,tension_max,energy,work,energy_drift,constraint_error";
enum Column { kT, kXTop, kYTop, kZTop, kXEnd, kYEnd, kZEnd, kTopFx, kTopFy, kTopFz, kBotFx, kBotFy, kBotFz,
              kTopMx, kTopMy, kTopMz, kBotMx, kBotMy, kBotMz, kTensionTop, kTensionMax, kEnergy, kWork, kDrift, kGap,
              kColumns, kXBottom = kColumns, kYBottom, kZBottom };

bool finite(const std::vector<double>& row) {
  return std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); });
}

void writeRow(std::FILE* f, const std::vector<double>& row) {
  for (size_t k = 0; k < row.size(); ++k) std::fprintf(f, k ? ",%.9g" : "%.9g", row[k]);
  std::fputc('\n', f);
}
}  // namespace

std::string spatialCsvHeader(const std::vector<int>& probe_rfes, bool bottom_moves, bool torsion) {
  std::string h = kSpatialColumns;
  if (bottom_moves) h += ",x_bottom,y_bottom,z_bottom";
  if (torsion) h += ",top_twist";
  for (const int k : probe_rfes) {
    const std::string K = std::to_string(k);
    h += ",x_rfe" + K + ",y_rfe" + K + ",z_rfe" + K + ",tension_rfe" + K;
  }
  return h;
}

std::vector<double> spatialSample(spatial::SpatialRun& run, const std::vector<int>& probe_rfes) {
  const spatial::LineOutputs3& o = run.outputs();
  std::vector<double> row = {o.t};
  for (const auto& v : {o.points.front(), o.points.back(), o.top_force, o.bottom_force, o.top_moment, o.bottom_moment})
    row.insert(row.end(), {v.x(), v.y(), v.z()});
  row.insert(row.end(), {o.top_tension, o.max_tension, o.kinetic_energy + o.potential_energy, o.work_in,
                         run.energyDrift(), o.constraint_error});
  if (run.bottomMoves()) row.insert(row.end(), {o.bottom_point.x(), o.bottom_point.y(), o.bottom_point.z()});
  if (run.hasTorsion()) row.push_back(o.top_twist);
  for (const int k : probe_rfes) {
    const auto& p = o.springs[k];
    row.insert(row.end(), {p.x(), p.y(), p.z(), o.axial_force[k]});
  }
  return row;
}

int runSpatial(const Scene& scene, const CliOptions& opt) {
  const auto info = [&](const char* fmt, auto... args) {
    if (opt.quiet) return;
    std::fputs("riser_sim_cli: ", stderr);
    std::fprintf(stderr, fmt, args...);
    std::fputc('\n', stderr);
  };

  if (opt.modes > 0) {  // the 3D modes; a time run only when --duration is given too (as planar)
    const int rc = runSpatialModes(scene, opt.modes, opt.modes_csv, opt.quiet);
    if (rc != kExitOk || opt.duration <= 0.0) return rc;
  }
  std::unique_ptr<spatial::SpatialRun> run;
  try {
    run = std::make_unique<spatial::SpatialRun>(scene);
  } catch (const std::invalid_argument& e) {  // what the 3D core cannot run yet, naming the key
    return fail(kExitBadInput, e.what());
  } catch (const std::runtime_error& e) {  // statics did not converge / not an equilibrium in 3D
    return fail(kExitDiverged, e.what());
  } catch (const std::exception& e) {
    return fail(kExitInternal, e.what());
  }
  const spatial::InitialState3& init = run->initial();
  char spins[96] = "";
  if (scene.torsion.enabled)
    std::snprintf(spins, sizeof(spins), "; largest moment on a spin at rest %g N m (bound %g)", init.max_twist_moment,
                  init.twist_moment_bound);
  info("initial state (%s): %s; %s; end force (%g, %g, %g) N; largest acceleration at rest %g m/s^2 (bound %g)%s",
       name(scene.initial.type), init.about.c_str(), init.statics.message.c_str(), init.end_force.x(),
       init.end_force.y(), init.end_force.z(), init.max_acceleration, init.acceleration_bound, spins);
  info("%s", stabilityMessage(run->explicitFixedStep(), name(scene.solver.integrator), run->highestFrequency(),
                              run->stableStepEstimate(), run->dt())
                 .c_str());

  OutputFile csv;
  if (!opt.csv.empty()) {
    if (!csv.open("--csv", opt.csv)) return fail(kExitBadInput, csv.error());
    std::fprintf(csv.get(), "%s\n", spatialCsvHeader(opt.probe_rfes, run->bottomMoves(), run->hasTorsion()).c_str());
  }
  const double dt = run->dt();
  const long total_steps = std::max(1L, static_cast<long>(std::ceil(scene.duration / dt - 1e-9)));
  const long every = outputStride(opt.output_dt, dt, total_steps);

  std::vector<double> last;
  SteppingTime time;
  const std::string diverged = stepRun(
      *run, total_steps, every, csv, [&] { return spatialSample(*run, opt.probe_rfes); },
      [](const std::vector<double>& s) { return finite(s); },
      [](std::FILE* f, const std::vector<double>& s) { writeRow(f, s); }, last, time);

  const double wall_s = time.wall_s, cpu_s = time.cpu_s;
  const double sim_s = run->time();
  const double rtf = wall_s > 0.0 ? sim_s / wall_s : NAN;
  // The energy balance and the forces' noise are judged as the planar run's (main.cpp).
  const RunEnd end = runEnd(*run, total_steps, diverged, last[kDrift], csv, !opt.csv.empty());
  const std::string& warning = end.warning;
  int rc = kExitOk;
  const Integrator::Stats stats = run->simulator().integrator().stats();
  if (opt.summary) {
    JsonLine j;
    j.add("status", runStatus(end))
        .add("wall_s", wall_s)
        .add("cpu_s", cpu_s)
        .add("sim_s", sim_s)
        .add("steps", run->steps())
        .add("rtf", rtf)
        .add("rhs_evaluations", stats.rhs)
        .add("newton_iterations", stats.newton)
        .add("t_last", last[kT])
        .add("x_top", last[kXTop])
        .add("y_top", last[kYTop])
        .add("z_top", last[kZTop])
        .add("x_end", last[kXEnd])
        .add("y_end", last[kYEnd])
        .add("z_end", last[kZEnd])
        .add("top_force_x", last[kTopFx])
        .add("top_force_y", last[kTopFy])
        .add("top_force_z", last[kTopFz])
        .add("bottom_force_x", last[kBotFx])
        .add("bottom_force_y", last[kBotFy])
        .add("bottom_force_z", last[kBotFz])
        .add("top_moment_x", last[kTopMx])
        .add("top_moment_y", last[kTopMy])
        .add("top_moment_z", last[kTopMz])
        .add("bottom_moment_x", last[kBotMx])
        .add("bottom_moment_y", last[kBotMy])
        .add("bottom_moment_z", last[kBotMz]);
    if (run->topFlexJoint()) j.add("top_moment_max", run->maxTopMoment());
    if (run->bottomFlexJoint()) j.add("bottom_moment_max", run->maxBottomMoment());
    if (run->bottomMoves()) j.add("x_bottom", last[kXBottom]).add("y_bottom", last[kYBottom]).add("z_bottom", last[kZBottom]);
    if (run->hasTorsion()) j.add("top_twist", last[kColumns + (run->bottomMoves() ? 3 : 0)]);
    j.add("tension_top", last[kTensionTop])
        .add("tension_max", last[kTensionMax])
        .add("max_constraint_error", run->maxConstraintError())
        .add("energy_drift", last[kDrift])
        .add("force_noise_top", run->forceNoise().total().top)
        .add("force_noise_max_axial", run->forceNoise().total().max_axial)
        .add("energy", last[kEnergy])
        .add("work", last[kWork])
        .add("energy_scale", run->energyScale())
        .add("scene", scene.name)
        .add("space", "spatial")
        .add("n", scene.elements)
        .add("dt", dt)
        .add("stable_dt_estimate", run->stableStepEstimate())
        .add("omega_max", run->highestFrequency())
        .add("integrator", name(scene.solver.integrator))
        .add("formulation", "natural")
        .add("statics_iterations", init.statics.iterations)
        .add("statics_residual", init.statics.residual)
        .add("end_force_x", init.end_force.x())
        .add("end_force_y", init.end_force.y())
        .add("end_force_z", init.end_force.z())
        .add("initial_acceleration", init.max_acceleration)
        .add("initial_acceleration_bound", init.acceleration_bound);
    if (scene.torsion.enabled)
      j.add("initial_twist_moment", init.max_twist_moment).add("initial_twist_moment_bound", init.twist_moment_bound);
    rc = finishRun(end, &j);
  } else {
    rc = finishRun(end, nullptr);
  }
  if (rc != kExitOk) return rc;
  info("done%s: %g s simulated in %.3f s of stepping (RTF %.3g), %ld steps; end at (%.6g, %.6g, %.6g) m",
       warning.empty() ? "" : " (with the warning above)", sim_s, wall_s, rtf, run->steps(), last[kXEnd], last[kYEnd],
       last[kZEnd]);
  return kExitOk;
}

}  // namespace cli
}  // namespace riser_sim
