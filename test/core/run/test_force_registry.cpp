// The force-term registry (force_registry.h): one table builds both engines' terms.
// - a planar scene with every term both engines share (gravity, springs, sea, drag, seabed, attachments) gives
//   the same term names in the same order in the planar Model and the spatial::Model3;
// - each row's name is the name() of the term it adds, and a term the scene does not want is not built.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "riser_sim/run/force_registry.h"
#include "riser_sim/planar/model.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

const char* kScene = R"(line:
  length: 60.0
  elements: 6
  EA: 1.0e7
  EI: 1.0e5
  mass_per_length: 100.0
  outer_diameter: 0.3
environment:
  water: {density: 1025.0, surface: 0.0}
hydrodynamics:
  drag_normal: 1.2
  drag_tangential: 0.1
seabed:
  level: -55.0
  stiffness_normal: 1.0e5
attachments:
  - arc_length: 30.0
    mass: 50.0
    volume: 0.1
    drag_area: 0.2
    cd: 1.0
)";

std::vector<std::string> planarNames(const Scene& s) {
  std::vector<std::string> out;
  const auto model = buildModel(s);  // held: a temporary's terms() would dangle in the loop
  for (const auto& t : model->terms()) out.push_back(t->name());
  return out;
}
std::vector<std::string> spatialNames(const Scene& s) {
  std::vector<std::string> out;
  const auto model = spatial::buildModel3(s);
  for (const auto& t : model->terms()) out.push_back(t->name());
  return out;
}

TEST(ForceRegistry, BothEnginesBuildTheSameTermsInTheSameOrder) {
  const Scene s = loadSceneText(kScene, "test_force_registry");
  const std::vector<std::string> expected = {"gravity",      "axial_spring", "bending_spring", "buoyancy",
                                             "morison_drag", "seabed",       "attachments"};
  EXPECT_EQ(planarNames(s), expected);
  EXPECT_EQ(spatialNames(s), expected);
}

TEST(ForceRegistry, RowsNameTheirTermsAndFollowTheScene) {
  const Scene s = loadSceneText(kScene, "test_force_registry");
  // Every term built is a wanted row's, in table order.
  std::vector<std::string> wanted;
  for (const ForceTermRow& row : forceTermRegistry())
    if (row.wanted(s)) wanted.push_back(row.name);
  size_t k = 0;
  for (const std::string& name : planarNames(s)) {
    while (k < wanted.size() && wanted[k] != name) ++k;
    EXPECT_LT(k, wanted.size()) << name << " is not a wanted row, or out of the table's order";
  }
  // Terms the scene switches off are not built.
  Scene off = s;
  off.seabed.enabled = false;
  off.attachments.clear();
  const std::vector<std::string> fewer = {"gravity", "axial_spring", "bending_spring", "buoyancy", "morison_drag"};
  EXPECT_EQ(planarNames(off), fewer);
  EXPECT_EQ(spatialNames(off), fewer);
  // C_M = 2 in still water: the planar engine's hydro_inertia term is the 3D added_mass (no Froude-Krylov force
  // without water acceleration), at the same place in the order.
  Scene cm = off;
  cm.hydro.inertia_coefficient = 2.0;
  std::vector<std::string> p = fewer, q = fewer;
  p.push_back("hydro_inertia");
  q.push_back("added_mass");
  EXPECT_EQ(planarNames(cm), p);
  EXPECT_EQ(spatialNames(cm), q);
}

}  // namespace
}  // namespace riser_sim
