#include "modal_output.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "cli_options.h"
#include "output_file.h"
#include "riser_sim/run/modes_report.h"

namespace riser_sim {
namespace cli {

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "riser_sim_cli: error: %s\n", message.c_str());
  return code;
}

// One row per mode and point; displacements unitless (largest point displacement of each mode = 1). Planar:
// x, y with y up (the 3D (x, 0, y)); 3D: x, y, z. "+ 0.0": no "-0".
void writeShapes(std::FILE* f, const ModesReport& r, size_t k) {
  const ModeEntry& m = r.modes[k];
  for (size_t p = 0; p < r.points.size(); ++p) {
    const Eigen::Vector3d& x = r.points[p];
    const Eigen::Vector3d& u = m.displacement[p];
    if (r.space == SpaceKind::kSpatial)
      std::fprintf(f, "%zu,%.10g,%.10g,%s,%zu,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", k + 1, m.period,
                   m.frequency, m.character.c_str(), p, r.arc_length[p], x.x() + 0.0, x.y() + 0.0, x.z() + 0.0,
                   u.x() + 0.0, u.y() + 0.0, u.z() + 0.0);
    else
      std::fprintf(f, "%zu,%.10g,%.10g,%s,%zu,%.10g,%.10g,%.10g,%.10g,%.10g\n", k + 1, m.period, m.frequency,
                   m.character.c_str(), p, r.arc_length[p], x.x() + 0.0, x.z() + 0.0, u.x() + 0.0, u.z() + 0.0);
  }
}

}  // namespace

int runModes(const Scene& scene, int count, const std::string& csv_path, bool quiet) {
  ModesReport r;
  try {
    r = sceneModesReport(scene, count);
  } catch (const std::invalid_argument& e) {
    return fail(kExitBadInput, e.what());
  } catch (const std::exception& e) {
    return fail(kExitDiverged, std::string("--modes: ") + e.what());
  }
  if (!quiet) std::fprintf(stderr, "riser_sim_cli: %s\n", r.header.c_str());
  // Even with --quiet:
  if (r.equilibrium_residual > 1e-6)
    std::fprintf(stderr,
                 "riser_sim_cli: warning: the state is not an equilibrium (residual %.2e); the modes are "
                 "not meaningful\n",
                 r.equilibrium_residual);
  if (count > static_cast<int>(r.modes.size()))
    std::fprintf(stderr,
                 "riser_sim_cli: warning: --modes %d: the line has %d modes (%d coordinates less its "
                 "constraints); all shown\n",
                 count, static_cast<int>(r.modes.size()), r.coordinates);
  OutputFile table;
  table.useStdout();
  int w = 0;  // the character column: the engine's widest name
  for (const std::string& c : modeCharacters(r.space)) w = std::max(w, static_cast<int>(c.size()));
  std::printf("%4s %14s %16s %14s  %-*s %11s\n", "mode", "period [s]", "frequency [Hz]", "omega [rad/s]", w,
              "character", "axial share");
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const ModeEntry& m = r.modes[k];
    if (m.status != ModeStatus::kOscillating)
      std::printf("%4zu %14s %16s %14s  %-*s %11.3f\n", k + 1, "-", "-", "-", w, name(m.status), m.axial_share);
    else
      std::printf("%4zu %14.6g %16.6g %14.6g  %-*s %11.3f\n", k + 1, m.period, m.frequency, m.omega, w,
                  m.character.c_str(), m.axial_share);
  }
  if (!table.close()) return fail(kExitWriteFailed, "--modes: " + table.error());
  if (csv_path.empty()) return kExitOk;
  OutputFile csv;
  if (!csv.open("--modes-csv", csv_path)) return fail(kExitBadInput, csv.error());
  std::fprintf(csv.get(), r.space == SpaceKind::kSpatial
                              ? "mode,period_s,frequency_hz,character,point,s,x,y,z,dx,dy,dz\n"
                              : "mode,period_s,frequency_hz,character,point,s,x,y,dx,dy\n");
  for (size_t k = 0; k < r.modes.size() && csv.ok(); ++k) writeShapes(csv.get(), r, k);
  return csv.close() ? kExitOk : fail(kExitWriteFailed, csv.error());
}

}  // namespace cli
}  // namespace riser_sim
