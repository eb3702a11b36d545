// sceneModesReport (modes_report.h): either engine's modes of a scene as one report. Planar: the modal
// analysis' own numbers, (x, y) as (x, 0, y); 3D: what the statics' equilibrium gives, with what it is about;
// counts and bad input refused naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "riser_sim/planar/modal.h"
#include "riser_sim/run/modes_report.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

const std::string kScenes = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/";

void expectWellFormed(const ModesReport& r, const std::string& what) {
  const auto& names = modeCharacters(r.space);
  ASSERT_EQ(r.points.size(), r.arc_length.size()) << what;
  for (const ModeEntry& m : r.modes) {
    EXPECT_NE(std::find(names.begin(), names.end(), m.character), names.end()) << what << ": " << m.character;
    ASSERT_EQ(m.displacement.size(), r.points.size()) << what;
    double big = 0.0;
    for (const auto& d : m.displacement) big = std::max(big, d.norm());
    EXPECT_NEAR(big, 1.0, 1e-12) << what;
    if (m.status == ModeStatus::kOscillating) {
      EXPECT_NEAR(m.period * m.frequency, 1.0, 1e-12) << what;
      EXPECT_NEAR(m.omega * m.omega, m.omega2, 1e-12 * m.omega2) << what;
    }
  }
}

TEST(ModesReport, PlanarIsTheModalAnalysisInThreeDimensions) {
  const Scene scene = loadSceneFile(kScenes + "paper_table1.yaml");
  ModalOptions o;
  o.modes = 5;
  const ModalResult ref = sceneModes(scene, o);
  const ModesReport r = sceneModesReport(scene, 5);
  expectWellFormed(r, "paper_table1");
  EXPECT_EQ(r.space, SpaceKind::kPlanar);
  EXPECT_EQ(r.dofs, ref.dofs);
  EXPECT_EQ(r.coordinates, ref.coordinates);
  EXPECT_EQ(r.about, "displaced static state");
  EXPECT_EQ(r.header.rfind("modes about the static state (displaced, ", 0), 0u) << r.header;
  ASSERT_EQ(r.modes.size(), 5u);
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(r.modes[k].period, ref.modes[k].period);
    EXPECT_EQ(r.modes[k].character, ref.modes[k].character);
    EXPECT_EQ(r.modes[k].axial_share, ref.modes[k].axial_fraction);
    EXPECT_EQ(r.modes[k].status, ModeStatus::kOscillating);
    for (size_t p = 0; p < ref.points.size(); ++p) {
      EXPECT_EQ(r.modes[k].displacement[p],
                Eigen::Vector3d(ref.modes[k].displacement[p].x(), 0.0, ref.modes[k].displacement[p].y()));
    }
  }
  for (size_t p = 0; p < ref.points.size(); ++p)
    EXPECT_EQ(r.points[p], Eigen::Vector3d(ref.points[p].x(), 0.0, ref.points[p].y()));
}

// The twisted umbilical: the statics' hang-off frame and material axes carry into the equilibrium the modes are
// about (without them Newton does not converge there).
TEST(ModesReport, SpatialTwistedUmbilical) {
  const Scene scene = loadSceneFile(kScenes + "spatial_flat_umbilical.yaml");
  const ModesReport r = sceneModesReport(scene, 4);
  expectWellFormed(r, "spatial_flat_umbilical");
  EXPECT_EQ(r.space, SpaceKind::kSpatial);
  EXPECT_EQ(r.about, "between_points static state");
  EXPECT_EQ(r.header.rfind("3D modes about the static state (between_points, ", 0), 0u) << r.header;
  EXPECT_LT(r.equilibrium_residual, 1e-9);
  ASSERT_EQ(r.modes.size(), 4u);
  // riser_sim_cli --modes 4 on the file (6 printed digits).
  const double periods[] = {4.25569, 2.30573, 2.03447, 1.46806};
  const char* characters[] = {"out-of-plane", "in-plane", "out-of-plane", "in-plane"};
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.modes[k].period / periods[k], 1.0, 5e-6) << k;  // half the last printed digit
    EXPECT_EQ(r.modes[k].character, characters[k]) << k;
  }
  EXPECT_EQ(r.points.size(), size_t(scene.elements) + 2);
  EXPECT_NEAR(r.points.back().x(), 25.0, 1e-6);  // the anchor
  EXPECT_NEAR(r.points.back().z(), -30.0, 1e-6);
}

// A straight 3D start is no equilibrium: the report names the one the modes are about.
TEST(ModesReport, SpatialStraightStartNamesTheEquilibrium) {
  const Scene scene = loadSceneFile(kScenes + "hanging_chain.yaml", {"space=spatial"});
  ASSERT_EQ(scene.initial.type, InitialKind::kStraight);
  const ModesReport r = sceneModesReport(scene, 6);
  expectWellFormed(r, "hanging_chain 3D");
  EXPECT_EQ(r.about.rfind("equilibrium relaxed from the straight start", 0), 0u) << r.about;
  EXPECT_EQ(r.header.find("static state (straight"), std::string::npos) << r.header;
  EXPECT_NE(r.header.find(r.about), std::string::npos) << r.header;
  // The planar report of the same chain: a hanging equilibrium, and the in-plane 3D modes have its periods.
  const ModesReport p = sceneModesReport(loadSceneFile(kScenes + "hanging_chain.yaml"), 3);
  EXPECT_EQ(p.about, "hanging equilibrium (initial.type straight is none)");
  int matched = 0;
  for (const ModeEntry& m : r.modes)
    for (const ModeEntry& q : p.modes) matched += std::abs(m.period / q.period - 1.0) < 1e-6;
  EXPECT_GE(matched, 3);
}

// The modes are about the static state, in the steady sea as the statics: waves that are not ramped in (full
// height at t = 0) leave them as they are without the waves, in both engines (the same model: 1e-12 of the period).
// spatial_sea_riser.yaml (3D, JONSWAP Hs 3 m) and the same scene planar.
TEST(ModesReport, WavesAtTheStartDoNotMoveTheModes) {
  for (const char* space : {"space=spatial", "space=planar"}) {
    SCOPED_TRACE(space);
    const bool planar = std::string(space) == "space=planar";
    // Planar: the same sea along +x (a planar scene's waves have no heading).
    std::vector<std::string> keys = {space, planar ? "environment.waves={type: jonswap, significant_height: 3.0, "
                                                     "peak_period: 9.0, gamma: 3.3, components: 40, seed: 7, "
                                                     "depth: 100.0}"
                                                   : "environment.waves.ramp=0"};
    if (planar)
      for (const char* k : {"seabed.friction_axial=null", "seabed.friction_lateral=null", "top.motion=null",
                            "environment.current.profile=[[0.0, 0.6], [100.0, 0.2]]"})
        keys.push_back(k);
    const Scene waves = loadSceneFile(kScenes + "spatial_sea_riser.yaml", keys);
    keys[1] = "environment.waves=null";
    const Scene calm = loadSceneFile(kScenes + "spatial_sea_riser.yaml", keys);
    const ModesReport a = sceneModesReport(waves, 3), b = sceneModesReport(calm, 3);
    ASSERT_EQ(a.modes.size(), 3u);
    ASSERT_EQ(b.modes.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.modes[k].period, b.modes[k].period, 1e-12 * b.modes[k].period) << k;
  }
}

TEST(ModesReport, CountsAndBadInput) {
  const Scene scene = loadSceneFile(kScenes + "paper_table1.yaml");
  for (int bad : {0, -2}) {
    try {
      sceneModesReport(scene, bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "count: must be >= 1, got " + std::to_string(bad));
    }
  }
  const ModesReport all = sceneModesReport(scene, 1000);  // more than there are: all of them
  EXPECT_EQ(all.modes.size(), size_t(all.dofs));
  const ModesReport all3 = sceneModesReport(loadSceneFile(kScenes + "spatial_swing.yaml"), 1000);
  EXPECT_EQ(all3.modes.size(), size_t(all3.dofs));
  try {  // a bottom that moves has no static state
    sceneModesReport(loadSceneFile(kScenes + "spatial_tether.yaml"), 3);
    ADD_FAILURE() << "spatial_tether: a moving bottom";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("bottom.motion: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace riser_sim
