#include "modal_output.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cli_options.h"
#include "output_file.h"
#include "riser_sim/run_builder.h"
#include "riser_sim/modal.h"

namespace riser_sim {
namespace cli {

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "riser_sim_cli: error: %s\n", message.c_str());
  return code;
}

// ω² below this share of the largest returned |ω²| counts as zero (no oscillation).
constexpr double kZeroOmega2 = 1e-12;

}  // namespace

int runModes(const Scene& scene, int count, const std::string& csv_path, bool quiet) {
  ModalOptions o;
  o.modes = count;
  StaticsResult st;
  ModalResult r;
  try {
    r = sceneModes(scene, o, &st);
  } catch (const std::invalid_argument& e) {
    return fail(kExitBadInput, e.what());
  } catch (const std::exception& e) {
    return fail(kExitDiverged, e.what());
  }
  if (!quiet) {
    std::fprintf(stderr,
                 "riser_sim_cli: modes about the static state (%s, %s), %d coordinates%s; end load (%g, %g) N kept "
                 "as a dead load; undamped (drag and damping left out); equilibrium residual %.2e, K asymmetry "
                 "%.2e\n",
                 name(scene.initial.type), st.message.c_str(), r.coordinates,
                 r.pinned ? " minus 2 end constraints (pinned)" : "", st.end_force.x(), st.end_force.y(),
                 r.equilibrium_residual, r.asymmetry);
  }
  if (r.equilibrium_residual > 1e-6)  // even with --quiet
    std::fprintf(stderr, "riser_sim_cli: warning: the state is not an equilibrium (residual %.2e); the modes are "
                 "not meaningful\n", r.equilibrium_residual);
  OutputFile table;
  table.useStdout();
  double big = 0.0;
  for (const Mode& m : r.modes) big = std::max(big, std::abs(m.omega2));
  std::printf("%4s %14s %16s %14s  %-10s %11s\n", "mode", "period [s]", "frequency [Hz]", "omega [rad/s]",
              "character", "axial share");
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const Mode& m = r.modes[k];
    if (std::abs(m.omega2) <= kZeroOmega2 * big || m.omega2 < 0.0) {
      std::printf("%4zu %14s %16s %14s  %-10s %11.3f\n", k + 1, "-", "-", "-",
                  m.omega2 < 0.0 ? "unstable" : "zero", m.axial_fraction);
      continue;
    }
    std::printf("%4zu %14.6g %16.6g %14.6g  %-10s %11.3f\n", k + 1, m.period, m.frequency, m.omega,
                m.character.c_str(), m.axial_fraction);
  }
  if (!table.close()) return fail(kExitWriteFailed, "--modes: " + table.error());
  if (csv_path.empty()) return kExitOk;
  OutputFile csv;
  if (!csv.open("--modes-csv", csv_path)) return fail(kExitBadInput, csv.error());
  std::FILE* f = csv.get();
  // Displacements are unitless (largest point displacement of each mode = 1).
  std::fprintf(f, "mode,period_s,frequency_hz,character,point,s,x,y,dx,dy\n");
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const Mode& m = r.modes[k];
    for (size_t p = 0; p < r.points.size(); ++p)
      std::fprintf(f, "%zu,%.10g,%.10g,%s,%zu,%.10g,%.10g,%.10g,%.10g,%.10g\n", k + 1, m.period, m.frequency,
                   m.character.c_str(), p, r.arc_length[p], r.points[p].x() + 0.0, r.points[p].y() + 0.0,
                   m.displacement[p].x() + 0.0, m.displacement[p].y() + 0.0);  // + 0.0: no "-0"
    if (!csv.ok()) break;
  }
  return csv.close() ? kExitOk : fail(kExitWriteFailed, csv.error());
}

}  // namespace cli
}  // namespace riser_sim
