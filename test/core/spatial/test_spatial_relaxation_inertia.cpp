// The 3D statics do not depend on inertia: the dynamic relaxation chooses its own spin inertia, so an end body's
// polar inertia (a slow, lightly damped torsional mode that outlasted the relaxation's budget) no longer decides
// whether the start converges.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {
namespace {

spatial::InitialState3 tetherStart(double end_polar_inertia, double GJ = 10.0, bool torsion = true) {
  std::vector<std::string> set = {"environment.current.velocity=[0, 0.3, 0]"};  // across the top-anchor plane
  if (torsion)
    set.push_back("line.torsion={stiffness: " + std::to_string(GJ) +
                  ", end_polar_inertia: " + std::to_string(end_polar_inertia) + "}");
  const Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/rov_tether.yaml", set);
  return spatial::solveInitialState3(s, s.top.position);
}

TEST(SpatialRelaxationInertia, EndPolarInertiaDoesNotChangeTheStart) {
  const spatial::InitialState3 a = tetherStart(0.0), b = tetherStart(1.0), c = tetherStart(100.0);
  // Both relax to the same rest: the relaxation stops at 1e-2 of the rest bound (~4e-7 m/s² here), a position
  // error of ~that / ω1² (ω1² ~ g_wet / L ~ 0.02 s⁻²): ~2e-5 m; 1e-4 m leaves a factor 5.
  double d = 0.0;
  for (size_t i = 0; i < a.kin.size(); ++i)
    d = std::max({d, (a.kin[i].end() - b.kin[i].end()).norm(), (a.kin[i].end() - c.kin[i].end()).norm()});
  EXPECT_LT(d, 1e-4);
  double off = 0.0;  // the cross current moves it out of its plane (y = 0 .. -0.5 m)
  for (const auto& k : a.kin) off = std::max(off, std::abs(k.end().y()));
  EXPECT_GT(off, 1.0);
}

// The tether's bottom spin is free and nothing but the twist loads the spins (isotropic bending, no torque from
// drag about the axis), so at rest the twisting moment vanishes along the line and its shape is the torsion-free
// shape, whatever GJ: from a soft 1e2 to a 1e12 N m^2 no line has (a steel pipe of 1 m: ~1e10). Same bound as
// above (both relax to within 1e-2 of the rest bound): 1e-4 m.
TEST(SpatialRelaxationInertia, StiffTorsionRestsInTheTorsionFreeShape) {
  const spatial::InitialState3 plain = tetherStart(0.0, 0.0, false);
  for (const double GJ : {1e2, 1e6, 1e10, 1e12}) {
    const spatial::InitialState3 t = tetherStart(0.0, GJ);
    double d = 0.0;
    for (size_t i = 0; i < t.kin.size(); ++i) d = std::max(d, (t.kin[i].end() - plain.kin[i].end()).norm());
    EXPECT_LT(d, 1e-4) << "GJ " << GJ;
    EXPECT_LE(t.max_twist_moment, t.twist_moment_bound) << "GJ " << GJ;
  }
}

}  // namespace
}  // namespace riser_sim
