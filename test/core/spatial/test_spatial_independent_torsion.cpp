// Torsion in the independent-coordinates cross-check (IndependentFormulation3, spin angles as generalised
// coordinates from the Lagrangian): its twist forces against -∂V/∂θ in the charts (finite differences), its
// energy balance, and agreement with the natural formulation (spin rates as states, the gyroscopic force
// by hand) on a bent, twisted, spinning line under a moving top.
#include <gtest/gtest.h>

#include <random>

#include "spatial_independent_util.h"

namespace riser_sim {
namespace {

using namespace spatial;
using spatial_test::LineSpec;

// The top's hold on the spin: the hang-off's (held), none (free), a torsion spring k_t = 500 N m/rad with a
// damper c_t = 30 N m s/rad.
enum class Top { kHeld, kFree, kSpring };
const char* name(Top t) { return t == Top::kHeld ? "held" : t == Top::kFree ? "free" : "spring"; }

TorsionProperties twistProps(double damping, Top top = Top::kHeld) {
  TorsionProperties p;
  p.free_top = top == Top::kFree;
  p.top_stiffness = top == Top::kSpring ? 500.0 : 0.0;
  p.top_damping = top == Top::kSpring ? 30.0 : 0.0;  // its damper too (both formulations' own code)
  p.stiffness = 1e3;
  p.polar_inertia = 0.05;
  p.damping = damping;
  p.end_polar_inertia = 0.5;
  return p;
}

std::vector<Vec3> bentDirections(int nb) {
  std::vector<Vec3> d;
  for (int i = 0; i < nb; ++i) d.push_back(Vec3(0.3 + 0.1 * i, 0.2 - 0.05 * i, -1.0).normalized());
  return d;
}

// Only the twist acts (no gravity, no bending, inextensible): at rest M_θ θ'' = Q_θ = -∂V/∂θ. Charts moved
// off their centres (u = 0.3 rad-ish, the twist charts too), random spins; held, free and spring-held top.
TEST(SpatialIndependentTorsion, ForcesAreTheGradientOfTheTwistEnergy) {
  for (Top kind : {Top::kHeld, Top::kFree, Top::kSpring}) {
    LineSpec s;
    s.segments = 6;
    s.props.mass_per_length = 10.0;
    s.options.bending = false;
    s.options.axial_flexibility = false;
    auto m = spatial_test::spatialModel(s, Vec3::Zero());
    m->setTorsion(twistProps(0.0, kind));
    IndependentFormulation3 f(*m);
    auto d = f.makeData();
    SphereCharts charts;
    const int p = f.positionSize();
    VecX y = VecX::Zero(2 * p), dy = y;
    f.packState(rigidChain(m->line(), Vec3::Zero(), bentDirections(m->bodies()), Vec3::Zero(), Vec3::Zero()), charts,
                y);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int c = 0; c < p; ++c) y[c] = (c < f.spinIndex(f.firstSpin()) ? 0.3 : 0.8) * u(rng);
    const PointMotion3 top;
    Kinematics3 kin(m->bodies());
    auto V = [&](const VecX& yy) {
      f.kinematics(yy, charts, top, kin);
      return f.twistEnergy(yy, charts, kin, *d);
    };
    f.derivative(0.0, y, charts, top, dy, *d);
    const VecX Q = d->rhs;
    double worst = 0.0;
    constexpr double eps = 1e-6;
    for (int c = 0; c < p; ++c) {
      VecX a = y, b = y;
      a[c] += eps;
      b[c] -= eps;
      worst = std::max(worst, std::abs(-(V(a) - V(b)) / (2 * eps) - Q[c]));
    }
    const double scale = Q.cwiseAbs().maxCoeff();
    std::printf("[independent torsion] %s top: Q_θ vs -dV/dθ (u and φ, charts off centre): %.2e of %.3g N m\n",
                name(kind), worst / scale, scale);
    EXPECT_GT(scale, 10.0);
    EXPECT_LT(worst / scale, 1e-7);  // central differences at 1e-6: truncation ~1e-12, round-off ~1e-10 V/eps
  }
}

// The flexible line of test_spatial_torsion's swing: bent, twisted (θ_i = 0.1 i), spinning (3 sin(1 + i)
// rad/s), swinging under a swaying, yawing top, with bending and twist dampers.
struct Pair {
  std::shared_ptr<Model3> model;
  std::unique_ptr<Simulator3> nat;
  std::unique_ptr<IndependentSimulator3> ind;
  double weight, scale;
};

std::unique_ptr<TopMotion3> swingTop() {
  return std::make_unique<PlanarMotion3>(spatial_test::topSway(Vec2(0.5, 0.3), 1.0), spatial_test::yawTilt(0.3, 0.5));
}

Pair pair(Top top, bool pinned = false, IntegratorKind kind = IntegratorKind::kRk4) {
  LineSpec s = spatial_test::flexibleLine();
  s.segments = 8;
  Pair r;
  r.model = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  r.model->setTorsion(twistProps(2.0, top));
  const int nb = r.model->bodies();
  // Pinned: at rest (a rigid turn would move the end off its anchor; E0 would count that velocity).
  const Vec3 turn = pinned ? Vec3::Zero() : Vec3(0.2, -0.3, 0.5);
  const Kinematics3 kin0 = rigidChain(r.model->line(), Vec3::Zero(), bentDirections(nb), Vec3::Zero(), turn);
  if (pinned) r.model->setBottom(BottomBoundary::kPinned, kin0.back().end());
  r.nat = std::make_unique<Simulator3>(r.model, swingTop(), kind);
  r.ind = std::make_unique<IndependentSimulator3>(r.model, swingTop(), kind);
  r.nat->reset(kin0, 0.0);
  r.ind->reset(kin0, 0.0);
  VecX theta(nb), omega(nb);
  for (int i = 0; i < nb; ++i) theta[i] = 0.1 * i, omega[i] = 3.0 * std::sin(1.0 + i);
  r.nat->setTwist(theta, omega);
  r.ind->setTwist(theta, omega);
  r.weight = (s.props.mass_per_length * s.length + s.end_mass) * s.g;
  r.scale = r.weight * s.length;
  return r;
}

struct Agreement {
  double dx = 0.0;       // positions [m]
  double frame = 0.0;    // material directors (unit vectors)
  double spin = 0.0;     // spin rates [rad/s]
  double force = 0.0;    // top reaction / weight
  double twist = 0.0;    // top twisting moment [N m]
  double energy = 0.0;   // |ΔE|, |ΔW| / m g L
  double balance = 0.0;  // independent run's |E - E0 - W| / m g L
  long switches = 0;
};

Agreement compare(double h, double duration, Top top = Top::kHeld, bool pinned = false) {
  Pair r = pair(top, pinned);
  const Model3& m = *r.model;
  const int nb = m.bodies(), vo = r.nat->formulation().positionSize();
  AlignedVector<Vec3> pn(nb + 1), pi(nb + 1);
  Kinematics3 kn(nb), ki(nb);
  const double e0 = r.ind->energy();
  Agreement a;
  const int per = int(std::lround(0.05 / h)), samples = int(std::lround(duration / 0.05));
  for (int k = 0; k < samples; ++k) {
    for (int j = 0; j < per; ++j) {
      EXPECT_TRUE(r.nat->step(h));
      EXPECT_TRUE(r.ind->step(h));
    }
    r.nat->positions(pn);
    r.ind->positions(pi);
    for (int i = 0; i <= nb; ++i) a.dx = std::max(a.dx, (pn[i] - pi[i]).norm());
    r.nat->kinematics(kn);
    r.ind->kinematics(ki);
    const TwistFrames& fn = r.nat->lastEvaluation().twist.frames;
    const VecX& yn = r.nat->state();
    const IndependentFormulation3& fi = r.ind->formulation();
    for (int i = 0; i < nb; ++i) {  // rfe 0 too: held, its frame is the hang-off's transported
      const Vec3 dn = materialDirector(fn, i, kn[i].e.normalized(), yn[m.dofs() + i]);
      a.frame = std::max(a.frame, (dn - fi.materialDirector(r.ind->state(), r.ind->charts(), ki, i)).norm());
      if (i < fi.firstSpin()) continue;  // a held rfe 0's rate is no state of the natural formulation
      a.spin = std::max(a.spin, std::abs(yn[vo + m.dofs() + i] - fi.spinRate(r.ind->state(), r.ind->charts(), ki, i)));
    }
    const Reactions3 rn = r.nat->evaluate().reactions, ri = r.ind->evaluate().reactions;
    a.force = std::max(a.force, (rn.top - ri.top).norm() / r.weight);
    a.twist = std::max(a.twist, std::abs(rn.top_twist - ri.top_twist));
    a.energy = std::max({a.energy, std::abs(r.nat->energy() - r.ind->energy()) / r.scale,
                         std::abs(r.nat->work() - r.ind->work()) / r.scale});
    a.balance = std::max(a.balance, std::abs(r.ind->energy() - e0 - r.ind->work()) / r.scale);
  }
  a.switches = r.ind->chartSwitches();
  return a;
}

// Both rk4 at h = 1e-4 s: the difference is the two schemes' truncation in different coordinates, O(h⁴),
// plus the natural formulation's Baumgarte response (as the torsion-off cross-check, bounds as there).
TEST(SpatialIndependentTorsion, AgreesWithNaturalFormulation) {
  const Agreement a = compare(1e-4, 2.0);
  std::printf(
      "[independent vs natural, torsion] h = 1e-4 s, 2 s: |dx| %.2e m, frames %.2e, spin rates %.2e rad/s, "
      "top force %.2e of the weight, top twist %.2e N m, E/W %.2e of m g L, independent E - E0 - W %.2e, "
      "chart switches %ld\n",
      a.dx, a.frame, a.spin, a.force, a.twist, a.energy, a.balance, a.switches);
  EXPECT_LT(a.dx, 1e-9);     // [m]
  EXPECT_LT(a.frame, 1e-9);  // unit vectors
  EXPECT_LT(a.spin, 1e-7);   // [rad/s]: rates are one derivative up from angles, ~ω_max x angles
  EXPECT_LT(a.force, 1e-6);  // as the torsion-off bound (stiff axial modes amplify by ω²)
  EXPECT_LT(a.twist, 1e-6);  // [N m], of moments ~1e2
  EXPECT_LT(a.energy, 1e-9);
  EXPECT_LT(a.balance, 1e-9);
  EXPECT_GT(a.switches, 0);
}

// A free and a spring-held top (rfe 0 spins): the same comparison over 1 s, the same bounds.
TEST(SpatialIndependentTorsion, FreeAndSpringTopsAgreeWithNaturalFormulation) {
  for (Top top : {Top::kFree, Top::kSpring}) {
    const Agreement a = compare(1e-4, 1.0, top);
    std::printf(
        "[independent vs natural, torsion, %s top] |dx| %.2e m, frames %.2e, spin rates %.2e rad/s, top force "
        "%.2e of the weight, top twist %.2e N m, E/W %.2e of m g L, independent E - E0 - W %.2e\n",
        name(top), a.dx, a.frame, a.spin, a.force, a.twist, a.energy, a.balance);
    EXPECT_LT(a.dx, 1e-9);
    EXPECT_LT(a.frame, 1e-9);
    EXPECT_LT(a.spin, 1e-7);
    EXPECT_LT(a.force, 1e-6);
    EXPECT_LT(a.twist, 1e-6);
    EXPECT_LT(a.energy, 1e-9);
    EXPECT_LT(a.balance, 1e-9);
  }
}

// Pinned bottom (free in twist; the anchor's force a multiplier in both), held top, from rest, 1 s.
TEST(SpatialIndependentTorsion, PinnedAgreesWithNaturalFormulation) {
  const Agreement a = compare(1e-4, 1.0, Top::kHeld, true);
  std::printf(
      "[independent vs natural, torsion, pinned] |dx| %.2e m, frames %.2e, spin rates %.2e rad/s, top force "
      "%.2e of the weight, top twist %.2e N m, E/W %.2e of m g L, independent E - E0 - W %.2e\n",
      a.dx, a.frame, a.spin, a.force, a.twist, a.energy, a.balance);
  EXPECT_LT(a.dx, 1e-9);
  EXPECT_LT(a.frame, 1e-9);
  EXPECT_LT(a.spin, 1e-7);
  EXPECT_LT(a.force, 1e-6);
  EXPECT_LT(a.twist, 1e-6);
  EXPECT_LT(a.energy, 1e-9);
  EXPECT_LT(a.balance, 1e-9);
}

// Truncation: halving h shrinks the difference ~16x (rk4); > 8 asserts order > 3.
TEST(SpatialIndependentTorsion, DifferenceConvergesAtRk4Order) {
  const Agreement c = compare(4e-4, 0.5), f = compare(2e-4, 0.5);
  std::printf(
      "[independent vs natural, torsion] h = 4e-4: |dx| %.3e m, frames %.3e; h = 2e-4: %.3e m, %.3e; ratios "
      "%.1f, %.1f\n",
      c.dx, c.frame, f.dx, f.frame, c.dx / f.dx, c.frame / f.frame);
  EXPECT_GT(c.dx / f.dx, 8.0);
  EXPECT_GT(c.frame / f.frame, 8.0);
}

}  // namespace
}  // namespace riser_sim
