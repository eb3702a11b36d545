// Every integrator x formulation x linear solve (structured, dense), on the Table 1 line, on the J-lay
// scene with every hydro term and on a pinned chain (the structured solve's end row): Simulator::step()
// allocates nothing after warm-up. Global operator
// new/delete are replaced by counting versions; the count is read around the stepping only.
#include <gtest/gtest.h>

#include <algorithm>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "validation_util.h"
#include "alloc_counter.h"

namespace riser_sim {
namespace {

constexpr int kWarmupSteps = 3;             // first Jacobian / FSAL / initial-step estimate happen here
constexpr int kCountedSteps = 40;           // spans several Jacobian refreshes (interval below)
constexpr double kDt = 1e-3;                // [s] stable for rk4 at n = 10 (limit ~1.9e-3 s)
constexpr double kJacobianInterval = 0.01;  // [s] refresh 4 times inside the counted steps

struct Case {
  const char* integrator;
  const char* formulation;
  bool axial;
  const char* jacobian = "auto";  // implicit schemes: auto (structured on the chain formulations) | dense
  bool hydro = false;             // the J-lay scene: drag, added mass, contents, 5 m/s flow, seabed
  bool pinned = false;            // the 10 m chain pinned at (6, -6) m, its top on a sinusoid
};

// The paper's J-lay scene at n = 10 with every hydro term switched on (flow too).
Scene jlayScene() {
  Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml");
  s.elements = 10;
  s.internal_fluid.velocity = 5.0;
  s.solver.dt = kDt;
  return s;
}

// config/scenes/hanging_chain.yaml pinned at the bottom, moving (the pinned end's Baumgarte row is active).
Scene pinnedScene() {
  Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/hanging_chain.yaml",
                          {"bottom.type=pinned", "bottom.position=[6, -6]", "initial.type=between_points",
                           "line.end_mass=0", "top.motion={type: sinusoid, amplitude: [0.5, 0.3], period: 2}"});
  s.solver.dt = kDt;
  return s;
}

// Warms sim up, then counts the allocations of kCountedSteps steps.
void countStepAllocations(Simulator& sim, long& allocations) {
  for (int k = 0; k < kWarmupSteps; ++k) ASSERT_TRUE(sim.step()) << sim.divergenceReason();
  const long before = g_allocations.load();
  bool ok = true;
  for (int k = 0; k < kCountedSteps && ok; ++k) ok = sim.step();
  allocations = g_allocations.load() - before;
  ASSERT_TRUE(ok) << sim.divergenceReason();
}

class NoAlloc : public ::testing::TestWithParam<Case> {};

TEST_P(NoAlloc, StepDoesNotAllocate) {
  const Case c = GetParam();
  Scene s = c.hydro ? jlayScene() : c.pinned ? pinnedScene() : validation::table1Scene(10, kDt);
  s.options.axial_flexibility = c.axial;
  s.solver.jacobian = toChoice<JacobianKind>(c.jacobian);
  s.solver.integrator = toChoice<IntegratorKind>(c.integrator);
  s.solver.formulation = toChoice<FormulationKind>(c.formulation);
  s.solver.jacobian_interval = kJacobianInterval;
  s.solver.tolerance = 1e-7;
  auto sim = buildSimulator(s);
  long allocations = -1;
  ASSERT_NO_FATAL_FAILURE(countStepAllocations(*sim, allocations));
  EXPECT_EQ(allocations, 0) << c.integrator << " / " << c.formulation << (c.axial ? "" : " (inextensible)") << " / "
                            << c.jacobian << (c.hydro ? " / J-lay hydro" : "") << (c.pinned ? " / pinned" : "");
  if (isImplicitIntegrator(s.solver.integrator))
    EXPECT_GE(sim->integrator().stats().jacobians, 3) << "the counted steps should include Jacobian refreshes";
}

// Every integrator's name (choices.h), or only the implicit ones: a new integrator is counted without an
// edit here.
std::vector<const char*> integrators(bool implicit_only) {
  std::vector<const char*> out;
  for (const auto& [kind, name] : Choices<IntegratorKind>::names)
    if (!implicit_only || isImplicitIntegrator(kind)) out.push_back(name);
  return out;
}

std::vector<Case> allCases() {
  std::vector<Case> out;
  for (const char* i : integrators(false))
    for (const char* f : {"absolute", "independent", "recursive"})
      for (bool axial : {true, false}) out.push_back({i, f, axial});
  for (const char* i : integrators(true))  // the dense path on the chain formulations
    for (bool axial : {true, false}) out.push_back({i, "recursive", axial, "dense"});
  for (const char* i : integrators(false))  // every hydro term, both solves
    for (const char* f : {"absolute", "recursive"}) out.push_back({i, f, true, "auto", true});
  for (const char* i : integrators(true))  // pinned bottom: both solves, both chain formulations
    for (const char* f : {"independent", "recursive"})
      for (const char* j : {"auto", "dense"}) out.push_back({i, f, true, j, false, true});
  return out;
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  return std::string(c.integrator) + "_" + c.formulation + (c.axial ? "" : "_inextensible") +
         (std::string(c.jacobian) == "dense" ? "_dense" : "") + (c.hydro ? "_jlay_hydro" : "") +
         (c.pinned ? "_pinned" : "");
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, NoAlloc, ::testing::ValuesIn(allCases()), caseName);

// Every sea term at once (the J-lay scene: buoyancy, drag, added mass, seabed contacts with their
// anchors as run data, internal flow of both models, end load, plus current and waves), explicit and
// implicit with the structured solves.
TEST(NoAllocSea, StepWithEverySeaTermDoesNotAllocate) {
  for (const char* flow : {"paper", "pipe_flow"})
    for (const char* integ : {"rk4", "rosenbrock2"}) {
      SCOPED_TRACE(std::string(flow) + " / " + integ);
      const bool implicit = std::string(integ) == "rosenbrock2";
      Scene s = loadSceneFile(
          std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml",
          {"internal_fluid.velocity=5", std::string("internal_fluid.model=") + flow, "initial.end_force=hold",
           "environment.current.velocity=[0.5, 0]", "environment.waves={height: 2, period: 8, depth: 80}",
           std::string("solver.integrator=") + integ,
           std::string("solver.formulation=") + (implicit ? "recursive" : "absolute"),
           "solver.jacobian_interval=0.002"});
      auto sim = buildSimulator(s);
      std::vector<std::string> names;
      for (const auto& t : sim->model().terms()) names.push_back(t->name());
      for (const char* want : {"buoyancy", "morison_drag", "hydro_inertia", "seabed", "end_load"})
        EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
      long allocations = -1;
      ASSERT_NO_FATAL_FAILURE(countStepAllocations(*sim, allocations));
      EXPECT_EQ(allocations, 0);
    }
}

}  // namespace
}  // namespace riser_sim
