#include "initial_twist.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "riser_sim/spatial/forces/end_load.h"
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
  const std::shared_ptr<SpatialModel> model = buildSpatialModel(stillWater(scene));
  if (!held_end && scene.bottom != BottomBoundary::kPinned && init.end_force.squaredNorm() > 0.0)
    model->addTerm(std::make_unique<EndLoad3>(init.end_force));
  Kinematics3 kin = init.kin;
  AlignedVector<Vec3> axes;
  Vec3 n0 = kin[0].e.normalized();  // the top rfe of Newton's last guess (its hang-off frame's)
  const auto newton = [&](const SpatialModalOptions& options, int iterations) {
    Vec3 force = init.end_force;
    n0 = kin[0].e.normalized();
    try {
      kin = held_end ? spatialEquilibriumHeldEnd(*model, kin, xy, force, iterations, options, &axes)
                     : spatialEquilibrium(*model, kin, iterations, options, &axes);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string("initial: the equilibrium twisted by the bending axes (line.EI: [EI_1, "
                                           "EI_2]), Newton in 3D with the spins: ") + e.what());
    }
    init.end_force = force;
  };
  // A line bent between soft axes twists far from its untwisted guess, and Newton from there may land on an
  // unstable equilibrium (the stiff axis bent): every solve asks for a stable one (statics.h).
  SpatialModalOptions settle;
  settle.stable = true;
  newton(settle, 100);
  // Newton held the hang-off's frame made at its guess's top rfe, carried to the solution's; the run makes it at
  // the solution: solve again from the solution until the two agree.
  const Vec3& axis = scene.bending_axes.axis;
  double moved = 0.0;
  for (int pass = 0; pass < 6; ++pass) {
    if (pass > 0) newton(settle, 30);
    const Vec3 n1 = kin[0].e.normalized();
    const Vec3 held = minimalRotation(n0, n1, unitPerp(axis, n0)), made = unitPerp(axis, n1);
    moved = std::atan2(held.cross(made).norm(), held.dot(made));
    if (moved < 1e-12) {
      init.kin = kin;
      init.material_axes = axes;
      return;
    }
  }
  throw std::runtime_error("initial: the equilibrium twisted by the bending axes: the hang-off's frame still moves by " +
                           std::to_string(moved) + " rad after 6 passes of Newton");
}

}  // namespace detail
}  // namespace spatial
}  // namespace riser_sim
