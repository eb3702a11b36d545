// A flex joint holding a line out of the vertical, at rest: the joint's moment on the holder balances the
// moment of the line's weight about the hang-off, M = Σ_p (x_p - A_0) × m_p g (statics of the whole line:
// the top force acts at A_0). Exact at any equilibrium, whatever n; the equilibrium is reached by damping
// (bending, axial and joint dampers) from a straight line along the joint's axis.
#include <gtest/gtest.h>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

using spatial_test::weightMoment;

TEST(SpatialFlexJoint, MomentBalancesTheWeightAtRest) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();  // 10 m, 10 kg/m, 50 kg end mass
  s.segments = 6;
  s.props.EI = 1e5;  // stiff enough that the line hangs off the joint as a bent rod, not as a pendulum
  s.props.bending_damping = 300.0;
  s.props.axial_damping = 3e3;
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -9.81));
  // The joint's axis 40° off the vertical toward (1, 1)/√2; k = 2 m g L: the line sags well below it.
  const Vec3 axis = Vec3(std::sin(0.7) / std::sqrt(2.0), std::sin(0.7) / std::sqrt(2.0), -std::cos(0.7));
  const double k = 2.0 * (10.0 * 10.0 + 50.0) * 9.81 * 10.0;
  m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, axis, k, 2e4));
  const auto* joint = static_cast<const FlexJoint*>(m->terms().back().get());
  Simulator3 sim(m, std::make_unique<FixedMotion3>(Vec3::Zero()), IntegratorKind::kRk4);
  sim.reset(rigidChain(m->line(), Vec3::Zero(), std::vector<Vec3>(m->bodies(), axis), Vec3::Zero(), Vec3::Zero()), 0.0);
  const double h = 5e-4;  // rk4 well inside its limit (highest mode ~2e3 rad/s at n = 6)
  for (int k = 0; k < int(40.0 / h); ++k) ASSERT_TRUE(sim.step(h));
  Kinematics3 kin(m->bodies());
  sim.kinematics(kin);
  const Vec3 M = joint->moment(*m, kin, sim.time()), W = weightMoment(*m, kin);
  // At rest up to what is left of the motion after 40 s (kinetic energy ~1e-14 of m g L): measured
  // |M - W| = 6.3e-6 |W|, the inertia of that motion; bound 3e-5 |W|. A wrong sign or lever is O(|W|).
  std::printf("[flex joint] angle %.4f rad, |M| = %.6e N m, |M - W| / |W| = %.2e, T = %.2e J\n",
              joint->angle(*m, kin, sim.time()), M.norm(), (M - W).norm() / W.norm(), sim.kineticEnergy());
  EXPECT_GT(joint->angle(*m, kin, sim.time()), 0.05);  // the weight really bends the joint
  EXPECT_LT((M - W).norm(), 3e-5 * W.norm());
  EXPECT_LT(sim.kineticEnergy(), 1e-9 * (10.0 * 10.0 + 50.0) * 9.81 * 10.0);
}

// An axis more than 90° off the line at the start is refused naming the key: the spring's moment k θ heads for the
// fold at 180°, where its direction is undefined (a reversed axis would report no moment while wound by π).
// spatial_tether's line leaves the top towards the ROV 12 m away and 25 m down: +z is ~150° off it, -z ~30°.
TEST(SpatialFlexJoint, AxisTurnedRoundIsRefusedNamingTheKey) {
  const std::string file = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/spatial_tether.yaml";
  for (const char* end : {"top", "bottom"}) {
    const std::string key = std::string(end) + ".flex_joint.axis";
    // The bottom joint's axis points along the line away from the ROV: up-ish; -z is turned round there.
    const std::string turned = std::string(end) == "top" ? "[0, 0, 1]" : "[0, 0, -1]";
    const Scene scene = loadSceneFile(file, {key + "=" + turned, "solver.dt=0.002"});
    try {
      Run3 run(scene);
      ADD_FAILURE() << key << " " << turned << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(key + ": ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("at most 90 deg"), std::string::npos) << e.what();
    }
  }
  // Within 90°: accepted, the start loaded and said so, and the joint's moment reported.
  const Scene ok = loadSceneFile(file, {"top.flex_joint.axis=[0, 0, -1]"});
  Run3 run(ok);
  EXPECT_NE(run.initial().about.find("top.flex_joint turned"), std::string::npos) << run.initial().about;
  ASSERT_TRUE(run.step()) << run.divergenceReason();
  EXPECT_GT(run.maxTopMoment(), 0.0);
}

}  // namespace
}  // namespace riser_sim
