// Every shipped scene in config/scenes, whole: its statics converge (in process) and every planar one run
// through the 3D path agrees with the planar CLI over 0.5 s. Release only: under the sanitizers (10-20x
// slower) each scene's statics and first steps run once, through the CLI (Cli.EveryShippedSceneRuns, and
// CliSpatial.PlanarScenesRunThroughTheSpatialPath for the planar ones in 3D; docs/hardening.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "cli_test_util.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

using namespace cli_test;
using namespace riser_sim;

TEST(SceneYaml, EveryShippedSceneParsesAndBuilds) {
  const std::filesystem::path dir = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    Scene s;
    ASSERT_NO_THROW(s = loadSceneFile(entry.path().string())) << entry.path();
    EXPECT_FALSE(s.name.empty());
    // The initial statics of every shipped scene converge (a 3D scene's through the 3D builder).
    StaticsResult statics;
    if (s.space == SpaceKind::kSpatial) {
      std::unique_ptr<spatial::Run3> run;
      EXPECT_NO_THROW(run = std::make_unique<spatial::Run3>(s));
      if (run) statics = run->initial().statics;
    } else {
      EXPECT_NO_THROW(buildSimulator(s, &statics));
    }
    EXPECT_TRUE(statics.converged) << statics.message;
  }
  EXPECT_GE(count, 2);  // at least paper_table1 and hanging_chain
}

// Every shipped planar scene with --set space=spatial: 0.5 s at the scene's own integrator and dt gives the
// planar CLI's top tension and end position (x, y_2D) = (x, z_3D), y_3D = 0; or, when the scene has a
// term the 3D core lacks, the refusal naming that section. Measured (rk4, the summary's 9 digits):
// hanging_chain and paper_table1 agree in every printed digit (paper_table1's displaced statics are solved
// mirrored, end_dx +50 m in the plane along -x). The 3D core itself agrees with the 2D one to 5e-13 m
// (docs/spatial.md); the tolerance 1e-8 m and 1e-8 of the tension is the statics' 1e-9 of the weight
// with margin.
TEST(CliSpatial, PlanarScenesThroughTheSpatialPath) {
  int compared = 0, refused = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string text = readFile(entry.path().string());
    if (text.find("\nspace: spatial") != std::string::npos) continue;  // not a planar scene
    SCOPED_TRACE(entry.path().string());
    const std::string base = "--scene " + entry.path().string() + " --duration 0.5 --summary --quiet";
    const CliRun r3 = runCli(base + " --set space=spatial");
    if (r3.code == 2) {
      ++refused;
      bool named = false;
      for (const char* section : {"seabed.stiffness_tangential", "internal_fluid"})
        if (r3.err.find(std::string("riser_sim_cli: error: ") + section + ": ") != std::string::npos &&
            text.find(std::string(section).substr(std::string(section).rfind('.') + 1) + ":") != std::string::npos)
          named = true;
      EXPECT_TRUE(named) << r3.err;
      EXPECT_NE(r3.err.find("not available with space: spatial yet"), std::string::npos) << r3.err;
      continue;
    }
    ASSERT_EQ(r3.code, 0) << r3.err;
    const CliRun r2 = runCli(base);
    ASSERT_EQ(r2.code, 0) << r2.err;
    auto j2 = summary(r2), j3 = summary(r3);
    EXPECT_EQ(j3["status"], "ok") << r3.out;
    EXPECT_EQ(j3["space"], "spatial");
    EXPECT_EQ(j3["steps"], j2["steps"]);
    EXPECT_NEAR(num(j3, "x_end"), num(j2, "x_end"), 1e-8);
    EXPECT_NEAR(num(j3, "z_end"), num(j2, "z_end"), 1e-8);
    EXPECT_NEAR(num(j3, "y_end"), 0.0, 1e-12);
    EXPECT_NEAR(num(j3, "tension_top"), num(j2, "tension_top"), 1e-8 * num(j2, "tension_top"));
    EXPECT_NEAR(num(j3, "tension_max"), num(j2, "tension_max"), 1e-8 * num(j2, "tension_max"));
    EXPECT_NEAR(num(j3, "top_force_y"), 0.0, 1e-9 * num(j2, "tension_top"));
    std::printf("[ measured ] %s: |dx| %.3g m, |dz| %.3g m, |dT|/T %.3g\n", entry.path().filename().c_str(),
                std::abs(num(j3, "x_end") - num(j2, "x_end")), std::abs(num(j3, "z_end") - num(j2, "z_end")),
                std::abs(num(j3, "tension_top") / num(j2, "tension_top") - 1.0));
    ++compared;
  }
  EXPECT_GE(compared, 4);  // hanging_chain, paper_table1, demo_riser, paper_riser_500m (C_M = 2)
  EXPECT_GE(refused, 1);   // paper_jlay_170m (internal flow, anchored seabed springs)
}
