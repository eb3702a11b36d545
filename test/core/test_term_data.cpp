// Terms are immutable parts of the model; a term's history (the seabed's contact anchors) is run data
// owned by each Simulator. Two simulators on one model, stepped alternately, must each match a run
// alone bit for bit, and a modal analysis of the shared model in between must change nothing.
#include <gtest/gtest.h>

#include <cstdio>

#include "riser_sim/force_term.h"
#include "riser_sim/forces/seabed.h"
#include "riser_sim/modal.h"
#include "riser_sim/scene.h"
#include "riser_sim/scene_yaml.h"

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
  s.initial.end_force = "release";
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
    a->formulation().kinematics(a->state(), kin);
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
      b->formulation().kinematics(b->state(), kin);
      const int c = bed->contacts(*shared, kin);
      b_contacts_min = std::min(b_contacts_min, c);
      b_contacts_max = std::max(b_contacts_max, c);
    }
  }
  // B really did rewrite contacts (else the test could not fail).
  EXPECT_GE(contacts0, 3);
  std::printf("[term_data] B: %d..%d contacts (A starts with %d)\n", b_contacts_min, b_contacts_max, contacts0);
  EXPECT_GT(b_contacts_max - b_contacts_min, 2) << "B's contacts: " << b_contacts_min << ".." << b_contacts_max;
  EXPECT_TRUE(a->state() == alone->state()) << "max |difference| "
                                            << (a->state() - alone->state()).lpNorm<Eigen::Infinity>();
}

}  // namespace
}  // namespace riser_sim
