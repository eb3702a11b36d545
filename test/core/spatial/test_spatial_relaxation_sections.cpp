// The 3D relaxation of a sectioned line in a current across its plane: the relaxation's model carries the current's
// static load (the drag on the line held still) with each section's own coefficients, once; a lazy wave whose
// buoyancy modules have their own drag comes to rest in a cross current from either side, as mirror images.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

// lazy_wave_fpso.yaml (sections; the modules' drag_normal 1.2 against the line's 1.0) without its waves and
// vessel motion (the turret at (0, 0, -15) m, in the plane y = 0 with the end), its current profile turned towards
// `heading_deg` (0: the riser's plane).
Scene lazyWave(double heading_deg) {
  const double h = heading_deg * M_PI / 180.0, c = std::cos(h), s = std::sin(h);
  const std::string profile = "environment.current.profile=[[0, " + std::to_string(0.9 * c) + ", " +
                              std::to_string(0.9 * s) + "], [300, " + std::to_string(0.3 * c) + ", " +
                              std::to_string(0.3 * s) + "]]";
  return loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/lazy_wave_fpso.yaml",
                       {"environment.waves=null", "top.motion=null", "top.position=[0, 0, -15]", profile});
}

VecX generalisedForces(const spatial::Model3& model, const spatial::Kinematics3& kin) {
  VecX Q = VecX::Zero(model.dofs());
  for (const auto& term : model.terms()) term->addForces(model, kin, 0.0, Q);
  return Q;
}

// On a line at rest the drag held still (the relaxation's) and the run's drag on the relative velocity are the same
// force, every section's coefficient counted once: the two models' generalised forces agree to round-off (1e-12 of
// the largest; the sums run in the same order).
TEST(SpatialRelaxationSections, DragHeldStillIsTheRunsDragAtRest) {
  const Scene s = lazyWave(90.0);
  const spatial::InitialState3 init = spatial::solveInitialState3(s, s.top.position);
  BuildOptions steady, held;
  steady.terms.steady_sea = held.terms.steady_sea = true;
  held.terms.drag_on_line_at_rest = true;
  const auto run = spatial::buildModel3(s, steady);
  const auto relaxed = spatial::buildModel3(s, held);
  ASSERT_EQ(run->terms().size(), relaxed->terms().size());
  const VecX a = generalisedForces(*run, init.kin), b = generalisedForces(*relaxed, init.kin);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-12 * a.cwiseAbs().maxCoeff());
}

// Across the plane from either side: both starts pass the builder's rest bound and stability check (they throw
// otherwise), leave the plane downstream by metres (the wave's lateral drag ~kN on a few kN/m of tension), and are
// mirror images in y = 0 to the relaxation's accuracy: it stops at 1e-2 of the rest bound (1.6e-3 m/s² here), a
// position error of ~that / ω² on the slowest lateral mode (ω² ≳ 1e-3 s⁻²: periods under ~200 s) ~1.6e-2 m;
// 0.05 m allows a factor 3.
TEST(SpatialRelaxationSections, LazyWaveRestsInACurrentAcrossItsPlane) {
  const Scene left = lazyWave(90.0), right = lazyWave(-90.0);
  const spatial::InitialState3 a = spatial::solveInitialState3(left, left.top.position);
  const spatial::InitialState3 b = spatial::solveInitialState3(right, right.top.position);
  EXPECT_LE(a.max_acceleration, a.acceleration_bound);
  double off = 0.0, mirror = 0.0;
  for (size_t i = 0; i < a.kin.size(); ++i) {
    const spatial::Vec3 p = a.kin[i].end(), q = b.kin[i].end();
    off = std::max(off, p.y());
    EXPECT_GT(p.y(), -1e-6) << "rfe " << i << " upstream of the plane";
    mirror = std::max(mirror, (p - spatial::Vec3(q.x(), -q.y(), q.z())).norm());
  }
  EXPECT_GT(off, 1.0);
  EXPECT_LT(mirror, 0.05);
}

}  // namespace
}  // namespace riser_sim
