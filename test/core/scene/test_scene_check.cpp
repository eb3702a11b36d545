// checkScene (scene_check.h) is the loader's solver and engine check: every shipped scene and variants of
// them (--set overrides) are accepted or refused by the loader exactly when checkScene accepts or refuses
// the same change made to the loaded Scene, naming the same key. The node calls checkScene too.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "riser_sim/scene/scene_check.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

namespace fs = std::filesystem;
const std::string kScenes = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/";

// The loader's answer: "" accepted, else the key it names.
std::string loaderKey(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    loadSceneFile(file, overrides);
    return "";
  } catch (const SceneError& e) {
    return e.key().empty() ? std::string("(no key) ") + e.what() : e.key();
  }
}

std::string checkKey(const Scene& scene) {
  const auto error = checkScene(scene);
  return error ? error->key : "";
}

TEST(SceneCheck, EveryShippedSceneIsAcceptedByTheLoaderAndByCheckScene) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".yaml") continue;
    const Scene scene = loadSceneFile(entry.path().string());
    EXPECT_EQ(checkKey(scene), "") << entry.path();
    ++n;
  }
  EXPECT_GE(n, 14);
}

// A change to a shipped scene: as --set overrides for the loader, and the same change to the Scene.
struct Variant {
  std::string scene;  // file in config/scenes
  std::vector<std::string> overrides;
  std::function<void(Scene&)> change;
  std::string key;  // expected: "" accepted, else the key both name
};

TEST(SceneCheck, TheLoaderAndCheckSceneAgreeOnVariants) {
  const std::vector<Variant> variants = {
      // 3D: what the planar limits would refuse, the 3D engine runs.
      {"spatial_swing.yaml",
       {"solver.jacobian=structured"},
       [](Scene& s) { s.solver.jacobian = JacobianKind::kStructured; },
       ""},
      {"spatial_swing.yaml",
       {"line.elements=600", "solver.integrator=midpoint"},
       [](Scene& s) { s.elements = 600, s.solver.integrator = IntegratorKind::kMidpoint; },
       ""},
      // 3D: what the 3D engine refuses.
      {"spatial_swing.yaml",
       {"solver.formulation=recursive"},
       [](Scene& s) { s.solver.formulation = FormulationKind::kRecursive; },
       "solver.formulation"},
      {"spatial_swing.yaml",
       {"line.elements=600", "solver.integrator=midpoint", "solver.jacobian=dense"},
       [](Scene& s) {
         s.elements = 600, s.solver.integrator = IntegratorKind::kMidpoint, s.solver.jacobian = JacobianKind::kDense;
       },
       "line.elements"},
      {"spatial_sea_riser.yaml",
       {"seabed.stiffness_tangential=1000"},
       [](Scene& s) { s.seabed.stiffness_tangential = 1000.0; },
       "seabed.stiffness_tangential"},
      // Planar: what the planar engine refuses.
      {"demo_riser.yaml",
       {"solver.jacobian=structured"},
       [](Scene& s) { s.solver.jacobian = JacobianKind::kStructured; },
       "solver.jacobian"},
      {"demo_riser.yaml",
       {"line.elements=600", "solver.integrator=midpoint"},
       [](Scene& s) { s.elements = 600, s.solver.integrator = IntegratorKind::kMidpoint; },
       "line.elements"},
      // Planar: a chain formulation has the structured solves.
      {"demo_riser.yaml",
       {"line.elements=600", "solver.integrator=midpoint", "solver.formulation=recursive"},
       [](Scene& s) {
         s.elements = 600, s.solver.integrator = IntegratorKind::kMidpoint;
         s.solver.formulation = FormulationKind::kRecursive;
       },
       ""},
      {"paper_table1.yaml",
       {"solver.jacobian=structured", "solver.formulation=independent"},
       [](Scene& s) {
         s.solver.jacobian = JacobianKind::kStructured, s.solver.formulation = FormulationKind::kIndependent;
       },
       ""},
      // The solver values, whatever the engine.
      {"demo_riser.yaml", {"solver.rho_inf=2"}, [](Scene& s) { s.solver.rho_inf = 2.0; }, "solver.rho_inf"},
      {"spatial_swing.yaml", {"solver.rho_inf=2"}, [](Scene& s) { s.solver.rho_inf = 2.0; }, "solver.rho_inf"},
      {"demo_riser.yaml",
       {"solver.newton_tolerance=0.1"},
       [](Scene& s) { s.solver.newton_tolerance = 0.1; },
       "solver.newton_tolerance"},
      {"spatial_flat_umbilical.yaml",
       {"solver.newton_tolerance=0.1"},
       [](Scene& s) { s.solver.newton_tolerance = 0.1; },
       "solver.newton_tolerance"},
  };
  for (const Variant& v : variants) {
    std::string what = v.scene;
    for (const auto& o : v.overrides) what += " --set " + o;
    Scene scene = loadSceneFile(kScenes + v.scene);
    v.change(scene);
    EXPECT_EQ(checkKey(scene), v.key) << what;
    EXPECT_EQ(loaderKey(kScenes + v.scene, v.overrides), v.key) << what;
  }
}

TEST(SceneCheck, ErrorsNameTheKeyAndSayWhy) {
  Scene scene = loadSceneFile(kScenes + "demo_riser.yaml");
  scene.solver.jacobian = JacobianKind::kStructured;
  const auto error = checkScene(scene);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->what().rfind("solver.jacobian: 'structured' needs solver.formulation independent or recursive", 0),
            0u)
      << error->what();
  scene = loadSceneFile(kScenes + "spatial_swing.yaml");
  scene.solver.formulation = FormulationKind::kIndependent;
  const auto spatial = checkScene(scene);
  ASSERT_TRUE(spatial);
  EXPECT_NE(spatial->what().find("'independent' is planar"), std::string::npos) << spatial->what();
}

}  // namespace
}  // namespace riser_sim
