#include "run_output.h"

#include <time.h>

#include <cmath>
#include <cstdio>

#include "cli_options.h"
#include "output_file.h"

namespace riser_sim {
namespace cli {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "riser_sim_cli: error: %s\n", message.c_str());
  return code;
}

Sample takeSample(Simulator& sim, const std::vector<int>& probe_rfes) {
  const LineOutputs& out = sim.outputs();
  Sample s;
  s.t = out.t;
  s.x_top = out.points.front().x();
  s.y_top = out.points.front().y();
  s.x_end = out.points.back().x();
  s.y_end = out.points.back().y();
  s.tension_top = out.top_tension;
  s.tension_max = out.max_tension;
  s.energy = out.kinetic_energy + out.potential_energy;
  s.work = out.work_in;
  s.energy_drift = sim.energyDrift();
  s.constraint_error = out.constraint_error;
  for (const int k : probe_rfes) {
    const double l1 = sim.model().rfe(k).length1, phi = out.angles[k];
    s.probes.push_back(out.points[k].x() + l1 * std::cos(phi));
    s.probes.push_back(out.points[k].y() + l1 * std::sin(phi));
    s.probes.push_back(out.axial_force[k]);
  }
  return s;
}

bool allFinite(const Sample& s) {
  for (double v : {s.t, s.x_top, s.y_top, s.x_end, s.y_end, s.tension_top, s.tension_max, s.energy, s.work,
                   s.energy_drift, s.constraint_error})
    if (!std::isfinite(v)) return false;
  for (double v : s.probes)
    if (!std::isfinite(v)) return false;
  return true;
}

std::string csvHeader(const std::vector<int>& probe_rfes) {
  std::string h = "t,x_top,y_top,x_end,y_end,tension_top,tension_max,energy,work,energy_drift,constraint_error";
  for (const int k : probe_rfes) {
    const std::string K = std::to_string(k);
    h += ",x_rfe" + K + ",y_rfe" + K + ",tension_rfe" + K;
  }
  return h;
}

void writeCsvRow(std::FILE* f, const Sample& s) {
  std::fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", s.t, s.x_top, s.y_top, s.x_end,
               s.y_end, s.tension_top, s.tension_max, s.energy, s.work, s.energy_drift, s.constraint_error);
  for (double v : s.probes) std::fprintf(f, ",%.9g", v);
  std::fputc('\n', f);
}

std::string stabilityMessage(bool explicit_fixed_step, const std::string& scheme, double omega_max,
                             double stable_dt, double dt) {
  char buf[320];
  if (explicit_fixed_step)
    std::snprintf(buf, sizeof(buf), "stability: highest frequency %g rad/s, %s stable for solver.dt <= ~%g s%s",
                  omega_max, scheme.c_str(), stable_dt,
                  dt > stable_dt ? " -- solver.dt is above it, the run will likely diverge" : "");
  else
    std::snprintf(buf, sizeof(buf), "stability: highest frequency %g rad/s (rk4 would need solver.dt <= ~%g s); %s has no such limit",
                  omega_max, stable_dt, scheme.c_str());
  return buf;
}

std::string energyWarning(double drift) {
  if (!(std::abs(drift) > kEnergyDriftWarning)) return "";
  char buf[320];
  std::snprintf(buf, sizeof(buf),
                "energy balance off by %.3g of m g L (bound %g): the step does not resolve the motion, so "
                "positions and forces may be wrong; use a smaller solver.dt or solver.integrator midpoint",
                drift, kEnergyDriftWarning);
  return buf;
}

const char* runStatus(const RunEnd& e) {
  return !e.diverged.empty() ? "diverged" : !e.written ? "write_failed" : e.warning.empty() ? "ok" : "warning";
}

int finishRun(const RunEnd& e, JsonLine* summary) {
  bool summary_written = true;
  if (summary) {
    if (!e.diverged.empty()) summary->add("diverged_at", e.sim_s).add("reason", e.diverged);
    if (!e.written) summary->add("write_error", e.write_error);
    if (!e.warning.empty()) summary->add("warning", e.warning);
    OutputFile out;
    out.useStdout();
    std::printf("%s\n", summary->str().c_str());
    summary_written = out.close();
    if (!summary_written) fail(kExitWriteFailed, "--summary: " + out.error());
  }
  int rc = summary_written ? kExitOk : kExitWriteFailed;
  if (!e.diverged.empty()) {
    char when[64];
    std::snprintf(when, sizeof(when), "diverged at t = %.9g s (step %ld): ", e.sim_s, e.steps);
    rc = fail(kExitDiverged, when + e.diverged + (e.csv ? "; the CSV stops at the last finite row" : ""));
  }
  if (!e.written) {  // a lost output wins over a divergence: nothing written can be trusted
    char when[96];
    std::snprintf(when, sizeof(when), "; the file is incomplete%s (t = %.9g s reached)",
                  e.diverged.empty() && e.steps < e.total_steps ? " and the run was stopped" : "", e.sim_s);
    rc = fail(kExitWriteFailed, e.write_error + when);
  }
  if (!summary_written) rc = kExitWriteFailed;
  if (rc == kExitOk && !e.warning.empty())
    std::fprintf(stderr, "riser_sim_cli: warning: %s\n", e.warning.c_str());  // even with --quiet
  return rc;
}

long outputStride(double output_dt, double dt, long total_steps) {
  const double ratio = std::round(output_dt / dt);
  if (!(ratio < static_cast<double>(total_steps))) return total_steps;
  return ratio < 1.0 ? 1L : static_cast<long>(ratio);
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void JsonLine::addRaw(const std::string& key, const std::string& json) {
  if (!body_.empty()) body_ += ",";
  body_ += jsonString(key) + ":" + json;
}

JsonLine& JsonLine::add(const std::string& key, double v) {
  char buf[32] = "null";
  if (std::isfinite(v)) std::snprintf(buf, sizeof(buf), "%.9g", v);
  addRaw(key, buf);
  return *this;
}

JsonLine& JsonLine::add(const std::string& key, long v) {
  addRaw(key, std::to_string(v));
  return *this;
}

JsonLine& JsonLine::add(const std::string& key, bool v) {
  addRaw(key, v ? "true" : "false");
  return *this;
}

JsonLine& JsonLine::add(const std::string& key, const std::string& v) {
  addRaw(key, jsonString(v));
  return *this;
}

}  // namespace cli
}  // namespace riser_sim
