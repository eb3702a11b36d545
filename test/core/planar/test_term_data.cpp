// Terms are immutable parts of the model; a term's history (the seabed's contact anchors) is run data
// owned by each Simulator. Two simulators on one model, stepped alternately, must each match a run
// alone bit for bit, and a modal analysis of the shared model in between must change nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/planar/modal.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

// The J-lay scene, coarser (n = 20): 3 of the 22 contact points lie on the seabed at the start.
Scene jlay() {
  return loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml",
                       {"line.elements=20", "initial.end_force=hold"});
}

std::unique_ptr<Simulator> simulator(const Scene& s, std::shared_ptr<const Model> model, const TopMotionSpec& top) {
  auto sim = std::make_unique<Simulator>(model, buildTopMotion(top), s.solver);
  StaticsProblem p = staticsProblem(s);
  const StaticsResult st = solveStatics(*model, p, 0.0);
  EXPECT_TRUE(st.converged) << st.message;
  sim->setInitialState(st.kin, 0.0);
  return sim;
}

TEST(TermData, SimulatorsSharingAModelRunIndependently) {
  Scene s = jlay();
  // The end load of initial.end_force: hold comes from buildSimulator; here the models are built by hand.
  s.initial.end_force = EndForceKind::kRelease;
  constexpr int kSteps = 4000;  // 2 s at dt = 5e-4 s
  // B drags its top fast along x: its touchdown moves by metres and its contacts lift off and touch down,
  // rewriting its anchors; A follows the scene's slow motion.
  TopMotionSpec fast = s.top;
  fast.period = 4.0;  // same start (x = 10 m), 20 m in 2 s

  auto alone = simulator(s, buildModel(s), s.top);
  for (int k = 0; k < kSteps; ++k) ASSERT_TRUE(alone->step());

  std::shared_ptr<const Model> shared = buildModel(s);
  auto a = simulator(s, shared, s.top);
  auto b = simulator(s, shared, fast);
  const auto* bed = dynamic_cast<const Seabed*>(shared->findTerm("seabed"));
  ASSERT_NE(bed, nullptr);
  const int contacts0 = bed->contacts(*shared, [&] {
    Kinematics kin(shared->bodies());
    a->kinematics(kin);
    return kin;
  }());
  int b_contacts_min = contacts0, b_contacts_max = contacts0;
  for (int k = 0; k < kSteps; ++k) {
    ASSERT_TRUE(a->step());
    ASSERT_TRUE(b->step());
    if (k == kSteps / 2) {  // a modal analysis of the same model in between
      const StaticsResult st = solveStatics(*shared, staticsProblem(s), 0.0);
      ModalOptions mo;
      mo.modes = 2;
      computeModes(*shared, st.kin, st.end_force, mo);
    }
    if (k % 100 == 0) {
      Kinematics kin(shared->bodies());
      b->kinematics(kin);
      const int c = bed->contacts(*shared, kin);
      b_contacts_min = std::min(b_contacts_min, c);
      b_contacts_max = std::max(b_contacts_max, c);
    }
  }
  // B really did rewrite contacts (else the test could not fail).
  EXPECT_GE(contacts0, 3);
  std::printf("[term_data] B: %d..%d contacts (A starts with %d)\n", b_contacts_min, b_contacts_max, contacts0);
  EXPECT_GT(b_contacts_max - b_contacts_min, 2) << "B's contacts: " << b_contacts_min << ".." << b_contacts_max;
  EXPECT_TRUE(a->state() == alone->state())
      << "max |difference| " << (a->state() - alone->state()).lpNorm<Eigen::Infinity>();
}

}  // namespace
}  // namespace riser_sim

namespace riser_sim {
namespace {

// ForceTerm::addForcesAndPower (what the simulation calls) equals addForces + power (what energy
// bookkeeping and the statics call) for every term, here every sea term on a moving J-lay in a current
// and waves, with both flow models. Same arithmetic in the same order: equal to round-off (1e-12).
TEST(TermData, FusedForcesAndPowerEqualSeparateCalls) {
  for (const char* flow : {"paper", "pipe_flow"}) {
    SCOPED_TRACE(flow);
    const Scene s =
        loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml",
                      {"line.elements=20", "internal_fluid.velocity=5", "internal_fluid.acceleration=0.5",
                       std::string("internal_fluid.model=") + flow, "line.axial_damping=1e6",
                       "line.bending_damping=1e5", "seabed.damping_normal=1e4", "environment.current.velocity=[0.5, 0]",
                       "environment.waves={height: 4, period: 8, depth: 80}"});
    auto sim = buildSimulator(s);
    ASSERT_TRUE(sim->advanceTo(0.5));  // moving: every velocity term is non-zero
    const Model& model = sim->model();
    Kinematics kin(model.bodies());
    sim->kinematics(kin);
    int checked = 0;
    for (const auto& term : model.terms()) {
      VecX Q1 = VecX::Zero(model.dofs()), Q2 = VecX::Zero(model.dofs());
      term->addForces(model, nullptr, kin, sim->time(), Q1);
      const double p1 = term->power(model, nullptr, kin, sim->time());
      const double p2 = term->addForcesAndPower(model, nullptr, kin, sim->time(), Q2);
      const double scale = std::max(Q1.lpNorm<Eigen::Infinity>(), 1.0);
      EXPECT_LT((Q1 - Q2).lpNorm<Eigen::Infinity>(), 1e-12 * scale) << term->name();
      EXPECT_NEAR(p1, p2, 1e-12 * std::max(std::abs(p1), 1.0)) << term->name();
      if (p1 != 0.0) ++checked;
    }
    EXPECT_GE(checked, 5) << "terms with power: drag, added mass, flow, springs' damping, seabed";
  }
}

}  // namespace
}  // namespace riser_sim
