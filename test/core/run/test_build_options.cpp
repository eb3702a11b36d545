// The builders' options (build_options.h): a model's variants come from the scene plus options, never from an edited
// scene copy. Each option is checked against the scene that says the same thing in its own keys (the loader's path,
// independent of the option's code), or against the force it must add:
// - steady_sea: the forces of the scene with its waves equal those of the scene without the waves key;
// - seabed_friction off: the forces of a line sliding on the seabed equal those with the friction keys at 0;
// - end_force: adds exactly F at the line's end (both engines), pinned_at moves the anchor, and neither is taken by
//   an end that cannot carry it (named errors); the planar builder refuses the 3D-only options by name;
// - Spins::kRelaxation: the spins' inertias the relaxation chooses (relaxation.h), the rest as the scene's.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "riser_sim/planar/model.h"
#include "riser_sim/run/build_options.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

using spatial::Vec3;

const char* kScene = R"(space: spatial
line:
  length: 60.0
  elements: 6
  EA: 1.0e7
  EI: 1.0e5
  mass_per_length: 100.0
  outer_diameter: 0.3
environment:
  water: {density: 1025.0, surface: 0.0}
  current: {velocity: [0.4, 0.3, 0.0]}
  waves: {height: 4.0, period: 9.0, heading: 0.7}
hydrodynamics:
  drag_normal: 1.2
  drag_tangential: 0.1
seabed:
  level: -55.0
  stiffness_normal: 1.0e5
  damping_normal: 1.0e3
  friction_axial: 0.5
  friction_lateral: 0.8
  damping_tangential: 2.0e3
attachments:
  - arc_length: 30.0
    mass: 50.0
    volume: 0.1
    drag_area: 0.2
    cd: 1.0
    seabed_contact: true
)";

Scene scene(const std::vector<std::string>& sets = {}) { return loadSceneText(kScene, "test_build_options", sets); }

// A line lying along x on the seabed (its points 0.05 m in it), sliding at (0.3, 0.2, 0) m/s and turning, so every
// term sees a velocity relative to the water and to the bed.
spatial::Kinematics3 sliding(const Scene& s) {
  spatial::Kinematics3 kin(s.elements + 1);
  const double l = s.length / s.elements;
  for (size_t i = 0; i < kin.size(); ++i) {
    spatial::BodyKinematics3& b = kin[i];
    const double len = (i == 0 || i + 1 == kin.size()) ? 0.5 * l : l;
    b.A = Vec3(i == 0 ? 0.0 : (i - 0.5) * l, 0.0, s.seabed.level - 0.05);
    b.e = Vec3::UnitX();
    b.len = len;
    b.delta = 0.0;
    b.A_dot = Vec3(0.3, 0.2, 0.0);
    b.e_dot = Vec3(0.0, 0.01, 0.0);
  }
  return kin;
}

VecX forces(const spatial::Model3& m, const spatial::Kinematics3& kin, double t) {
  VecX Q = VecX::Zero(m.dofs());
  for (const auto& term : m.terms()) term->addForces(m, kin, t, Q);
  return Q;
}

// Equal to round-off: the same terms sum the same numbers in the same order (1e-12 of the largest).
void expectSame(const VecX& a, const VecX& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-12 * a.cwiseAbs().maxCoeff());
}

TEST(BuildOptions, SteadySeaIsTheSceneWithoutItsWaves) {
  const Scene waves = scene(), calm = scene({"environment.waves=null"});
  BuildOptions steady;
  steady.terms.steady_sea = true;
  const auto with_option = spatial::buildModel3(waves, steady), without_waves = spatial::buildModel3(calm);
  const auto with_waves = spatial::buildModel3(waves);
  const spatial::Kinematics3 kin = sliding(waves);
  for (double t : {0.0, 2.5}) {
    expectSame(forces(*with_option, kin, t), forces(*without_waves, kin, t));
    // The option does something: the waves' forces differ from the steady sea's by more than round-off.
    EXPECT_GT((forces(*with_waves, kin, t) - forces(*without_waves, kin, t)).cwiseAbs().maxCoeff(), 1.0) << t;
  }
}

// The planar engine's steady sea: the same equality in its coordinates (the scene in its x-z plane).
TEST(BuildOptions, PlanarSteadySeaIsTheSceneWithoutItsWaves) {
  Scene waves = scene({"seabed.friction_axial=null", "seabed.friction_lateral=null", "seabed.damping_tangential=null"}),
        calm = waves;
  waves.space = calm.space = SpaceKind::kPlanar;
  calm.water.waves = WaveSpec();
  BuildOptions steady;
  steady.terms.steady_sea = true;
  const auto with_option = buildModel(waves, steady), without_waves = buildModel(calm), with_waves = buildModel(waves);
  const Kinematics kin = straightLine(*with_waves, Vec2(0.0, -10.0), -0.3);
  const auto planarForces = [&](const Model& m, double t) {
    VecX Q = VecX::Zero(m.dofs());
    for (const auto& term : m.terms()) term->addForces(m, nullptr, kin, t, Q);
    return Q;
  };
  for (double t : {0.0, 2.5}) {
    expectSame(planarForces(*with_option, t), planarForces(*without_waves, t));
    EXPECT_GT((planarForces(*with_waves, t) - planarForces(*without_waves, t)).cwiseAbs().maxCoeff(), 1.0) << t;
  }
}

TEST(BuildOptions, SeabedWithoutFrictionIsTheSceneWithItsFrictionKeysAtZero) {
  const Scene rough = scene(),
              smooth = scene({"seabed.friction_axial=0", "seabed.friction_lateral=0", "seabed.damping_tangential=0"});
  BuildOptions o;
  o.terms.seabed_friction = false;
  const spatial::Kinematics3 kin = sliding(rough);
  const VecX a = forces(*spatial::buildModel3(rough, o), kin, 0.0), b = forces(*spatial::buildModel3(smooth), kin, 0.0);
  expectSame(a, b);
  EXPECT_GT((forces(*spatial::buildModel3(rough), kin, 0.0) - b).cwiseAbs().maxCoeff(), 1.0);
}

// The end load's generalised force on the last rfe: the point force F at its end E = A + (l + Δ) e, i.e. F on A's
// rows, F·e on Δ's and (l + Δ) F on e's (natural coordinates, spatial/kinematics.h).
TEST(BuildOptions, EndForceAddsTheForceAtTheEndInBothEngines) {
  const Scene s = scene({"environment.waves=null"});
  const Vec3 F(3.0e3, -2.0e3, 1.5e3);
  BuildOptions o;
  o.end_force = F;
  const spatial::Kinematics3 kin = sliding(s);
  const VecX d = forces(*spatial::buildModel3(s, o), kin, 0.0) - forces(*spatial::buildModel3(s), kin, 0.0);
  const int n = s.elements;
  const spatial::BodyKinematics3& b = kin[n];
  const double* q = d.data() + spatial::kDofPerBody3 * n;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(q[spatial::kA + k], F[k], 1e-9 * F.norm()) << k;
    EXPECT_NEAR(q[spatial::kE + k], b.len * F[k], 1e-9 * F.norm() * b.len) << k;
  }
  EXPECT_NEAR(q[spatial::kDelta3], F.dot(b.e), 1e-9 * F.norm());
  EXPECT_LE(d.head(spatial::kDofPerBody3 * n).cwiseAbs().maxCoeff(), 1e-9 * F.norm());

  // Planar: F's x and z on the end's x and y rows (the planar EndLoad: paper eq. 6's coordinates).
  Scene p = s;
  p.space = SpaceKind::kPlanar;
  const auto plain = buildModel(p), loaded = buildModel(p, o);
  const Kinematics kin2 = straightLine(*plain, Vec2(0.0, -10.0), -0.3);
  VecX Q0 = VecX::Zero(plain->dofs()), Q1 = VecX::Zero(plain->dofs());
  for (const auto& t : plain->terms()) t->addForces(*plain, nullptr, kin2, 0.0, Q0);
  for (const auto& t : loaded->terms()) t->addForces(*loaded, nullptr, kin2, 0.0, Q1);
  const VecX d2 = Q1 - Q0;
  EXPECT_NEAR(d2[kDofPerBody * n + kX], F.x(), 1e-9 * F.norm());
  EXPECT_NEAR(d2[kDofPerBody * n + kY], F.z(), 1e-9 * F.norm());
}

TEST(BuildOptions, AnEndThatCannotCarryAnOptionRefusesIt) {
  const Scene free_end = scene();
  const Scene pinned = scene({"bottom.type=pinned", "bottom.position=[40, 0, -50]", "initial.type=between_points"});
  BuildOptions load, anchor;
  load.end_force = Vec3(1.0, 0.0, 0.0);
  anchor.pinned_at = Vec3(41.0, 0.0, -50.0);
  EXPECT_THROW(spatial::buildModel3(pinned, load), std::invalid_argument);
  EXPECT_THROW(spatial::buildModel3(free_end, anchor), std::invalid_argument);
  EXPECT_EQ(spatial::buildModel3(pinned, anchor)->bottomPoint(), *anchor.pinned_at);
  Scene p = pinned;
  p.space = SpaceKind::kPlanar;
  EXPECT_THROW(buildModel(p, load), std::invalid_argument);
  EXPECT_EQ(buildModel(p, anchor)->bottomPoint(), Vec2(41.0, -50.0));
  // The 3D-only options, by name.
  BuildOptions damped, held, spins;
  damped.mass_damping = 0.1;
  held.terms.drag_on_line_at_rest = true;
  spins.spins = BuildOptions::Spins::kOff;
  for (const BuildOptions* o : {&damped, &held, &spins}) {
    try {
      buildModel(p, *o);
      ADD_FAILURE() << "the planar builder took a 3D-only option";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("terms.steady_sea, pinned_at and end_force only"), std::string::npos)
          << e.what();
    }
  }
}

// The relaxation's spins: no end body's polar inertia, the line's at most a solid rod's m D^2 / 8; off: no spins.
TEST(BuildOptions, RelaxationSpinsCapTheInertiasAndKeepTheStiffness) {
  const Scene s =
      scene({"line.torsion={stiffness: 2.0e5, polar_inertia: 9.0, end_polar_inertia: 40.0}", "environment.waves=null"});
  BuildOptions relax, off;
  relax.spins = BuildOptions::Spins::kRelaxation;
  off.spins = BuildOptions::Spins::kOff;
  const auto as_scene = spatial::buildModel3(s), relaxed = spatial::buildModel3(s, relax);
  ASSERT_TRUE(as_scene->hasTorsion());
  EXPECT_EQ(as_scene->torsion().polar_inertia, 9.0);
  EXPECT_EQ(as_scene->torsion().end_polar_inertia, 40.0);
  EXPECT_DOUBLE_EQ(relaxed->torsion().polar_inertia, 100.0 * 0.3 * 0.3 / 8.0);
  EXPECT_EQ(relaxed->torsion().end_polar_inertia, 0.0);
  EXPECT_EQ(relaxed->torsion().stiffness, 2.0e5);
  EXPECT_FALSE(spatial::buildModel3(s, off)->hasTorsion());
}

}  // namespace
}  // namespace riser_sim
