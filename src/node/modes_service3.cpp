// ~modes for a 3D scene: the same analysis as riser_sim_cli --modes with space: spatial (src/cli/
// spatial_modes.cpp), its table's periods, characters and axial shares, and its CSV's shapes.
#include <cmath>
#include <cstdio>
#include <exception>

#include "riser_sim/spatial/forces/end_load.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/modal_characters.h"
#include "riser_sim_ros/modes_service.h"

namespace riser_sim_ros {

using riser_sim::spatial::kZeroOmega2;
using riser_sim::spatial::SpatialMode;
using Vec3 = Eigen::Vector3d;

void computeModesResponse3(const riser_sim::Scene& scene, const riser_sim::spatial::InitialState3& initial, int count,
                           riser_sim::Modes::Response& res) {
  namespace sp = riser_sim::spatial;
  res.success = false;
  if (count < 1) {
    res.message = "count: must be >= 1, got " + std::to_string(count);
    return;
  }
  if (scene.bottom == riser_sim::BottomBoundary::kPinned && scene.bottom_motion.type != riser_sim::MotionKind::kFixed) {
    res.message = "bottom.motion: ~modes in 3D needs a fixed or free bottom (the modes are about a static state)";
    return;
  }
  std::shared_ptr<sp::SpatialModel> model;
  sp::SpatialModalResult r;
  try {
    model = sp::buildSpatialModel(scene);
    sp::addFlexJoints(scene, initial.kin, *model);
    if (initial.end_force.squaredNorm() > 0.0) model->addTerm(std::make_unique<sp::EndLoad3>(initial.end_force));
    r = sp::computeSpatialModes(*model, sp::spatialEquilibrium(*model, initial.kin));
  } catch (const std::exception& e) {
    res.message = std::string("modal analysis failed: ") + e.what();
    return;
  }
  res.dofs = static_cast<int>(r.stiffness.rows());
  res.equilibrium_residual = r.equilibrium_residual;
  if (count > res.dofs) {
    res.message = "count: must be <= " + std::to_string(res.dofs) + " (the degrees of freedom of this line), got " +
                  std::to_string(count);
    return;
  }
  const Vec3 n = Vec3::UnitZ().cross(initial.plane_direction).normalized();  // the statics' plane's normal
  std::vector<SpatialMode>& modes = r.modes;
  sp::alignDegeneratePairs(modes, n);
  double big = 0.0;
  for (const SpatialMode& m : modes) big = std::max(big, std::abs(m.omega2));
  const int nb = model->bodies();
  res.points.resize(nb + 1);
  res.arc_length.resize(nb + 1);
  for (int p = 0; p <= nb; ++p) {
    const Vec3 x = p < nb ? r.equilibrium[p].A : r.equilibrium[nb - 1].end();
    res.points[p].x = x.x(), res.points[p].y = x.y(), res.points[p].z = x.z();
    res.arc_length[p] = p < nb ? model->rfe(p).s_begin : scene.length;
  }
  for (int k = 0; k < count; ++k) {
    const SpatialMode& m = modes[k];
    const bool oscillates = m.omega2 > kZeroOmega2 * big && m.omega > 0.0;
    res.periods.push_back(oscillates ? 2.0 * M_PI / m.omega : 0.0);
    res.frequencies.push_back(oscillates ? m.omega / (2.0 * M_PI) : 0.0);
    res.characters.push_back(sp::modeCharacter(m, n));
    res.axial_share.push_back(m.along_fraction);
    double scale = 0.0;
    for (const Vec3& v : m.displacement) scale = std::max(scale, v.norm());
    scale = scale > 0.0 ? 1.0 / scale : 0.0;
    for (const Vec3& v : m.displacement) {
      res.shape_x.push_back(scale * v.x());
      res.shape_y.push_back(scale * v.y());
      res.shape_z.push_back(scale * v.z());
    }
  }
  for (const auto* v : {&res.periods, &res.frequencies, &res.axial_share, &res.shape_x, &res.shape_y, &res.shape_z})
    for (double x : *v)
      if (!std::isfinite(x)) {
        res.message = "modal analysis gave non-finite values (ill-conditioned state?)";
        res.periods.clear(), res.frequencies.clear(), res.characters.clear(), res.axial_share.clear();
        res.shape_x.clear(), res.shape_y.clear(), res.shape_z.clear();
        return;
      }
  const std::string about = scene.initial.type == riser_sim::InitialKind::kStraight
                                ? std::string("equilibrium relaxed from the straight start (not one)")
                                : std::string(riser_sim::name(scene.initial.type)) + " static state";
  char buf[400];
  std::snprintf(buf, sizeof(buf),
                "%d modes of %d about the %s (3D); plane of in-plane modes along (%g, %g, 0); end load (%g, %g, %g) N "
                "kept as a dead load; undamped (drag and damping left out); equilibrium residual %.2e, K asymmetry "
                "%.2e%s",
                count, res.dofs, about.c_str(),
                initial.plane_direction.x(), initial.plane_direction.y(), initial.end_force.x(), initial.end_force.y(),
                initial.end_force.z(), r.equilibrium_residual, r.asymmetry,
                r.equilibrium_residual > 1e-6 ? " (not an equilibrium: modes not meaningful)" : "");
  res.message = buf;
  res.success = true;
}

}  // namespace riser_sim_ros
