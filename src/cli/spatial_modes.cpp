#include "spatial_modes.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cli_options.h"
#include "output_file.h"
#include "riser_sim/spatial/forces/end_load.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/modal_characters.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace cli {

namespace {

using spatial::Vec3;
using spatial::kZeroOmega2;

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "riser_sim_cli: error: %s\n", message.c_str());
  return code;
}

}  // namespace

int runSpatialModes(const Scene& scene, int count, const std::string& csv_path, bool quiet) {
  if (scene.bottom == BottomBoundary::kPinned && scene.bottom_motion.type != MotionKind::kFixed &&
      scene.bottom_motion.type != MotionKind::kExternal)
    return fail(kExitBadInput, "bottom.motion: --modes with space: spatial needs a fixed or free bottom (the modes are "
                               "about a static state)");
  std::shared_ptr<spatial::SpatialModel> model;
  spatial::InitialState3 init;
  spatial::SpatialModalResult r;
  try {
    model = spatial::buildSpatialModel(scene);
    init = spatial::solveInitialState3(scene, spatial::buildTopMotion3(scene.top)->at(0.0).p);
    spatial::addFlexJoints(scene, init.kin, *model);
    // The statics' end force stays as a dead load (as the planar --modes).
    if (init.end_force.squaredNorm() > 0.0) model->addTerm(std::make_unique<spatial::EndLoad3>(init.end_force));
    // A line twisted by its bending axes: the equilibrium and the modes about it with its spins.
    AlignedVector<Vec3> axes = init.material_axes;
    spatial::SpatialModalOptions options;
    options.hang_off = init.hang_off;
    const spatial::Kinematics3 eq = spatial::spatialEquilibrium(*model, init.kin, 20, options, &axes);
    r = spatial::computeSpatialModes(*model, eq, options, &axes);
  } catch (const std::invalid_argument& e) {
    return fail(kExitBadInput, e.what());
  } catch (const std::exception& e) {
    return fail(kExitDiverged, std::string("--modes: ") + e.what());
  }
  const Vec3 n = Vec3::UnitZ().cross(init.plane_direction).normalized();  // normal of the statics' plane
  std::vector<spatial::SpatialMode>& modes = r.modes;
  spatial::alignDegeneratePairs(modes, n);
  if (!quiet)
    std::fprintf(stderr,
                 "riser_sim_cli: 3D modes about the static state (%s, %s), %d coordinates; plane of in-plane modes "
                 "along (%g, %g, 0); end load (%g, %g, %g) N kept as a dead load; undamped; equilibrium residual "
                 "%.2e, K asymmetry %.2e\n",
                 name(scene.initial.type), init.statics.message.c_str(), int(r.stiffness.rows()),
                 init.plane_direction.x(), init.plane_direction.y(), init.end_force.x(), init.end_force.y(),
                 init.end_force.z(), r.equilibrium_residual, r.asymmetry);
  const size_t shown = std::min(modes.size(), static_cast<size_t>(count));
  double big = 0.0;
  for (const auto& m : modes) big = std::max(big, std::abs(m.omega2));
  OutputFile table;
  table.useStdout();
  std::printf("%4s %14s %16s %14s  %-12s %11s\n", "mode", "period [s]", "frequency [Hz]", "omega [rad/s]",
              "character", "axial share");
  for (size_t k = 0; k < shown; ++k) {
    const spatial::SpatialMode& m = modes[k];
    if (std::abs(m.omega2) <= kZeroOmega2 * big || m.omega2 < 0.0) {
      std::printf("%4zu %14s %16s %14s  %-12s %11.3f\n", k + 1, "-", "-", "-", m.omega2 < 0.0 ? "unstable" : "zero",
                  m.along_fraction);
      continue;
    }
    std::printf("%4zu %14.6g %16.6g %14.6g  %-12s %11.3f\n", k + 1, 2.0 * M_PI / m.omega, m.omega / (2.0 * M_PI),
                m.omega, spatial::modeCharacter(m, n), m.along_fraction);
  }
  if (!table.close()) return fail(kExitWriteFailed, "--modes: " + table.error());
  if (csv_path.empty()) return kExitOk;
  OutputFile csv;
  if (!csv.open("--modes-csv", csv_path)) return fail(kExitBadInput, csv.error());
  std::FILE* f = csv.get();
  // Displacements are unitless (largest point displacement of each mode = 1), as the planar CSV.
  std::fprintf(f, "mode,period_s,frequency_hz,character,point,s,x,y,z,dx,dy,dz\n");
  for (size_t k = 0; k < shown && csv.ok(); ++k) {
    const spatial::SpatialMode& m = modes[k];
    const double period = m.omega > 0.0 ? 2.0 * M_PI / m.omega : 0.0, freq = m.omega / (2.0 * M_PI);
    double scale = 0.0;
    for (const Vec3& v : m.displacement) scale = std::max(scale, v.norm());
    scale = scale > 0.0 ? 1.0 / scale : 0.0;
    const int nb = model->bodies();
    for (int p = 0; p <= nb; ++p) {
      const Vec3 x = p < nb ? r.equilibrium[p].A : r.equilibrium[nb - 1].end();
      const double s = p < nb ? model->rfe(p).s_begin : scene.length;  // arc length, unstretched [m]
      const Vec3 u = scale * m.displacement[p];
      std::fprintf(f, "%zu,%.10g,%.10g,%s,%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", k + 1, period, freq,
                   spatial::modeCharacter(m, n), p, s, x.x() + 0.0, x.y() + 0.0, x.z() + 0.0, u.x() + 0.0, u.y() + 0.0,
                   u.z() + 0.0);
    }
  }
  return csv.close() ? kExitOk : fail(kExitWriteFailed, csv.error());
}

}  // namespace cli
}  // namespace riser_sim
