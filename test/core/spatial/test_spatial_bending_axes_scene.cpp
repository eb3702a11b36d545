// Bending axes in scenes (line.EI: [EI_1, EI_2], line.bending_axis): the initial equilibrium bent about one axis
// (the planar statics with its EI) or between them (twisted: the 3D Newton with the spins, settled in a stable
// equilibrium) starts at rest; the modes of a clamped line split into the isotropic lines' of EI_1 and EI_2; the
// keys are checked, naming the key.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/forces/flex_joint.h"
#include "riser_sim/spatial/modal.h"
#include "riser_sim/spatial/run_builder.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

// Scenes: a flat 30 m umbilical (EI_1 = 9 EI_2) between two points 20 m apart, axis 1 given normal to the
// catenary's plane, in it, or between; the initial state is an equilibrium of every term (the run stays put).
// axis "": the isotropic line of EI = ei.
std::string axesScene(const std::string& axis, const std::string& ei = "[9.0e4, 1.0e4]") {
  return "space: spatial\n"
         "line: {length: 30, elements: 15, EA: 1.0e8, EI: " +
         ei + ", mass_per_length: 20, " + (axis.empty() ? "" : "bending_axis: " + axis + ", ") +
         "torsion: {stiffness: 5.0e3, polar_inertia: 0.02, damping: 50}}\n"
         "bottom: {type: pinned, position: [20.0, 0.0, -18.0]}\n"
         "initial: {type: between_points}\n"
         "solver: {dt: 0.001, integrator: rk4}\n";
}

struct AtRest {
  Kinematics3 kin;
  double moved = 0.0;    // largest move of a joint in 0.5 s [m]
  double spin = 0.0;     // largest spin angle [rad]
  bool twisted = false;  // the initial state carries spins
  std::string about;
};

AtRest restRun(const std::string& text) {
  Run3 run(parseScene(YAML::Load(text)));
  AtRest r;
  r.kin = run.initial().kin;
  r.twisted = !run.initial().material_axes.empty();
  r.about = run.initial().about;
  const int nb = run.model().bodies();
  AlignedVector<Vec3> p0(nb + 1), p(nb + 1);
  run.simulator().positions(p0);
  for (int i = 0; i < nb; ++i) r.spin = std::max(r.spin, std::abs(run.simulator().state()[run.model().dofs() + i]));
  const int steps = int(std::lround(0.5 / run.dt()));
  for (int k = 0; k < steps; ++k)
    if (!run.step()) {
      ADD_FAILURE() << run.divergenceReason();
      break;
    }
  run.simulator().positions(p);
  for (int i = 0; i <= nb; ++i) r.moved = std::max(r.moved, (p[i] - p0[i]).norm());
  return r;
}

TEST(SpatialBendingAxesScene, StartsAtRestWithTheAxesAnyWay) {
  // Axis 1 normal to the plane (y): the catenary bends about it, EI_1, its stiff axis: balanced, but the twist
  // lets it fall over to its soft axis (4 modes with ω² < 0, --modes): refused naming stability. In the plane (x):
  // about axis 2, EI_2.
  try {
    restRun(axesScene("[0.0, 1.0, 0.0]"));
    ADD_FAILURE() << "the catenary bent about its stiff axis was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("stability: the equilibrium is unstable"), std::string::npos) << e.what();
  }
  const AtRest inplane = restRun(axesScene("[1.0, 0.0, 0.0]"));
  const AtRest stiff = restRun(axesScene("", "9.0e4"));
  double d_soft = 0.0;
  for (size_t i = 0; i < inplane.kin.size(); ++i)
    d_soft = std::max(d_soft, (inplane.kin[i].end() - stiff.kin[i].end()).norm());
  // Between the axes (yaw 30° off the plane's normal, tilted): twisted by the 3D Newton with the spins.
  const AtRest oblique = restRun(axesScene("[0.5, 0.866, 0.3]"));
  // A free end held displaced by a horizontal force (kept on: hold), axes between: the 3D Newton holds its end.
  std::string held = axesScene("[0.5, 0.866, 0.3]");
  held.replace(held.find("bottom:"), held.find("solver:") - held.find("bottom:"),
               "initial: {type: displaced, end_offset: [12.0, 0.0], end_force: hold}\n");
  held.replace(held.find("dt: 0.001"), 9, "dt: 0.0004");  // the light free end's axial mode: 3700 rad/s
  const AtRest displaced = restRun(held);
  const Vec3 end = displaced.kin.back().end();
  double off_plane = 0.0;
  for (const auto& b : oblique.kin) off_plane = std::max(off_plane, std::abs(b.end().y()));
  std::printf(
      "[bending axes] catenary, axis 1 in the plane: %.3g m from the isotropic EI_1 line (EI_2), moved %.1e m "
      "in 0.5 s; between: out of the plane %.3g m, spins up to %.3g rad, moved %.1e m (%s)\n",
      d_soft, inplane.moved, off_plane, oblique.spin, oblique.moved, oblique.about.c_str());
  EXPECT_GT(d_soft, 1e-3);
  EXPECT_FALSE(inplane.twisted);
  EXPECT_TRUE(oblique.twisted);
  EXPECT_GT(off_plane, 1e-4);
  EXPECT_GT(oblique.spin, 1e-4);
  // At rest: a start 1e-9 off equilibrium (initial.tolerance) moves by ~1e-9 m; an untwisted oblique start by mm.
  std::printf(
      "[bending axes] displaced end held at (12, 0): end at (%.12f, %.2e), spins up to %.3g rad, moved %.1e m "
      "in 0.5 s\n",
      end.x(), end.y(), displaced.spin, displaced.moved);
  EXPECT_TRUE(displaced.twisted);
  EXPECT_NEAR(end.x(), 12.0, 1e-9);
  EXPECT_NEAR(end.y(), 0.0, 1e-9);
  for (const AtRest* r : {&inplane, &oblique, &displaced}) EXPECT_LT(r->moved, 1e-6);
}

// Starts the shifted Newton stalls on (far from the planar guess), so dynamic relaxation with the spins brings the
// line near and Newton finishes. A swivel top (top.torsion: free): the line spins its soft axis into the bend and
// is the isotropic EI_2 catenary, in its plane. A current across the plane (0.8 m/s): the drag bends the line
// out of it, about both axes, and it twists. Both at rest.
TEST(SpatialBendingAxesScene, FarStartsRelaxFirst) {
  std::string swivel = axesScene("[0.5, 0.866, 0.3]");
  swivel.replace(swivel.find("bottom:"), 0, "top: {torsion: free}\n");
  const AtRest s = restRun(swivel), soft = restRun(axesScene("", "1.0e4"));
  double off = 0.0, d_soft = 0.0;
  for (size_t i = 0; i < s.kin.size(); ++i)
    off = std::max(off, std::abs(s.kin[i].end().y())),
    d_soft = std::max(d_soft, (s.kin[i].end() - soft.kin[i].end()).norm());
  std::string current = axesScene("[0.0, 1.0, 0.0]");
  current.replace(current.find("mass_per_length: 20"), 19, "mass_per_length: 20, outer_diameter: 0.1");
  current.replace(current.find("bottom:"), 0,
                  "environment: {water: {density: 1025.0, surface: 5.0}, current: "
                  "{velocity: [0.0, 0.8, 0.0]}}\nhydrodynamics: {drag_normal: 1.2}\n");
  const AtRest c = restRun(current);
  double c_off = 0.0;
  for (const auto& b : c.kin) c_off = std::max(c_off, std::abs(b.end().y()));
  std::printf(
      "[bending axes] swivel top: %.1e m out of the plane, %.1e m from the isotropic EI_2 line, spins up to "
      "%.3g rad, moved %.1e m; current across: out of the plane %.3g m, spins up to %.3g rad, moved %.1e m\n",
      off, d_soft, s.spin, s.moved, c_off, c.spin, c.moved);
  EXPECT_LT(off, 1e-9);
  EXPECT_LT(d_soft, 1e-8);  // [m] Newton's 1e-12 of the weight
  EXPECT_GT(s.spin, 0.5);
  EXPECT_TRUE(c.twisted);
  EXPECT_GT(c_off, 1.0);
  for (const AtRest* r : {&s, &c}) EXPECT_LT(r->moved, 1e-6);
}

TEST(SpatialBendingAxesScene, KeysAreChecked) {
  const auto key = [](const std::string& text) {
    try {
      Run3 run(parseScene(YAML::Load(text)));
    } catch (const SceneError& e) {
      return e.key();
    } catch (const std::exception& e) {
      return std::string(e.what()).substr(0, std::string(e.what()).find(':'));
    }
    return std::string("accepted");
  };
  const std::string ok = axesScene("[1.0, 0.0, 0.0]");  // bent about its soft axis: stable
  EXPECT_EQ(key(ok), "accepted");
  std::string no_torsion = ok;
  no_torsion.replace(no_torsion.find(", torsion:"),
                     no_torsion.find("}", no_torsion.find(", torsion:")) + 1 - no_torsion.find(", torsion:"), "");
  EXPECT_EQ(key(no_torsion), "line.EI");
  EXPECT_EQ(key(axesScene("")), "line.bending_axis");                              // the pair, no axis
  EXPECT_EQ(key(axesScene("[0.0, 1.0, 0.0]", "[9.0e4, 1.0e4, 1.0]")), "line.EI");  // three
  EXPECT_EQ(key(axesScene("[0.0, 1.0, 0.0]", "[9.0e4, -1.0]")), "line.EI[1]");
  EXPECT_EQ(key(axesScene("[0.0, 1.0, 0.0]", "1.0e4")), "line.bending_axis");  // an axis, no pair
  EXPECT_EQ(key(axesScene("[0.0, 0.0, 0.0]")), "line.bending_axis");
  EXPECT_EQ(key(axesScene("[0.0, 1.0]")), "line.bending_axis");  // [x, y, z] only, as flex_joint.axis
  // Along the top rfe of a straight line hanging down: no direction across it.
  std::string along = axesScene("[0.0, 0.0, 1.0]");
  along.replace(along.find("bottom:"), along.find("solver:") - along.find("bottom:"), "initial: {type: straight}\n");
  EXPECT_EQ(key(along), "line.bending_axis");
  std::string planar = ok.substr(ok.find("line:"));
  EXPECT_EQ(key(planar.substr(0, planar.find("bottom:"))), "line.EI");
}

// A 10 m line hanging straight from a stiff flex joint (a clamp), EI_1 = 4 EI_2, axis 1 along x: its swings along
// x bend it about y (axis 2) and are the isotropic EI_2 line's, those along y the EI_1 line's. The straight line is
// the same discrete problem in each plane: the frequencies agree to the eigen-solve's round-off.
constexpr double kClamp = 1e6;  // [N m/rad]: 250x the line's EI_1/d

std::vector<double> clampedModes(double EI1, double EI2, bool axes) {
  spatial_test::LineSpec s;
  s.segments = 12;
  s.props.mass_per_length = 10.0;
  s.props.EA = 1e8;
  s.props.EI = 0.5 * (EI1 + EI2);
  s.options.axial_flexibility = false;
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties t;
  t.stiffness = 3e3;
  t.polar_inertia = 0.05;
  m->setTorsion(t);
  if (axes) m->setBendingAxes(EI1, EI2, Vec3::UnitX());
  m->addTerm(std::make_unique<FlexJoint>(FlexJoint::End::kTop, -Vec3::UnitZ(), kClamp, 0.0));
  const std::vector<Vec3> down(m->bodies(), -Vec3::UnitZ());
  const Kinematics3 eq = equilibrium3(*m, rigidChain(m->line(), Vec3::Zero(), down, Vec3::Zero(), Vec3::Zero()));
  std::vector<double> w;
  for (const Mode3& mode : computeModes3(*m, eq).modes)
    if (!mode.torsional && mode.omega2 > 0.0) w.push_back(std::sqrt(mode.omega2));
  return w;
}

TEST(SpatialBendingAxesScene, ClampedModesSplitIntoEachAxisStiffness) {
  const std::vector<double> a = clampedModes(4e3, 1e3, true), soft = clampedModes(1e3, 1e3, false),
                            stiff = clampedModes(4e3, 4e3, false);
  // The isotropic lines' transverse modes come in degenerate pairs; the axes' line has one of each.
  std::vector<double> expect;
  for (size_t k = 0; k + 1 < soft.size() && expect.size() < 8; k += 2) expect.push_back(soft[k]);
  for (size_t k = 0; k + 1 < stiff.size() && expect.size() < 16; k += 2) expect.push_back(stiff[k]);
  std::sort(expect.begin(), expect.end());
  double worst = 0.0;
  const size_t compared = 6;
  for (size_t k = 0; k < compared; ++k) worst = std::max(worst, std::abs(a[k] / expect[k] - 1.0));
  std::printf(
      "[bending axes] clamped line's lowest modes: %.6f %.6f %.6f %.6f rad/s; isotropic EI_2 %.6f %.6f, EI_1 "
      "%.6f %.6f; worst of %zu %.2e\n",
      a[0], a[1], a[2], a[3], soft[0], soft[2], stiff[0], stiff[2], compared, worst);
  EXPECT_NEAR(soft[0], soft[1], 1e-9 * soft[0]);  // the isotropic pair
  EXPECT_GT(a[1] / a[0], 1.1);                    // split (gravity stiffens both alike: less than sqrt(4))
  EXPECT_LT(worst, 1e-9);  // the FD stiffness' round-off (the isotropic pair is degenerate to the same)
}

}  // namespace
}  // namespace riser_sim
