#include "initial_twist.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "riser_sim/spatial/relaxation.h"
#include "riser_sim/spatial/statics.h"

namespace riser_sim {
namespace spatial {
namespace detail {

namespace {
Vec3 unitPerp(const Vec3& x, const Vec3& n) { return (x - x.dot(n) * n).normalized(); }
}  // namespace

double planarBendingStiffness(const Scene& scene, const Vec3& normal, bool& principal) {
  const BendingAxesSpec& b = scene.bending_axes;
  const double c = std::abs(normal.dot(b.axis.normalized()));
  principal = c > 1.0 - 1e-12 || c < 1e-12;
  return c > 1.0 - 1e-12 ? b.EI1 : c < 1e-12 ? b.EI2 : 0.5 * (b.EI1 + b.EI2);
}

void twistedEquilibrium(const Scene& scene, bool held_end, const Vec2& xy, InitialState3& init) {
  // In the steady sea; a free end under the start's end force unless Newton holds it (a pinned one at its anchor).
  BuildOptions o;
  o.terms.steady_sea = true;
  if (!held_end && scene.bottom != BottomBoundary::kPinned) o.end_force = init.end_force;
  const std::shared_ptr<Model3> model = buildModel3(scene, o);
  // A line bent between soft axes twists far from its untwisted guess, and Newton from there may land on an
  // unstable equilibrium (the stiff axis bent): ask for a stable one (statics.h).
  ModalOptions3 settle;
  settle.stable = true;
  // The hang-off's twist frame: line.bending_axis across the guess's top rfe, the joint's axis along it. Held as
  // given by Newton and by the run (its axis is part of the joint's law: torsion.h, HangOff).
  const Vec3 n0 = init.kin[0].e.normalized();
  settle.hang_off.axis = n0;
  settle.hang_off.ref = unitPerp(scene.bending_axes.axis, n0);
  AlignedVector<Vec3> axes;
  Vec3 force = init.end_force;
  Kinematics3 kin = init.kin;
  const auto newton = [&] {
    kin = held_end ? equilibriumHeldEnd3(*model, kin, xy, force, 100, settle, &axes)
                   : equilibrium3(*model, kin, 100, settle, &axes);
  };
  try {
    newton();
  } catch (const std::runtime_error& first) {
    // Far from its guess (a current across the plane, a swivel top), the shifted Newton can stall: dynamic
    // relaxation (relaxation.h: the spins and the hang-off's frame with it) brings the line near, Newton finishes.
    try {
      const Relaxed3 r = relaxToRest(scene, init.kin, init.kin[0].A, 1e5 * init.acceleration_bound, init.end_force,
                                     1e5 * init.twist_moment_bound);
      kin = r.kin;
      axes = r.material_axes;
      settle.hang_off = r.hang_off;
      force = init.end_force;
      newton();
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string("initial: the equilibrium twisted by the bending axes (line.EI: [EI_1, "
                                           "EI_2]), Newton in 3D with the spins: ") +
                               first.what() + "; from a dynamic relaxation: " + e.what());
    }
  }
  init.kin = kin;
  init.material_axes = axes;
  init.end_force = force;
  init.hang_off = settle.hang_off;
}

}  // namespace detail
}  // namespace spatial
}  // namespace riser_sim
