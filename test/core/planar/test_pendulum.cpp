// Large-amplitude pendulum: a heavy end mass on a nearly massless inextensible line must swing with
// the exact elliptic period T = 4 sqrt(l/g) K(sin(θ0/2)).
#include <gtest/gtest.h>

#include <cstdio>

#include "validation_util.h"

namespace riser_sim {
namespace {

constexpr double kLength = 10.0;    // [m] (short: T ≈ 6.5-7.5 s keeps the run cheap)
constexpr double kEndMass = 100.0;  // [kg]
constexpr double kLineMass = 1e-4;  // [kg/m]
// Line-mass fraction ε = μ L / m_s = 1e-5.
constexpr double kMassFraction = kLineMass * kLength / kEndMass;
// Reference: the rigid compound pendulum (point mass at L plus a uniform rod, which is exactly the
// rfe mass distribution when the chain stays straight) has l_eff = L (1 + ε/3) / (1 + ε/2), a
// -ε/12 correction to the period. The chain is not rigid: when it bends (most at θ0 = 90°, where
// the tension starts at zero and the light links whip), the period changes by O(ε) with an unknown
// O(1) coefficient. RK4 phase error (ω h)^4 ~ 1e-15 and the interpolated zero crossings (x'' = 0 at
// the bottom, so the linear interpolation error is O(h³)) are far below that. Bound: ε itself.
// Measured: 2.8e-10 (30°), 1.7e-7 (90°). A misplaced end mass (at L - d/2) would give ~6e-2.
constexpr double kPeriodRelTol = kMassFraction;
// Inextensible, light chain with Baumgarte ω_c = 50 rad/s: the zero-tension release at 90° excites
// link whipping, the worst case; measured drift 1e-6, constraint error 1.1e-6 m at h = 1e-4 s.
constexpr double kEnergyDriftTol = 1e-5;
constexpr double kConstraintTol = 1e-5;  // [m] = 1e-6 L
constexpr double kDt = 1e-4;             // [s]; h = 5e-4 diverges at 90° (stiff light links when the tension rises)

struct Swing {
  double period = 0.0, reference = 0.0, drift = 0.0, cerr = 0.0;
};

Swing swing(double theta0, bool from_statics) {
  Scene s;
  s.length = kLength;
  s.elements = 4;
  s.line.mass_per_length = kLineMass;
  s.line.EA = 1e9;  // unused: inextensible
  s.options.bending = false;
  s.options.axial_flexibility = false;
  s.end_mass = kEndMass;
  s.solver.dt = kDt;
  if (from_statics) {  // the paper's way: end displaced by a horizontal force (straight when massless)
    s.initial.type = InitialKind::kDisplaced;
    s.initial.end_dx = -kLength * std::sin(theta0);
  } else {  // |end_dx| = L is out of the statics' range: start from the straight rigid-rod position
    s.initial.type = InitialKind::kStraight;
    s.initial.angle = -M_PI / 2 - theta0;
  }
  auto sim = buildSimulator(s);
  const double eps = kMassFraction;
  Swing out;
  out.reference = validation::pendulumPeriod(kLength * (1 + eps / 3) / (1 + eps / 2), s.gravity, theta0);
  Kinematics kin(sim->model().bodies());
  std::vector<double> t, x;
  t.reserve(size_t(2.2 * out.reference / kDt) + 2);
  x.reserve(t.capacity());
  while (sim->time() < 2.1 * out.reference) {
    if (!sim->step()) break;
    sim->kinematics(kin);
    t.push_back(sim->time());
    x.push_back(kin.back().end().x() - kin[0].A.x());
  }
  EXPECT_FALSE(sim->diverged()) << sim->divergenceReason();
  // Crossings at T/4, 3T/4, 5T/4, 7T/4: two full periods measured between crossings of the same sign.
  const std::vector<double> z = validation::zeroCrossings(t, x);
  EXPECT_EQ(z.size(), 4u);
  if (z.size() >= 4) out.period = 0.5 * ((z[2] - z[0]) + (z[3] - z[1]));
  out.drift = sim->energyDrift();
  out.cerr = sim->maxConstraintError();
  return out;
}

void check(double theta_deg, bool from_statics) {
  const Swing s = swing(theta_deg * M_PI / 180.0, from_statics);
  std::printf("[pendulum %g deg] T = %.9f s, exact %.9f s, rel error %.3e, energy drift %.2e, constraint %.2e m\n",
              theta_deg, s.period, s.reference, s.period / s.reference - 1.0, s.drift, s.cerr);
  EXPECT_NEAR(s.period / s.reference, 1.0, kPeriodRelTol);
  EXPECT_LT(std::abs(s.drift), kEnergyDriftTol);
  EXPECT_LT(s.cerr, kConstraintTol);
}

TEST(Pendulum, EllipticIntegralByAgm) {
  // K(0) = π/2; K(sin 45°) = Γ(1/4)² / (4 sqrt(π)) (lemniscatic case).
  EXPECT_NEAR(validation::ellipticK(0.0), M_PI / 2, 1e-15);
  EXPECT_NEAR(validation::ellipticK(std::sqrt(0.5)), std::pow(std::tgamma(0.25), 2) / (4 * std::sqrt(M_PI)), 1e-14);
}

TEST(Pendulum, PeriodAt30DegreesFromDisplacedStatics) { check(30.0, true); }

TEST(Pendulum, PeriodAt90DegreesFromHorizontal) { check(90.0, false); }

}  // namespace
}  // namespace riser_sim
