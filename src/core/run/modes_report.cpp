#include "riser_sim/run/modes_report.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

#include "riser_sim/planar/modal.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/modal_characters.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {

namespace {

using Vec3 = Eigen::Vector3d;

ModeStatus statusOf(double omega2, double big) {
  if (omega2 < 0.0) return ModeStatus::kUnstable;
  return std::abs(omega2) <= spatial::kZeroOmega2 * big ? ModeStatus::kZero : ModeStatus::kOscillating;
}

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
  char buf[640];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof(buf), fmt, args);
  va_end(args);
  return buf;
}

ModesReport planarReport(const Scene& scene, int count) {
  ModalOptions o;
  o.modes = count;
  StaticsResult st;
  const ModalResult r = sceneModes(scene, o, &st);
  ModesReport rep;
  rep.space = SpaceKind::kPlanar;
  rep.coordinates = r.coordinates;
  rep.dofs = r.dofs;
  rep.equilibrium_residual = r.equilibrium_residual;
  rep.asymmetry = r.asymmetry;
  rep.about = scene.initial.type == InitialKind::kStraight
                  ? std::string("hanging equilibrium (initial.type straight is none)")
                  : std::string(name(scene.initial.type)) + " static state";
  rep.header = format(
      "modes about the static state (%s, %s), %d coordinates%s; end load (%g, %g) N kept as a dead "
      "load; undamped (drag and damping left out); equilibrium residual %.2e, K asymmetry %.2e",
      name(scene.initial.type), st.message.c_str(), r.coordinates, r.pinned ? " minus 2 end constraints (pinned)" : "",
      st.end_force.x(), st.end_force.y(), r.equilibrium_residual, r.asymmetry);
  rep.arc_length = r.arc_length;
  for (const Vec2& p : r.points) rep.points.emplace_back(p.x(), 0.0, p.y());
  double big = 0.0;
  for (const Mode& m : r.modes) big = std::max(big, std::abs(m.omega2));
  for (const Mode& m : r.modes) {  // sceneModes returns at most count
    ModeEntry e;
    e.omega2 = m.omega2, e.omega = m.omega, e.period = m.period, e.frequency = m.frequency;
    e.character = m.character;
    e.axial_share = m.axial_fraction;
    e.status = statusOf(m.omega2, big);
    for (const Vec2& d : m.displacement) e.displacement.emplace_back(d.x(), 0.0, d.y());  // already scaled to 1
    rep.modes.push_back(std::move(e));
  }
  return rep;
}

ModesReport spatialReport(const Scene& scene, int count) {
  namespace sp = spatial;
  if (scene.bottom == BottomBoundary::kPinned && scene.bottom_motion.type != MotionKind::kFixed &&
      scene.bottom_motion.type != MotionKind::kExternal)
    throw std::invalid_argument(
        "bottom.motion: the modes with space: spatial need a fixed or free bottom (the modes "
        "are about a static state)");
  const sp::InitialState3 init = sp::solveInitialState3(scene, sp::buildTopMotion3(scene.top)->at(0.0).p);
  // In the steady sea, as the statics (the modes are about the static state); the statics' end force on a free end
  // stays as a dead load (as the planar modes; a pinned end's anchor holds it).
  BuildOptions options3;
  options3.terms.steady_sea = true;
  if (scene.bottom != BottomBoundary::kPinned) options3.end_force = init.end_force;
  std::shared_ptr<sp::Model3> model = sp::buildModel3(scene, options3);
  sp::addFlexJoints(scene, init.kin, *model);
  // The equilibrium from the statics' state with their hang-off frame; a line twisted by its bending axes:
  // the equilibrium and the modes about it with its spins.
  AlignedVector<Vec3> axes = init.material_axes;
  sp::ModalOptions3 options;
  options.hang_off = init.hang_off;
  const sp::Kinematics3 eq = sp::equilibrium3(*model, init.kin, 20, options, &axes);
  sp::ModalResult3 r = sp::computeModes3(*model, eq, options, &axes);

  const Vec3 n = Vec3::UnitZ().cross(init.plane_direction).normalized();  // normal of the statics' plane
  sp::alignDegeneratePairs(r.modes, n);
  ModesReport rep;
  rep.space = SpaceKind::kSpatial;
  rep.coordinates = rep.dofs = static_cast<int>(r.stiffness.rows());
  rep.equilibrium_residual = r.equilibrium_residual;
  rep.asymmetry = r.asymmetry;
  const bool straight = scene.initial.type == InitialKind::kStraight;
  rep.about = straight ? std::string("equilibrium relaxed from the straight start (initial.type straight is none)")
                       : std::string(name(scene.initial.type)) + " static state";
  const std::string what = straight ? "3D modes about the " + rep.about
                                    : "3D modes about the static state (" + std::string(name(scene.initial.type)) +
                                          ", " + init.statics.message + ")";
  rep.header = format(
      "%s, %d coordinates; plane of in-plane modes along (%g, %g, 0); end load (%g, %g, %g) N kept "
      "as a dead load; undamped; equilibrium residual %.2e, K asymmetry %.2e",
      what.c_str(), rep.coordinates, init.plane_direction.x(), init.plane_direction.y(), init.end_force.x(),
      init.end_force.y(), init.end_force.z(), r.equilibrium_residual, r.asymmetry);
  const int nb = model->bodies();
  for (int p = 0; p <= nb; ++p) {
    rep.points.push_back(p < nb ? r.equilibrium[p].A : r.equilibrium[nb - 1].end());
    rep.arc_length.push_back(p < nb ? model->rfe(p).s_begin : scene.length);  // unstretched [m]
  }
  double big = 0.0;
  for (const sp::Mode3& m : r.modes) big = std::max(big, std::abs(m.omega2));
  const size_t shown = std::min(r.modes.size(), static_cast<size_t>(count));
  for (size_t k = 0; k < shown; ++k) {
    const sp::Mode3& m = r.modes[k];
    ModeEntry e;
    e.omega2 = m.omega2, e.omega = m.omega;
    e.period = m.omega > 0.0 ? 2.0 * M_PI / m.omega : 0.0;
    e.frequency = m.omega / (2.0 * M_PI);
    e.character = sp::modeCharacter(m, n);
    e.axial_share = m.along_fraction;
    e.status = statusOf(m.omega2, big);
    double scale = 0.0;
    for (const Vec3& v : m.displacement) scale = std::max(scale, v.norm());
    scale = scale > 0.0 ? 1.0 / scale : 0.0;
    for (const Vec3& v : m.displacement) e.displacement.push_back(scale * v);
    rep.modes.push_back(std::move(e));
  }
  return rep;
}

}  // namespace

const char* name(ModeStatus status) {
  switch (status) {
    case ModeStatus::kOscillating: return "oscillating";
    case ModeStatus::kZero: return "zero";
    case ModeStatus::kUnstable: return "unstable";
  }
  return "?";
}

const std::vector<std::string>& modeCharacters(SpaceKind space) {
  static const std::vector<std::string> planar = {"transverse", "axial"};
  static const std::vector<std::string> spatial = {"in-plane", "out-of-plane", "axial", "torsional"};
  return space == SpaceKind::kSpatial ? spatial : planar;
}

ModesReport sceneModesReport(const Scene& scene, int count) {
  if (count < 1) throw std::invalid_argument("count: must be >= 1, got " + std::to_string(count));
  return scene.space == SpaceKind::kSpatial ? spatialReport(scene, count) : planarReport(scene, count);
}

}  // namespace riser_sim
