// Small oscillations of a hanging line in 3D (spatial/modal.h) against the planar modal analysis: the
// transverse modes come in degenerate pairs (the two vertical planes) at the planar frequencies, the
// axial modes once each. Flexible line, free end with an end mass, bending and axial springs.
#include <gtest/gtest.h>

#include <algorithm>

#include "riser_sim/planar/modal.h"
#include "riser_sim/spatial/modal.h"
#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

struct Spectra {
  std::vector<double> w3, expected;  // sorted ω [rad/s]: 3D, and the planar with transverse ones doubled
  int axial3 = 0, axial2 = 0;
  double pair_spread = 0.0;  // max over transverse 3D modes of the relative distance to the nearest other one
  double residual = 0.0, asymmetry = 0.0;
};

Spectra spectra(int n, const Vec3& gravity) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = n;
  auto m3 = spatial_test::spatialModel(s, gravity);
  // Straight along gravity, Δ = 0: Newton finds the stretched equilibrium.
  const std::vector<Vec3> dirs(m3->bodies(), gravity.normalized());
  const Kinematics3 eq = equilibrium3(*m3, rigidChain(m3->line(), Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero()));
  const ModalResult3 r3 = computeModes3(*m3, eq);

  // The planar line at the same equilibrium (its plane: the one through gravity and x after the map).
  auto m2 = spatial_test::planarModel(s);
  const Kinematics kin2 = spatial_test::planarHanging(eq);
  ModalOptions o;
  o.modes = 2 * m2->bodies();
  const ModalResult r2 = computeModes(*m2, kin2, Vec2::Zero(), o);

  Spectra sp;
  for (const auto& m : r3.modes) sp.w3.push_back(m.omega), sp.axial3 += m.axial;
  for (const auto& m : r2.modes) {
    const bool axial = m.character == "axial";
    sp.axial2 += axial;
    sp.expected.push_back(m.omega);
    if (!axial) sp.expected.push_back(m.omega);
  }
  std::sort(sp.expected.begin(), sp.expected.end());
  for (const auto& a : r3.modes) {
    double nearest = 1.0;
    for (const auto& b : r3.modes)
      if (&a != &b && !a.axial && !b.axial) nearest = std::min(nearest, std::abs(b.omega / a.omega - 1.0));
    if (!a.axial) sp.pair_spread = std::max(sp.pair_spread, nearest);
  }
  sp.residual = r3.equilibrium_residual;
  sp.asymmetry = r3.asymmetry;
  return sp;
}

void check(int n, const Vec3& gravity, const char* label) {
  const Spectra sp = spectra(n, gravity);
  ASSERT_EQ(sp.w3.size(), sp.expected.size());
  double worst = 0.0, worst_low = 0.0;
  for (size_t k = 0; k < sp.w3.size(); ++k) {
    const double e = std::abs(sp.w3[k] / sp.expected[k] - 1.0);
    worst = std::max(worst, e);
    if (k < 8) worst_low = std::max(worst_low, e);
  }
  std::printf(
      "[spatial modal %s] n = %d: lowest 3D ω %.6f %.6f %.6f %.6f rad/s; pairs within %.1e; vs planar (pairs) worst "
      "%.2e (lowest 8: %.2e) over %zu modes, axial %d/%d, residual %.1e, asymmetry %.1e\n",
      label, n, sp.w3[0], sp.w3[1], sp.w3[2], sp.w3[3], sp.pair_spread, worst, worst_low, sp.w3.size(), sp.axial3,
      sp.axial2, sp.residual, sp.asymmetry);
  // The brief's bound, relative. Both sides take K from central differences (step 1e-6): round-off
  // eps |Q| / h ~ 1e-10 of the entries. Measured 4.1e-11 (vertical, n = 12 and 20), 5.3e-11 (tilted).
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(sp.pair_spread, 1e-9);  // same round-off; measured 2.6e-12..3.9e-11
  EXPECT_EQ(sp.axial3, sp.axial2);
  EXPECT_EQ(sp.axial3, n + 1);  // one axial mode per rfe
  EXPECT_LT(sp.residual, 1e-12);
}

TEST(SpatialModal, HangingLineHasPlanarModesInPairs) {
  check(12, Vec3(0, 0, -9.81), "vertical");
  check(20, Vec3(0, 0, -9.81), "vertical");
}

// Frame invariance: gravity along a tilted axis, so the pairs are not the x and y planes.
TEST(SpatialModal, TiltedGravityGivesTheSameSpectrum) {
  check(12, spatial_test::yawTilt(0.7, 0.4) * Vec3(0, 0, -9.81), "tilted");
}

}  // namespace
}  // namespace riser_sim
