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

std::string csvHeader(const std::vector<int>& probe_rfes, bool bottom_moves, bool torsion) {
  std::string h =
      "t,x_top,y_top,z_top,x_end,y_end,z_end,top_fx,top_fy,top_fz,bottom_fx,bottom_fy,bottom_fz,top_mx,top_my,top_mz,"
      "bottom_mx,bottom_my,bottom_mz,tension_top,tension_max,energy,work,energy_drift,constraint_error";
  if (bottom_moves) h += ",x_bottom,y_bottom,z_bottom";
  if (torsion) h += ",top_twist";
  for (const int k : probe_rfes) {
    const std::string K = std::to_string(k);
    h += ",x_rfe" + K + ",y_rfe" + K + ",z_rfe" + K + ",tension_rfe" + K;
  }
  return h;
}

void writeCsvRow(std::FILE* f, const RunOutputs& o, const std::vector<int>& probe_rfes, bool bottom_moves,
                 bool torsion) {
  std::fprintf(f, "%.9g", o.t);
  for (const Vec3* v : {&o.top_point, &o.end_point, &o.top_force, &o.bottom_force, &o.top_moment, &o.bottom_moment})
    std::fprintf(f, ",%.9g,%.9g,%.9g", v->x(), v->y(), v->z());
  std::fprintf(f, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", o.top_tension, o.max_tension, o.energy, o.work, o.energy_drift,
               o.constraint_error);
  if (bottom_moves) std::fprintf(f, ",%.9g,%.9g,%.9g", o.bottom_point.x(), o.bottom_point.y(), o.bottom_point.z());
  if (torsion) std::fprintf(f, ",%.9g", o.top_twist);
  for (const int k : probe_rfes) {
    const Vec3& p = o.springs[k];
    std::fprintf(f, ",%.9g,%.9g,%.9g,%.9g", p.x(), p.y(), p.z(), o.axial_force[k]);
  }
  std::fputc('\n', f);
}

std::string rangeGraphHeader(bool seabed) {
  return std::string("s,tension_min,tension_max") + (seabed ? ",clearance_min,clearance_max" : "") +
         ",s_joint,moment_min,moment_max,curvature_min,curvature_max";
}

void writeRangeGraph(std::FILE* f, const RangeGraph& g) {
  std::fprintf(f, "%s\n", rangeGraphHeader(g.hasSeabed()).c_str());
  const size_t nb = g.stations().size();
  for (size_t i = 0; i < nb; ++i) {
    std::fprintf(f, "%.9g,%.9g,%.9g", g.stations()[i], g.tension().min[i], g.tension().max[i]);
    if (g.hasSeabed()) std::fprintf(f, ",%.9g,%.9g", g.clearance().min[i], g.clearance().max[i]);
    if (i + 1 < nb)
      std::fprintf(f, ",%.9g,%.9g,%.9g,%.9g,%.9g\n", g.jointStations()[i], g.moment().min[i], g.moment().max[i],
                   g.curvature().min[i], g.curvature().max[i]);
    else
      std::fputs(",,,,,\n", f);
  }
}

std::string stabilityMessage(bool explicit_fixed_step, const std::string& scheme, double omega_max, double stable_dt,
                             double dt) {
  char buf[320];
  if (explicit_fixed_step)
    std::snprintf(buf, sizeof(buf), "stability: highest frequency %g rad/s, %s stable for solver.dt <= ~%g s%s",
                  omega_max, scheme.c_str(), stable_dt,
                  dt > stable_dt ? " -- solver.dt is above it, the run will likely diverge" : "");
  else
    std::snprintf(buf, sizeof(buf),
                  "stability: highest frequency %g rad/s (rk4 would need solver.dt <= ~%g s); %s has no such limit",
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

void addSectionKeys(JsonLine& j, const SectionExtremes& sections, const RangeGraph& range) {
  const std::vector<SectionExtremes::PerSection> per = sections.sections(range);
  for (size_t k = 0; k < per.size(); ++k) {
    const std::string key = "section" + std::to_string(k);
    j.add(key + "_tension_max", per[k].tension_max)
        .add(key + "_tension_max_s", per[k].tension_max_s)
        .add(key + "_curvature_max", per[k].curvature_max)
        .add(key + "_curvature_max_s", per[k].curvature_max_s);
  }
  const SectionExtremes::Wave w = sections.wave();
  if (w.found) j.add("sag_z", w.sag_z).add("sag_s", w.sag_s).add("hog_z", w.hog_z).add("hog_s", w.hog_s);
}

}  // namespace cli
}  // namespace riser_sim
