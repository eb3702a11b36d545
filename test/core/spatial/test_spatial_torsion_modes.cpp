// Torsional modes in the 3D modal analysis (spatial/modal.h with line.torsion): a uniform shaft fixed in
// twist at the top with an end inertia has (ωL/c) tan(ωL/c) = J_line/J_end, c = sqrt(GJ/ρI_p) (exact); the
// rfes' lumped polar inertias on springs GJ/d converge to it at order 2 in d. Torsion on leaves the
// bending modes of a straight line unchanged (no coupling without curvature).
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim/spatial/modal.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

// Root k (0, 1, ...) of x tan x = mu: in (kπ, kπ + π/2), by bisection (to round-off).
double root(double mu, int k) {
  double lo = k * M_PI, hi = k * M_PI + 0.5 * M_PI - 1e-15;
  for (int it = 0; it < 200; ++it) {
    const double x = 0.5 * (lo + hi);
    (x * std::tan(x) < mu ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

// test_spatial_torsion's pendulum: L = 10 m, GJ = 1e4 N m², ρI_p = 1 kg m, J_end = 10 kg m², hanging
// straight (no bending, inextensible).
constexpr double kL = 10.0, kGJ = 1e4, kRhoIp = 1.0, kJend = 10.0;

// Root k (1, 2, ...) of tan x = -x / mu: in (kπ - π/2, kπ).
double freeRoot(double mu, int k) {
  double lo = k * M_PI - 0.5 * M_PI + 1e-15, hi = k * M_PI;
  for (int it = 0; it < 200; ++it) {
    const double x = 0.5 * (lo + hi);
    (std::tan(x) + x / mu < 0.0 ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

// Roots of the shaft on a top spring k_t (κ = k_t L/GJ): θ = cos kx + (κ/kL) sin kx (GJ θ'(0) = k_t θ(0)),
// J_end ω² θ(L) = GJ θ'(L); times x = kL: g(x) = (x²/μ) cos x + (κ/μ + 1) x sin x - κ cos x = 0 (κ -> ∞:
// x tan x = μ; κ = 0: tan x = -x/μ). The first `count` roots by a scan (step 1e-3) and bisection.
std::vector<double> springRoots(double mu, double kappa, int count) {
  auto g = [&](double x) {
    return x * x / mu * std::cos(x) + (kappa / mu + 1.0) * x * std::sin(x) - kappa * std::cos(x);
  };
  std::vector<double> r;
  for (double x = 1e-3; int(r.size()) < count; x += 1e-3) {
    if (g(x) * g(x + 1e-3) > 0.0) continue;
    double lo = x, hi = x + 1e-3;
    for (int it = 0; it < 100; ++it) {
      const double m = 0.5 * (lo + hi);
      (g(lo) * g(m) <= 0.0 ? hi : lo) = m;
    }
    r.push_back(0.5 * (lo + hi));
  }
  return r;
}

std::shared_ptr<Model3> shaft(int n, bool torsion, bool free_top = false, double top_stiffness = 0.0) {
  TorsionProperties t;  // stiffness 0: torsion off
  if (torsion) {
    t.stiffness = kGJ;
    t.polar_inertia = kRhoIp;
    t.end_polar_inertia = kJend;
    t.free_top = free_top;
    t.top_stiffness = top_stiffness;
  }
  return spatial_test::twistShaft(n, t);  // L = kL
}

ModalResult3 modes(const Model3& m) {
  const Kinematics3 down =
      rigidChain(m.line(), Vec3::Zero(), std::vector<Vec3>(m.bodies(), -Vec3::UnitZ()), Vec3::Zero(), Vec3::Zero());
  return computeModes3(m, equilibrium3(m, down));
}

std::vector<double> torsional(const ModalResult3& r) {
  std::vector<double> w;
  for (const Mode3& m : r.modes)
    if (m.torsional) w.push_back(m.omega);
  return w;
}

TEST(SpatialTorsionModes, ShaftConvergesToTheExactFrequencyEquation) {
  const double c = std::sqrt(kGJ / kRhoIp), mu = kRhoIp * kL / kJend;
  double prev[2] = {0.0, 0.0}, err[2] = {0.0, 0.0};
  for (int n : {8, 16, 32}) {
    const ModalResult3 r = modes(*shaft(n, true));
    const std::vector<double> w = torsional(r);
    ASSERT_EQ(int(w.size()), n);  // one per spinning rfe (n + 1 rfes; rfe 0 is held by the hang-off)
    for (int k = 0; k < 2; ++k) {
      const double exact = root(mu, k) * c / kL;
      err[k] = std::abs(w[k] / exact - 1.0);
      std::printf("[torsion modes] shaft n = %2d, mode %d: ω = %.9f rad/s vs exact %.9f, error %.3e%s\n", n, k + 1,
                  w[k], exact, err[k], n > 8 ? (" (x" + std::to_string(prev[k] / err[k]) + ")").c_str() : "");
      // Second order in d: the error falls 4x per halving (3.5..4.5 leaves room for the next order).
      if (n > 8) {
        EXPECT_GT(prev[k] / err[k], 3.5);
        EXPECT_LT(prev[k] / err[k], 4.5);
      }
      prev[k] = err[k];
    }
    for (const Mode3& m : r.modes) {
      if (m.torsional) EXPECT_GT(m.torsion_fraction, 1.0 - 1e-9);  // straight: the spins are on their own
    }
  }
  // The time-domain pendulum (test_spatial_torsion) measured the first period's error 5.21e-5 at n = 32:
  // the same discretisation, so the same error (to the integrator's 1e-9 and the zero-crossing fit).
  EXPECT_NEAR(err[0], 5.21e-5, 1e-6);
  EXPECT_LT(err[1], 1e-3);
}

// A free top (top.torsion: free): the shaft is free at the top, θ = cos(kx), and the end inertia gives
// GJ k sin(kL) = -J_end ω² cos(kL), i.e. tan x = -x/μ (x = kL = ωL/c, μ = J_line/J_end). Plus the rigid spin
// at ω = 0 (the equilibrium's Newton takes least-norm steps along it).
TEST(SpatialTorsionModes, ShaftWithAFreeTop) {
  const double c = std::sqrt(kGJ / kRhoIp), mu = kRhoIp * kL / kJend;
  double prev[2] = {0.0, 0.0}, err[2] = {0.0, 0.0};
  for (int n : {8, 16, 32}) {
    const ModalResult3 r = modes(*shaft(n, true, true));
    const std::vector<double> w = torsional(r);
    ASSERT_EQ(int(w.size()), n + 1);  // rfe 0 spins too
    double big = 0.0;
    for (const Mode3& m : r.modes) big = std::max(big, std::abs(m.omega2));
    double rigid = HUGE_VAL;
    for (const Mode3& m : r.modes)
      if (m.torsional) rigid = std::min(rigid, std::abs(m.omega2) / big);
    EXPECT_LT(rigid, 1e-10);  // the rigid spin: FD round-off of K relative to its largest entry
    for (int k = 0; k < 2; ++k) {
      const double exact = freeRoot(mu, k + 1) * c / kL;
      err[k] = std::abs(w[k + 1] / exact - 1.0);
      std::printf(
          "[torsion modes] free top n = %2d, mode %d: ω = %.9f rad/s vs exact %.9f, error %.3e%s; rigid spin "
          "ω² %.1e of the largest\n",
          n, k + 1, w[k + 1], exact, err[k], n > 8 ? (" (x" + std::to_string(prev[k] / err[k]) + ")").c_str() : "",
          rigid);
      if (n > 8) {  // second order in d
        EXPECT_GT(prev[k] / err[k], 3.5);
        EXPECT_LT(prev[k] / err[k], 4.5);
      }
      prev[k] = err[k];
    }
  }
  EXPECT_LT(err[0], 1e-3);
}

// A flex joint's torsional stiffness k_t = GJ/L (κ = 1) at the top, against springRoots: between the free
// and the held top.
TEST(SpatialTorsionModes, ShaftOnATopTorsionSpring) {
  const double c = std::sqrt(kGJ / kRhoIp), mu = kRhoIp * kL / kJend, kappa = 1.0;
  const std::vector<double> x = springRoots(mu, kappa, 2);
  double prev[2] = {0.0, 0.0}, err[2] = {0.0, 0.0};
  for (int n : {8, 16, 32}) {
    const std::vector<double> w = torsional(modes(*shaft(n, true, false, kappa * kGJ / kL)));
    ASSERT_EQ(int(w.size()), n + 1);  // rfe 0 spins on the spring
    for (int k = 0; k < 2; ++k) {
      const double exact = x[k] * c / kL;
      err[k] = std::abs(w[k] / exact - 1.0);
      std::printf("[torsion modes] top spring κ = 1, n = %2d, mode %d: ω = %.9f rad/s vs exact %.9f, error %.3e%s\n", n,
                  k + 1, w[k], exact, err[k], n > 8 ? (" (x" + std::to_string(prev[k] / err[k]) + ")").c_str() : "");
      if (n > 8) {  // second order in d
        EXPECT_GT(prev[k] / err[k], 3.5);
        EXPECT_LT(prev[k] / err[k], 4.5);
      }
      prev[k] = err[k];
    }
  }
  // The spring's roots interlace the limits': below the held top's first, between the free top's first
  // non-zero and the held top's second (the root scan found the right ones).
  EXPECT_LT(x[0], root(mu, 0));
  EXPECT_GT(x[1], freeRoot(mu, 1));
  EXPECT_LT(x[1], root(mu, 1));
  EXPECT_LT(err[0], 1e-3);
}

// Straight down the twist does not couple to the director (kb = 0, m = 0): every non-torsional mode with
// torsion on is a torsion-off mode. Equal to the eigen-solver's round-off (~1e-13 relative in ω²) on a
// 23-coordinate problem vs the 16-coordinate one.
TEST(SpatialTorsionModes, BendingModesUnchangedByTorsion) {
  const ModalResult3 off = modes(*shaft(8, false)), on = modes(*shaft(8, true));
  std::vector<double> w;
  for (const Mode3& m : on.modes)
    if (!m.torsional) w.push_back(m.omega2);
  ASSERT_EQ(w.size(), off.modes.size());
  double worst = 0.0;
  for (size_t k = 0; k < w.size(); ++k) worst = std::max(worst, std::abs(w[k] / off.modes[k].omega2 - 1.0));
  std::printf("[torsion modes] %zu bending/pendulum modes with torsion vs without: %.2e relative in ω²\n", w.size(),
              worst);
  EXPECT_LT(worst, 1e-9);
  for (const Mode3& m : off.modes) EXPECT_EQ(m.torsion_fraction, 0.0);
}

// A pinned bottom turns freely about the line (free in twist): pinned where the hanging shaft's end rests, the
// torsional modes are the free end's (x tan x = μ, above), while the pin takes out the pendulum modes. The
// torsional ω agree to the finite-difference K's round-off; the pendulum's lowest ω² rises.
// The shaft made extensible (EA 1e7 N; an inextensible line pinned at its length would be locked).
std::shared_ptr<Model3> extensibleShaft(int n, bool torsion) {
  spatial_test::LineSpec s;
  s.length = kL;
  s.segments = n;
  s.props.mass_per_length = 10.0;
  s.props.EA = 1e7;
  s.options.bending = false;
  s.end_mass = 50.0;
  auto m = spatial_test::spatialModel(s, Vec3(0, 0, -s.g));
  TorsionProperties t;
  t.stiffness = kGJ;
  t.polar_inertia = kRhoIp;
  t.end_polar_inertia = kJend;
  if (torsion) m->setTorsion(t);
  return m;
}

TEST(SpatialTorsionModes, PinnedBottomIsFreeInTwist) {
  for (const bool torsion : {true, false}) {
    auto free_end = extensibleShaft(16, torsion), pinned = extensibleShaft(16, torsion);
    const ModalResult3 rf = modes(*free_end);
    pinned->setBottom(BottomBoundary::kPinned, rf.equilibrium.back().end());
    const ModalResult3 rp = computeModes3(*pinned, equilibrium3(*pinned, rf.equilibrium));
    const std::vector<double> wf = torsional(rf), wp = torsional(rp);
    ASSERT_EQ(wp.size(), wf.size());
    ASSERT_EQ(int(wp.size()), torsion ? 16 : 0);
    double worst = 0.0;
    for (size_t k = 0; k < wf.size(); ++k) worst = std::max(worst, std::abs(wp[k] / wf[k] - 1.0));
    EXPECT_LT(worst, 1e-8);
    // The lowest non-torsional mode: the free end's pendulum, gone with the pin.
    double lowest_free = HUGE_VAL, lowest_pinned = HUGE_VAL;
    for (const Mode3& m : rf.modes)
      if (!m.torsional) lowest_free = std::min(lowest_free, m.omega2);
    for (const Mode3& m : rp.modes)
      if (!m.torsional) lowest_pinned = std::min(lowest_pinned, m.omega2);
    EXPECT_GT(lowest_pinned, 4.0 * lowest_free);
    if (torsion)
      std::printf(
          "[torsion modes] pinned bottom, n = 16: %zu torsional ω vs the free end's: %.2e relative (first "
          "%.9f rad/s); lowest other ω² %.4g -> %.4g 1/s²\n",
          wp.size(), worst, wp[0], lowest_free, lowest_pinned);
  }
}

}  // namespace
}  // namespace riser_sim
