// Statics on a seabed against the catenary resting on a flat seabed (validation::SeabedCatenary):
// an end displaced beyond the hanging reach, an anchor on the seabed, and a line hanging straight
// down onto it (before: Newton started from the straight hanging line far below the seabed and
// returned a vertical column held up by huge contact forces as "converged").
#include <gtest/gtest.h>

#include <cstdio>

#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/scene/scene_yaml.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// A 90 m chain (7 kg/m), top at (0, 0), seabed 28 m below.
Scene chainOverSeabed(int n, bool axial, double stiffness) {
  Scene s;
  s.name = "chain_over_seabed";
  s.length = 90.0;
  s.elements = n;
  s.line.mass_per_length = 7.0;
  s.line.EA = 4e6;
  s.options.bending = false;
  s.options.axial_flexibility = axial;
  s.seabed.enabled = true;
  s.seabed.level = -28.0;
  s.seabed.stiffness_normal = stiffness;
  return s;
}

struct SeabedResult {
  double H, top_tension, touchdown_s, touchdown_x;
  validation::SeabedCatenary ref;
};

// Solves the scene (end force held) and the analytic reference for the same end offset. The seabed
// springs sink each laid joint by w d / k: the reference seabed is that much lower.
SeabedResult solve(const Scene& s) {
  StaticsResult st;
  auto sim = buildSimulator(s, &st);
  EXPECT_TRUE(st.converged) << st.message;
  const Model& m = sim->model();
  const double w = s.line.mass_per_length * s.gravity, d = m.segmentLength();
  SeabedResult r;
  r.ref.L = s.length;
  r.ref.w = w;
  r.ref.EA = s.options.axial_flexibility ? s.line.EA : INFINITY;
  r.ref.h = -(s.seabed.level - w * d / s.seabed.stiffness_normal);
  r.ref.X = st.kin.back().end().x();
  EXPECT_TRUE(r.ref.solve());
  r.H = std::abs(st.end_force.x());
  r.top_tension = sim->outputs().top_tension;
  // Touchdown: the first joint in contact (below the seabed level).
  r.touchdown_s = r.touchdown_x = NAN;
  for (int i = 0; i < m.bodies(); ++i)
    if (st.kin[i].A.y() < s.seabed.level) {
      r.touchdown_s = m.rfe(i).s_begin;
      r.touchdown_x = st.kin[i].A.x();
      break;
    }
  return r;
}

// Tolerances. The rods resolve the touchdown's bend (radius a = H/w = 4.7 m here) only to their
// length d, and the first joint in contact lies within one segment of the analytic touchdown; the
// force error oscillates with where the touchdown falls between two joints but shrinks with d
// (measured, worst of elastic / inextensible on a stiff / soft seabed: 1.7e-3 at d = 1 m, 4.2e-4 at
// d = 0.5 m, 1.7e-4 at d = 0.25 m).
constexpr double kForceRelTol90 = 2.5e-3, kForceRelTol180 = 6e-4;

TEST(StaticsSeabed, DisplacedEndLaysTheRestOnTheSeabed) {
  for (bool axial : {true, false})
    for (double k : {3e6, 3e4}) {  // stiff (sink 0.1 mm) and soft (sink 11 mm at n = 90) seabed
      for (int n : {90, 180}) {
        Scene s = chainOverSeabed(n, axial, k);
        s.initial.type = InitialKind::kDisplaced;
        s.initial.end_dx = 70.0;
        s.initial.end_force = EndForceKind::kHold;
        const SeabedResult r = solve(s);
        const double eh = std::abs(r.H / r.ref.H - 1.0), et = std::abs(r.top_tension / r.ref.topTension() - 1.0);
        const double d = s.length / n;
        std::printf(
            "[seabed, displaced, %s, k %.0e, n %d] H %.3f (ref %.3f, %.2e), top %.3f (ref %.3f, %.2e), "
            "touchdown s %.3f (ref %.3f), x %.3f (ref %.3f)\n",
            axial ? "elastic" : "inext.", k, n, r.H, r.ref.H, eh, r.top_tension, r.ref.topTension(), et, r.touchdown_s,
            r.ref.s, r.touchdown_x, r.ref.touchdownX());
        EXPECT_NEAR(r.touchdown_s, r.ref.s, d);
        EXPECT_NEAR(r.touchdown_x, r.ref.touchdownX(), d);
        EXPECT_LT(eh, n == 90 ? kForceRelTol90 : kForceRelTol180);
        EXPECT_LT(et, n == 90 ? kForceRelTol90 : kForceRelTol180);
      }
    }
}

// Problem (b) with the anchor on the seabed, 75 m from the top: the same shape, the anchor holding H.
TEST(StaticsSeabed, AnchorOnTheSeabed) {
  for (bool axial : {true, false}) {
    Scene s = chainOverSeabed(90, axial, 3e6);
    s.initial.type = InitialKind::kBetweenPoints;
    s.bottom = BottomBoundary::kPinned;
    s.bottom_point = Eigen::Vector3d(75.0, 0.0, s.seabed.level);
    const SeabedResult r = solve(s);
    const double eh = std::abs(r.H / r.ref.H - 1.0), et = std::abs(r.top_tension / r.ref.topTension() - 1.0);
    std::printf(
        "[seabed, anchor, %s] H %.3f (ref %.3f, %.2e), top %.3f (ref %.3f, %.2e), touchdown s %.3f (ref %.3f)\n",
        axial ? "elastic" : "inext.", r.H, r.ref.H, eh, r.top_tension, r.ref.topTension(), et, r.touchdown_s, r.ref.s);
    EXPECT_NEAR(r.touchdown_s, r.ref.s, s.length / s.elements);
    EXPECT_LT(eh, kForceRelTol90);
    EXPECT_LT(et, kForceRelTol90);
  }
}

// Straight down onto the seabed, no horizontal load: the suspended part hangs vertically (unstretched
// length s with s + w s²/(2 EA) = h), the rest lies on the seabed with no tension. Top tension w s, to
// within the weight of the one rod that leans from the last hanging joint onto the seabed (w d).
// Before: the straight line 62 m into the seabed was returned as converged.
TEST(StaticsSeabed, HangingStraightDownOntoTheSeabed) {
  for (bool axial : {true, false}) {
    Scene s = chainOverSeabed(90, axial, 3e6);
    s.initial.type = InitialKind::kHanging;
    StaticsResult st;
    auto sim = buildSimulator(s, &st);
    ASSERT_TRUE(st.converged) << st.message;
    const Model& m = sim->model();
    const double w = s.line.mass_per_length * s.gravity, d = m.segmentLength();
    const double sink = w * d / s.seabed.stiffness_normal, h = -s.seabed.level + sink;
    const double sus = axial ? (std::sqrt(1.0 + 2.0 * w * h / s.line.EA) - 1.0) * s.line.EA / w : h;
    std::printf("[seabed, hanging, %s] top tension %.3f N (w s = %.3f N), end (%.3f, %.5f)\n",
                axial ? "elastic" : "inext.", sim->outputs().top_tension, w * sus, st.kin.back().end().x(),
                st.kin.back().end().y());
    EXPECT_NEAR(sim->outputs().top_tension, w * sus, w * d);
    // Every joint above the seabed or within 2 sinks of it (the lean rod's joint carries up to twice
    // a segment's weight); the laid part flat, straight out from below the top.
    for (int i = 0; i < m.bodies(); ++i) {
      EXPECT_GT(st.kin[i].A.y(), s.seabed.level - 2.0 * sink) << "joint " << i;
      if (st.kin[i].A.y() < s.seabed.level + 1e-9) EXPECT_GT(st.kin[i].A.x(), -d) << "joint " << i;
    }
    EXPECT_NEAR(std::abs(st.kin.back().end().x()), s.length - sus, d);
  }
}

// A straight initial line is no statics solve, but it must not start inside the seabed: refused naming
// seabed.level; the same line above the seabed starts. (The 10 m chain at 45 degrees reaches y = -7.07 m.)
TEST(StaticsSeabed, StraightStartInsideTheSeabedIsRefused) {
  const std::string chain = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/hanging_chain.yaml";
  try {
    buildSimulator(loadSceneFile(chain, {"seabed={level: -5, stiffness_normal: 1e5}"}));
    FAIL() << "a straight line through the seabed started";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("seabed.level"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(buildSimulator(loadSceneFile(chain, {"seabed={level: -8, stiffness_normal: 1e5}"})));
}

}  // namespace
}  // namespace riser_sim
