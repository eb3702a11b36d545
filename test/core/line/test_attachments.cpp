// Attachments (clump weights, buoys) on the line, in both engines: the pinned line's equilibrium against an
// independent reference (two or more elastic catenary pieces joined at the attachments, solved by shooting),
// the term's energy/power and linearisation (finite differences), planar vs 3D, and the loader's refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "riser_sim/line/attachment.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/forces/attachments.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/forces/attachments.h"
#include "riser_sim/spatial/run_builder.h"

using namespace riser_sim;

namespace {

// ---- Reference: the elastic catenary (EI = 0) with point loads, by shooting on the top force ----
// Along the unstretched arc length s from the top, the tension vector τ(s) = -F_top - Σ (external forces on
// [0, s]) (the force of the lower part on the upper one); dr/ds = τ/EA + τ/|τ|. With w the weight in water per
// length (down) τ = (τx, τy0 + w s) on each piece, integrated exactly:
// x = τx s/EA + (τx/w)(asinh((τy0 + w s)/τx) - asinh(τy0/τx)), y = (τy0 s + w s²/2)/EA + (|τ(s)| - |τ(0)|)/w.
struct PointLoad {
  double s;  // [m]
  Vec2 F;    // external force on the line there [N]
};

struct Catenary {
  double L, EA, w;
  std::vector<PointLoad> loads;  // in order of s

  // Position at arc length s_end with top force F_top (the force of the hang-off on the line).
  Vec2 at(const Vec2& top, const Vec2& F_top, double s_end) const {
    Vec2 r = top, tau = -F_top;
    double s = 0.0;
    for (size_t k = 0; k <= loads.size(); ++k) {
      const double next = std::min(k < loads.size() ? loads[k].s : L, s_end);
      const double ds = next - s, tx = tau.x(), ty0 = tau.y(), ty1 = ty0 + w * ds;
      r.x() += tx * ds / EA + (tx / w) * (std::asinh(ty1 / tx) - std::asinh(ty0 / tx));
      r.y() += (ty0 * ds + 0.5 * w * ds * ds) / EA + (std::hypot(tx, ty1) - std::hypot(tx, ty0)) / w;
      tau.y() = ty1;
      s = next;
      if (s >= s_end) break;
      tau -= loads[k].F;
    }
    return r;
  }
  // The top force that ends the line at `end` (Newton on the 2 unknowns, FD Jacobian).
  Vec2 solve(const Vec2& top, const Vec2& end, Vec2 F) const {
    for (int it = 0; it < 100; ++it) {
      const Vec2 g = at(top, F, L) - end;
      if (g.norm() < 1e-11 * L) return F;
      Mat2 J;
      for (int c = 0; c < 2; ++c) {
        Vec2 dF = Vec2::Zero();
        dF[c] = 1e-6 * std::max(1.0, F.norm());
        J.col(c) = (at(top, F + dF, L) - at(top, F - dF, L)) / (2.0 * dF[c]);
      }
      Vec2 step = J.lu().solve(g);
      if (step.norm() > 0.5 * F.norm()) step *= 0.5 * F.norm() / step.norm();  // damped: stay on the branch
      F -= step;
    }
    ADD_FAILURE() << "reference catenary did not converge";
    return F;
  }
};

// A 100 m line pinned at (0, 0) and (60, -60), under water (surface 10 m above the top), EI = 0.
std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string pinnedScene(int n, const std::string& attachments, const std::string& space = "planar") {
  return "space: " + space + R"(
line: {length: 100.0, elements: )" +
         std::to_string(n) + R"(, mass_per_length: 50.0, outer_diameter: 0.2,
       EA: 1.0e7, EI: 0.0, bending: false}
top: {position: [0.0, 0.0]}
bottom: {type: pinned, position: [60.0, -60.0]}
environment: {water: {density: 1025.0, surface: 10.0}}
initial: {type: between_points, tolerance: 1.0e-12}
attachments: )" +
         attachments + "\n";
}

constexpr double kG = 9.81, kRho = 1025.0;
double wetWeightPerLength() { return (50.0 - kRho * M_PI * 0.01) * kG; }

// The RFEM's A_i at arc length s (a joint), the planar statics of the scene.
struct PinnedResult {
  Vec2 attachment, top_force;
};
PinnedResult planarPinned(int n, const std::string& att, double s_att) {
  const Scene scene = loadSceneText(pinnedScene(n, att), "test");
  riser_sim::Run run = buildRun(scene);
  const auto* term = dynamic_cast<const Attachments*>(run.model->findTerm("attachments"));
  EXPECT_NE(term, nullptr);
  const AttachmentPoint p = term->point(0);
  EXPECT_NEAR(run.model->rfe(p.rfe).s_begin + p.s0, s_att, 1e-9);
  PinnedResult r;
  r.attachment = term->position(run.initial.kin, 0);
  r.top_force = -run.sim->outputs().top_force;  // outputs: the force on the hang-off
  return r;
}

}  // namespace

// The clump and the buoy at a joint of both discretisations (s = 23 L/60 is a joint of n = 30 and n = 90):
// the RFEM converges as O(d²) to the reference (an exact hinge at the kink), so the error at n = 90 is ~1/9
// of n = 30's; both are bounded by the measured n = 30 error with a margin.
TEST(Attachments, PinnedClumpAndBuoyMatchTheCatenaryShooting) {
  const double s_att = 100.0 * 23.0 / 60.0;
  struct Case {
    const char* name;
    std::string yaml;
    Vec2 force;  // external force on the line at the attachment (weight + buoyancy) [N]
  };
  const Case cases[] = {
      {"clump", "[{name: clump, arc_length: " + num(s_att) + ", mass: 2000.0}]", Vec2(0.0, -2000.0 * kG)},
      {"buoy", "[{name: buoy, arc_length: " + num(s_att) + ", mass: 300.0, volume: 1.5}]",
       Vec2(0.0, (kRho * 1.5 - 300.0) * kG)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Catenary ref{100.0, 1.0e7, wetWeightPerLength(), {{s_att, c.force}}};
    const Vec2 F_ref = ref.solve(Vec2::Zero(), Vec2(60.0, -60.0), Vec2(-5000.0, 20000.0));
    const Vec2 p_ref = ref.at(Vec2::Zero(), F_ref, s_att);
    double err[2];
    int k = 0;
    for (int n : {30, 90}) {
      const PinnedResult r = planarPinned(n, c.yaml, s_att);
      const double pos = (r.attachment - p_ref).norm(), force = (r.top_force - F_ref).norm() / F_ref.norm();
      err[k++] = pos;
      // The top force converges with the shape: within 1e-3 of itself at n = 30 (measured 1.0e-3 clump, 1.3e-3 buoy
      // relative to |F_top|), a ninth of that at n = 90.
      EXPECT_LT(force, n == 30 ? 3e-3 : 3e-4);
      std::printf("%s n=%d: attachment (%.6f, %.6f) ref (%.6f, %.6f); top force (%.3f, %.3f) ref (%.3f, %.3f)\n",
                  c.name, n, r.attachment.x(), r.attachment.y(), p_ref.x(), p_ref.y(), r.top_force.x(), r.top_force.y(),
                  F_ref.x(), F_ref.y());
    }
    // The n = 30 discretisation error is millimetres to centimetres on a 100 m line (measured 4.7 mm clump,
    // 24 mm buoy); n = 90 a ninth of it (O(d²); measured ratios 8.9 and 9.3).
    EXPECT_LT(err[0], 0.05);
    EXPECT_LT(err[1], err[0] / 6.0) << "not converging as O(d^2): " << err[0] << " -> " << err[1];
  }
}

namespace {

// A planar model with a buoy cutting the surface, a clump on the seabed and a drag body in a current: every part
// of the law active. surface 0, seabed -50.
std::shared_ptr<Model> lawModel(bool current) {
  const std::string yaml = std::string(R"(
line: {length: 60.0, elements: 6, mass_per_length: 40.0, outer_diameter: 0.2, EA: 1.0e7, EI: 1.0e4}
environment: {water: {density: 1025.0, surface: 0.0})") +
                           (current ? ", current: {velocity: [0.7, 0.1]}" : "") + R"(}
seabed: {level: -50.0, stiffness_normal: 2.0e5, damping_normal: 3.0e3, damping_tangential: 1.0e3}
attachments:
  - {name: buoy, arc_length: 4.0, mass: 100.0, volume: 0.5, drag_area: 0.8, cd: 1.1, ca: 0.5}
  - {name: clump, arc_length: 37.0, mass: 900.0, volume: 0.1, drag_area: 0.4, cd: 0.9, seabed_contact: true}
  - {name: end, arc_length: 60.0, mass: 50.0, volume: 0.05, drag_area: 0.1, cd: 1.0, added_mass: 20.0, seabed_contact: true}
)";
  return buildModel(loadSceneText(yaml, "test"));
}

// Each rfe on its own: the term acts on its rfe's point only, so the joints need not be closed here. The buoy's
// rfe (0) straddles the surface, the clump's (4) and the end's (6) reach below the seabed.
Kinematics lawState(const Model& m, std::mt19937& rng, bool moving) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kinematics kin(m.bodies());
  const double top_y[] = {1.1, -6.0, -16.0, -26.0, -49.6, -50.3, -50.2};
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = Vec2(10.0 * i + u(rng), top_y[i] + 0.1 * u(rng));
    b.delta = 2e-3 * u(rng);
    b.phi = i == 0 ? -0.3 + 0.01 * u(rng) : -0.3 + 0.2 * u(rng);  // rfe 0: the buoy's sphere cuts the surface
    if (moving) b.A_dot = Vec2(u(rng), u(rng)), b.delta_dot = 0.05 * u(rng), b.phi_dot = 0.3 * u(rng);
    b.c = std::cos(b.phi), b.s = std::sin(b.phi), b.len = m.rfe(i).length + b.delta;
  }
  return kin;
}

Vec4 coords(const BodyKinematics& b) { return Vec4(b.A.x(), b.A.y(), b.delta, b.phi); }
Vec4 rates(const BodyKinematics& b) { return Vec4(b.A_dot.x(), b.A_dot.y(), b.delta_dot, b.phi_dot); }
void setCoords(BodyKinematics& b, const Vec4& q, double len0) {
  b.A = q.head<2>(), b.delta = q[2], b.phi = q[3], b.c = std::cos(q[3]), b.s = std::sin(q[3]), b.len = len0 + q[2];
}
void setRates(BodyKinematics& b, const Vec4& v) { b.A_dot = v.head<2>(), b.delta_dot = v[2], b.phi_dot = v[3]; }

}  // namespace

// Q·q' = -dV/dt + P along random motions (dV/dt by central differences of V, step 1e-6: truncation ~1e-12 of
// the power scale; the sphere's W is C² except where a sphere meets the surface exactly). Bound 1e-6 of the power.
TEST(Attachments, PlanarTermPowerBalance) {
  auto model = lawModel(true);
  const ForceTerm* term = model->findTerm("attachments");
  ASSERT_NE(term, nullptr);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 8; ++trial) {
    const Kinematics kin = lawState(*model, rng, true);
    VecX Q = VecX::Zero(model->dofs());
    const double P = term->addForcesAndPower(*model, nullptr, kin, 0.7, Q);
    double qv = 0.0;
    for (int i = 0; i < model->bodies(); ++i) qv += Q.segment<4>(4 * i).dot(rates(kin[i]));
    const double h = 1e-6;
    Kinematics kp = kin, km = kin;
    for (int i = 0; i < model->bodies(); ++i) {
      setCoords(kp[i], coords(kin[i]) + h * rates(kin[i]), model->rfe(i).length);
      setCoords(km[i], coords(kin[i]) - h * rates(kin[i]), model->rfe(i).length);
    }
    const double dV =
        (term->potentialEnergy(*model, nullptr, kp) - term->potentialEnergy(*model, nullptr, km)) / (2 * h);
    EXPECT_NEAR(qv, -dV + P, 1e-6 * std::max({std::abs(qv), std::abs(P), 1.0})) << "trial " << trial;
    EXPECT_GT(std::abs(P), 1.0);  // the drag and the dampers are on
  }
}

// K = -∂Q/∂q at rest in a uniform current (the drag then depends on q only through the wetted fraction, which the
// linearisation leaves out: the buoy's rfe is checked without the current) and C = -∂Q/∂q' when moving, against
// central differences (step 1e-7: error ~1e-7 relative).
TEST(Attachments, PlanarStiffnessAgainstFiniteDifferences) {
  for (bool current : {false, true}) {
    auto model = lawModel(current);
    const ForceTerm* term = model->findTerm("attachments");
    std::mt19937 rng(5);
    for (bool moving : {false, true}) {
      const Kinematics kin = lawState(*model, rng, moving);
      StiffnessBlocks S;
      S.resize(model->bodies());
      ASSERT_TRUE(term->addStiffness(*model, nullptr, kin, 0.0, S));
      for (int i : {0, 4, 6}) {
        if (current && i == 0) continue;  // see above
        Mat4 K, C;
        for (int j = 0; j < 4; ++j) {
          const double h = 1e-7 * (j < 2 ? 10.0 : 1.0);
          for (int which = 0; which < 2; ++which) {
            if (which == 0 && moving) continue;  // K at rest: the drag's q-dependence through v is not in K
            Kinematics kp = kin, km = kin;
            Vec4 d = Vec4::Zero();
            d[j] = h;
            if (which == 0) {
              setCoords(kp[i], coords(kin[i]) + d, model->rfe(i).length);
              setCoords(km[i], coords(kin[i]) - d, model->rfe(i).length);
            } else {
              setRates(kp[i], rates(kin[i]) + d);
              setRates(km[i], rates(kin[i]) - d);
            }
            VecX Qp = VecX::Zero(model->dofs()), Qm = VecX::Zero(model->dofs());
            term->addForces(*model, nullptr, kp, 0.0, Qp);
            term->addForces(*model, nullptr, km, 0.0, Qm);
            (which == 0 ? K : C).col(j) = -(Qp - Qm).segment<4>(4 * i) / (2 * h);
          }
        }
        if (!moving) {
          const double scale = std::max(1.0, K.norm());
          EXPECT_LT((S.K_diag[i] - K).norm(), 1e-5 * scale) << "K of rfe " << i << "\n" << S.K_diag[i] << "\nFD\n" << K;
        } else {
          const double scale = std::max(1.0, C.norm());
          EXPECT_LT((S.C_diag[i] - C).norm(), 1e-5 * scale) << "C of rfe " << i << "\n" << S.C_diag[i] << "\nFD\n" << C;
        }
      }
    }
  }
}

namespace {

std::shared_ptr<spatial::Model3> lawModel3() {
  const std::string yaml = R"(
space: spatial
line: {length: 60.0, elements: 6, mass_per_length: 40.0, outer_diameter: 0.2, EA: 1.0e7, EI: 1.0e4}
environment: {water: {density: 1025.0, surface: 0.0}, current: {velocity: [0.7, -0.4, 0.1]}}
seabed: {level: -50.0, stiffness_normal: 2.0e5, damping_normal: 3.0e3, damping_tangential: 1.0e3, slope: 5.0, slope_heading: 30.0}
attachments:
  - {name: buoy, arc_length: 4.0, mass: 100.0, volume: 0.5, drag_area: 0.8, cd: 1.1, ca: 0.5}
  - {name: clump, arc_length: 37.0, mass: 900.0, volume: 0.1, drag_area: 0.4, cd: 0.9, seabed_contact: true}
  - {name: end, arc_length: 60.0, mass: 50.0, volume: 0.05, drag_area: 0.1, cd: 1.0, added_mass: 20.0, seabed_contact: true}
)";
  return spatial::buildModel3(loadSceneText(yaml, "test"));
}

spatial::Kinematics3 lawState3(const spatial::Model3& m, std::mt19937& rng, bool moving) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  spatial::Kinematics3 kin(m.bodies());
  const double top_z[] = {1.1, -6.0, -16.0, -26.0, -49.0, -50.3, -49.9};
  for (int i = 0; i < m.bodies(); ++i) {
    spatial::BodyKinematics3& b = kin[i];
    b.A = Vec3(10.0 * i + u(rng), 3.0 * u(rng), top_z[i] + 0.1 * u(rng));
    b.delta = 2e-3 * u(rng);
    b.e = i == 0 ? Vec3(1.0, 0.01 * u(rng), -0.3).normalized()  // rfe 0: the buoy's sphere cuts the surface
                 : Vec3(1.0, 0.3 * u(rng), -0.3 + 0.2 * u(rng)).normalized();
    if (moving) {
      b.A_dot = Vec3(u(rng), u(rng), u(rng)), b.delta_dot = 0.05 * u(rng);
      const Vec3 w(0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng));
      b.e_dot = w.cross(b.e);
    }
    b.len = m.rfe(i).length + b.delta;
  }
  return kin;
}

using Vec7 = Eigen::Matrix<double, 7, 1>;
Vec7 coords3(const spatial::BodyKinematics3& b) {
  Vec7 q;
  q << b.A, b.delta, b.e;
  return q;
}
Vec7 rates3(const spatial::BodyKinematics3& b) {
  Vec7 q;
  q << b.A_dot, b.delta_dot, b.e_dot;
  return q;
}
void setCoords3(spatial::BodyKinematics3& b, const Vec7& q, double len0) {
  b.A = q.head<3>(), b.delta = q[3], b.e = q.tail<3>(), b.len = len0 + q[3];
}
void setRates3(spatial::BodyKinematics3& b, const Vec7& v) {
  b.A_dot = v.head<3>(), b.delta_dot = v[3], b.e_dot = v.tail<3>();
}

const spatial::ForceTerm3* attachmentsTerm3(const spatial::Model3& m) {
  for (const auto& t : m.terms())
    if (t->name() == "attachments") return t.get();
  return nullptr;
}

}  // namespace

// As the planar check, on a sloped seabed in a cross current: Q·q' = -dV/dt + P.
TEST(Attachments, SpatialTermPowerBalance) {
  auto model = lawModel3();
  const spatial::ForceTerm3* term = attachmentsTerm3(*model);
  ASSERT_NE(term, nullptr);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 8; ++trial) {
    const spatial::Kinematics3 kin = lawState3(*model, rng, true);
    VecX Q = VecX::Zero(model->dofs());
    const double P = term->addForcesAndPower(*model, kin, 0.4, Q);
    double qv = 0.0;
    for (int i = 0; i < model->bodies(); ++i) qv += Q.segment<7>(7 * i).dot(rates3(kin[i]));
    const double h = 1e-6;
    spatial::Kinematics3 kp = kin, km = kin;
    for (int i = 0; i < model->bodies(); ++i) {
      setCoords3(kp[i], coords3(kin[i]) + h * rates3(kin[i]), model->rfe(i).length);
      setCoords3(km[i], coords3(kin[i]) - h * rates3(kin[i]), model->rfe(i).length);
    }
    const double dV = (term->potentialEnergy(*model, kp, 0.4) - term->potentialEnergy(*model, km, 0.4)) / (2 * h);
    EXPECT_NEAR(qv, -dV + P, 1e-6 * std::max({std::abs(qv), std::abs(P), 1.0})) << "trial " << trial;
  }
}

// K and C of the 3D term against central differences (K at rest: see the planar check; the buoy's rfe, whose
// wetted fraction changes the drag, is left out of K in the current).
TEST(Attachments, SpatialStiffnessAgainstFiniteDifferences) {
  auto model = lawModel3();
  const spatial::ForceTerm3* term = attachmentsTerm3(*model);
  std::mt19937 rng(9);
  for (bool moving : {false, true}) {
    const spatial::Kinematics3 kin = lawState3(*model, rng, moving);
    spatial::Stiffness3 S;
    S.resize(model->bodies());
    term->addStiffness(*model, kin, 0.0, S);
    for (int i : {4, 6, 0}) {
      if (!moving && i == 0) continue;
      Eigen::Matrix<double, 7, 7> D;
      for (int j = 0; j < 7; ++j) {
        const double h = 1e-7 * (j < 3 ? 10.0 : 1.0);
        spatial::Kinematics3 kp = kin, km = kin;
        Vec7 d = Vec7::Zero();
        d[j] = h;
        if (!moving) {
          setCoords3(kp[i], coords3(kin[i]) + d, model->rfe(i).length);
          setCoords3(km[i], coords3(kin[i]) - d, model->rfe(i).length);
        } else {
          setRates3(kp[i], rates3(kin[i]) + d);
          setRates3(km[i], rates3(kin[i]) - d);
        }
        VecX Qp = VecX::Zero(model->dofs()), Qm = VecX::Zero(model->dofs());
        term->addForces(*model, kp, 0.0, Qp);
        term->addForces(*model, km, 0.0, Qm);
        D.col(j) = -(Qp - Qm).segment<7>(7 * i) / (2 * h);
      }
      const auto& A = moving ? S.C_diag[i] : S.K_diag[i];
      EXPECT_LT((A - D).norm(), 1e-5 * std::max(1.0, D.norm())) << (moving ? "C" : "K") << " of rfe " << i << "\n"
                                                                << A << "\nFD\n"
                                                                << D;
    }
  }
}

// The pinned clump-and-buoy line in both engines: the 3D start (the planar statics turned into 3D, then checked
// at rest by the 3D engine's own forces) puts the attachments where the planar one does, under the same forces.
TEST(Attachments, PlanarAndSpatialAgree) {
  const std::string att =
      "[{name: clump, arc_length: 30.0, mass: 800.0, drag_area: 0.5, cd: 1.0, added_mass: 100.0},"
      " {name: buoy, arc_length: 60.0, mass: 200.0, volume: 1.0, drag_area: 1.0, cd: 1.0, ca: 0.5}]";
  riser_sim::Run planar = buildRun(loadSceneText(pinnedScene(20, att), "test"));
  spatial::Run3 space(loadSceneText(pinnedScene(20, att, "spatial"), "test"));
  const auto* a2 = dynamic_cast<const Attachments*>(planar.model->findTerm("attachments"));
  const auto* a3 = dynamic_cast<const spatial::Attachments*>(attachmentsTerm3(space.model()));
  ASSERT_TRUE(a2 && a3);
  for (int k = 0; k < 2; ++k) {
    const Vec2 p2 = a2->position(planar.initial.kin, k);
    const Vec3 p3 = a3->position(space.initial().kin, k);
    EXPECT_NEAR((Vec3(p2.x(), 0.0, p2.y()) - p3).norm(), 0.0, 1e-9);
    const Vec2 f2 = a2->force(*planar.model, planar.initial.kin, 0.0, k);
    const Vec3 f3 = a3->force(space.model(), space.initial().kin, 0.0, k);
    EXPECT_NEAR((Vec3(f2.x(), 0.0, f2.y()) - f3).norm(), 0.0, 1e-9 * f3.norm());
  }
}

// Bad input: each refusal names its key.
TEST(Attachments, BadInputNamesTheKey) {
  const auto key = [](const std::string& att, const std::string& extra = "") {
    try {
      loadSceneText(pinnedScene(10, att) + extra, "test");
    } catch (const SceneError& e) {
      return e.key();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key("[{arc_length: 120.0, mass: 1.0}]"), "attachments[0].arc_length");
  EXPECT_EQ(key("[{arc_length: -1.0, mass: 1.0}]"), "attachments[0].arc_length");
  EXPECT_EQ(key("[{mass: 1.0}]"), "attachments[0].arc_length");
  EXPECT_EQ(key("[{arc_length: 10.0, mass: -1.0}]"), "attachments[0].mass");
  EXPECT_EQ(key("[{arc_length: 10.0}]"), "attachments[0]");
  EXPECT_EQ(key("[{arc_length: 10.0, drag_area: 1.0}]"), "attachments[0].cd");
  EXPECT_EQ(key("[{arc_length: 10.0, volume: 1.0, added_mass: 1.0, ca: 1.0}]"), "attachments[0].ca");
  EXPECT_EQ(key("[{arc_length: 10.0, mass: 1.0, ca: 1.0}]"), "attachments[0].ca");
  EXPECT_EQ(key("[{arc_length: 10.0, mass: 1.0, seabed_contact: true}]"), "attachments[0].seabed_contact");
  EXPECT_EQ(key("[{arc_length: 10.0, mass: 1.0, colour: red}]"), "attachments[0].colour");
  EXPECT_EQ(key("[{name: a, arc_length: 10.0, mass: 1.0}, {name: a, arc_length: 20.0, mass: 1.0}]"),
            "attachments[1].name");
  EXPECT_EQ(key("{arc_length: 10.0, mass: 1.0}"), "attachments");
  EXPECT_EQ(key("[{arc_length: 10.0, mass: 1.0}]"), "(accepted)");
  // A free end held up by a buoy stronger than the whole line's weight in water (1.75e4 N): refused, naming it.
  const std::string hanging = R"(
line: {length: 100.0, elements: 10, mass_per_length: 50.0, outer_diameter: 0.2, EA: 1.0e7, EI: 0.0}
environment: {water: {density: 1025.0, surface: 10.0}}
attachments: [{arc_length: 90.0, mass: 10.0}, {name: big, arc_length: 100.0, mass: 100.0, volume: 2.0}]
)";
  try {
    loadSceneText(hanging, "test");
    ADD_FAILURE() << "a buoy floating the line was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "attachments[1].volume");
    EXPECT_NE(std::string(e.what()).find("float the whole line"), std::string::npos) << e.what();
  }
}

// The float check counts the line's buoyant sections (their modules smeared): a 100 m free-ended line, its lower half
// carrying modules (0.05 m³ and 10 kg every 2 m: net -2.8 kg/m in water against the pipe's +17.8 kg/m), weighs
// 7.36 kN in water, 17.5 kN without the modules; a 1 m³, 100 kg buoy lifts 10.06 kN against 7.36 + 0.98 kN:
// refused, naming it. Lighter (0.5 m³, lifting 5.03 kN): accepted.
TEST(Attachments, BuoyFloatingASectionedLineIsRefused) {
  const auto scene = [](double volume) {
    return R"(
line:
  length: 100.0
  mass_per_length: 50.0
  outer_diameter: 0.2
  EA: 1.0e7
  EI: 0.0
  sections:
    - {length: 50.0, elements: 5}
    - length: 50.0
      elements: 5
      buoyancy_modules: {outer_diameter: 0.5, length: 0.5, pitch: 2.0, mass: 10.0, volume: 0.05, drag_normal: 1.0}
environment: {water: {density: 1025.0, surface: 10.0}}
hydrodynamics: {drag_normal: 1.0}
attachments: [{name: float, arc_length: 100.0, mass: 100.0, volume: )" +
           std::to_string(volume) + "}]\n";
  };
  try {
    loadSceneText(scene(1.0), "test");
    ADD_FAILURE() << "a buoy floating the sectioned line was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "attachments[0].volume");
    EXPECT_NE(std::string(e.what()).find("'float'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("float the whole line"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(loadSceneText(scene(0.5), "test"));
}
