// --modes in 3D through the CLI (docs/spatial.md, "--modes"): free lines against the planar modes (pairs where
// the line is symmetric), pinned lines (taut and sagging) against the planar pinned modes, and a stiff rod on
// a top flex joint against the rigid pendulum on its spring.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cli_test_util.h"

using namespace cli_test;

namespace {

constexpr double kG = 9.81;

// One row of a --modes table: frequency [Hz], character, axial share.
struct ModeRow {
  double f;
  std::string character;
  double share;  // axial share of the kinetic energy
};
std::vector<ModeRow> modeTable(const std::string& out) {
  std::vector<ModeRow> rows;
  std::istringstream in(out);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string k, period, f, omega, character;
    double share = NAN;
    ls >> k >> period >> f >> omega >> character >> share;
    rows.push_back({f == "-" ? 0.0 : std::stod(f), character, share});
  }
  return rows;
}

// A planar scene with --set space=spatial --modes: the in-plane and axial 3D modes are the planar modes,
// in order, at the planar frequencies. A line hanging freely (hanging_chain) is symmetric about the
// vertical: each transverse mode comes in a pair, the out-of-plane one at the same frequency too. Held
// displaced by a dead horizontal end load (paper_table1) it is not: the out-of-plane modes differ (printed).
TEST(CliSpatialEnds, ModesIn3DArePairsAtThePlanarFrequencies) {
  for (const std::string file : {"hanging_chain.yaml", "paper_table1.yaml"}) {
    SCOPED_TRACE(file);
    const bool symmetric = file == "hanging_chain.yaml";
    const CliRun p = runCli("--scene " + kScenes + file + " --quiet --modes 6");
    const std::string csv = tempPath("modes3.csv");
    const CliRun s = runCli("--scene " + kScenes + file + " --quiet --set space=spatial --modes 12 --modes-csv " + csv);
    ASSERT_EQ(p.code, 0) << p.err;
    ASSERT_EQ(s.code, 0) << s.err;
    const auto planar = modeTable(p.out), spatial = modeTable(s.out);
    ASSERT_EQ(planar.size(), 6u);
    ASSERT_EQ(spatial.size(), 12u);
    std::vector<ModeRow> in, out;
    for (const ModeRow& m : spatial) (m.character == "out-of-plane" ? out : in).push_back(m);
    double worst_in = 0.0, worst_out = 0.0;
    size_t matched = 0, transverse = 0;
    for (size_t k = 0; k < planar.size() && k < in.size(); ++k, ++matched) {
      EXPECT_EQ(in[k].character == "axial", planar[k].character == "axial") << k;
      worst_in = std::max(worst_in, std::abs(in[k].f / planar[k].f - 1.0));
      EXPECT_NEAR(in[k].share, planar[k].share, 1e-3) << k;  // the same definition, 3 printed digits
      if (planar[k].character == "axial" || transverse >= out.size()) continue;
      worst_out = std::max(worst_out, std::abs(out[transverse++].f / planar[k].f - 1.0));
    }
    std::printf(
        "[modes %s] %zu in-plane/axial modes vs planar: %.2e; %zu out-of-plane vs the planar transverse: %.2e\n",
        file.c_str(), matched, worst_in, transverse, worst_out);
    EXPECT_GE(matched, 5u);
    EXPECT_GE(transverse, 5u);
    EXPECT_LT(worst_in, 1e-5);  // 6 printed digits
    if (symmetric)
      EXPECT_LT(worst_out, 1e-5);
    else
      EXPECT_GT(worst_out, 1e-4);  // the end load's plane is special
    EXPECT_EQ(readFile(csv).rfind("mode,period_s,frequency_hz,character,point,s,x,y,z,dx,dy,dz\n", 0), 0u);
  }
}

// A line pinned at both ends, taut and vertical (between (0, 0) and (0, -10.05) m, 0.5 % stretched): the 3D
// modes (the end held in the null space of its Jacobian, the anchor's force a dead load) are the planar pinned
// modes (docs/modal.md), the transverse ones in degenerate pairs (the line is symmetric about its axis).
// Bound 1e-5: the tables' 6 printed digits.
TEST(CliSpatialEnds, PinnedModesIn3DArePairsAtThePlanarFrequencies) {
  const std::string scene =
      writeScene("pinned_modes",
                 "name: pinned_modes\nline: {length: 10, elements: 8, mass_per_length: 10, EA: 1.0e6, EI: 2.0e3}\n"
                 "top: {position: [0, 0]}\nbottom: {type: pinned, position: [0, -10.05]}\n"
                 "initial: {type: between_points}\nsolver: {integrator: rk4, dt: 1.0e-4}\n");
  const CliRun p = runCli("--scene " + scene + " --quiet --modes 8");
  const CliRun s = runCli("--scene " + scene + " --quiet --set space=spatial --modes 16");
  ASSERT_EQ(p.code, 0) << p.err;
  ASSERT_EQ(s.code, 0) << s.err;
  const auto planar = modeTable(p.out), spatial = modeTable(s.out);
  ASSERT_EQ(planar.size(), 8u);
  ASSERT_EQ(spatial.size(), 16u);
  std::vector<double> expected;  // the planar frequencies, transverse ones twice
  for (const ModeRow& m : planar) {
    expected.push_back(m.f);
    if (m.character != "axial") expected.push_back(m.f);
  }
  std::sort(expected.begin(), expected.end());
  double worst = 0.0;
  for (size_t k = 0; k < 12; ++k) worst = std::max(worst, std::abs(spatial[k].f / expected[k] - 1.0));
  std::printf("[pinned modes] lowest 12 3D modes vs the planar pinned modes (pairs): %.2e; %.5g Hz lowest\n", worst,
              spatial[0].f);
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(spatial[0].f, 0.1);  // the held end: no pendulum mode
}

// The same line sagging between (0, 0) and (6, -7) m: the anchor's force has a horizontal part, whose geometric
// stiffness the in-plane modes need; the in-plane and axial 3D modes are the planar pinned ones (6 digits).
TEST(CliSpatialEnds, SaggingPinnedModesInPlaneAreThePlanarOnes) {
  const std::string scene =
      writeScene("sag_modes",
                 "name: sag_modes\nline: {length: 10, elements: 8, mass_per_length: 10, EA: 1.0e6, EI: 2.0e3}\n"
                 "top: {position: [0, 0]}\nbottom: {type: pinned, position: [6, -7]}\n"
                 "initial: {type: between_points}\nsolver: {integrator: rk4, dt: 1.0e-4}\n");
  const CliRun p = runCli("--scene " + scene + " --quiet --modes 6");
  const CliRun s = runCli("--scene " + scene + " --quiet --set space=spatial --modes 14");
  ASSERT_EQ(p.code, 0) << p.err;
  ASSERT_EQ(s.code, 0) << s.err;
  const auto planar = modeTable(p.out), spatial = modeTable(s.out);
  std::vector<ModeRow> in;
  for (const ModeRow& m : spatial)
    if (m.character != "out-of-plane") in.push_back(m);
  ASSERT_GE(in.size(), planar.size());
  double worst = 0.0;
  for (size_t k = 0; k < planar.size(); ++k) worst = std::max(worst, std::abs(in[k].f / planar[k].f - 1.0));
  std::printf("[sagging pinned modes] %zu in-plane 3D modes vs planar: %.2e (lowest %.5g Hz)\n", planar.size(), worst,
              in[0].f);
  EXPECT_LT(worst, 1e-5);
}

// --modes with a top flex joint: a stiff rod (EI = 1e10 N m², inextensible, 10 m, 100 kg, 50 kg end mass)
// hanging from a joint of k = 3e4 N m/rad swings as a rigid pendulum on a rotational spring,
// ω² = (k + g (m L/2 + m_e L)) / (m L²/3 + m_e L²), in both vertical planes. The rod's own compliance
// (the joint turns rfe 0 against the bending springs c = EI/d = 6e9 N m/rad) lowers ω by ~k/2c = 2.5e-6;
// without the joint ω would be 1.085 rad/s, half of it.
TEST(CliSpatialEnds, ModesWithATopFlexJoint) {
  const std::string scene =
      writeScene("rod",
                 "name: rod\nspace: spatial\nline: {length: 10, elements: 6, mass_per_length: 10, EI: 1.0e10, "
                 "axial_flexibility: false, end_mass: 50}\ntop: {position: [0, 0, 0], flex_joint: {stiffness: 3.0e4, "
                 "damping: 100}}\ninitial: {type: hanging}\n");
  const CliRun r = runCli("--scene " + scene + " --quiet --modes 2");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto modes = modeTable(r.out);
  ASSERT_EQ(modes.size(), 2u);
  const double J = 100.0 * 100.0 / 3.0 + 50.0 * 100.0;
  const double f = std::sqrt((3.0e4 + kG * (100.0 * 5.0 + 50.0 * 10.0)) / J) / (2.0 * M_PI);
  std::printf("[modes flex joint] %.6g, %.6g Hz vs the rigid pendulum on its spring %.6g Hz\n", modes[0].f, modes[1].f,
              f);
  EXPECT_EQ(modes[0].character, "in-plane");
  EXPECT_EQ(modes[1].character, "out-of-plane");
  for (const ModeRow& m : modes) EXPECT_NEAR(m.f / f, 1.0, 2e-5);  // compliance 2.5e-6 + 6 printed digits
}

}  // namespace

// More modes asked than the line has: every mode shown and a warning that says how many there are (a pinned 3D
// line has fewer modes than coordinates: its constraints take some).
TEST(CliSpatialEnds, MoreModesThanTheLineHasIsSaid) {
  const std::string scene = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/spatial_flat_umbilical.yaml";
  const CliRun all = runCli("--scene " + scene + " --modes 1000");
  ASSERT_EQ(all.code, 0) << all.err;
  const size_t count = modeTable(all.out).size();
  ASSERT_GT(count, 10u);
  EXPECT_NE(all.err.find("warning: --modes 1000: the line has " + std::to_string(count) + " modes"), std::string::npos)
      << all.err;
  // One more than it has: said too; exactly as many: no warning.
  const CliRun over = runCli("--scene " + scene + " --modes " + std::to_string(count + 1));
  EXPECT_EQ(modeTable(over.out).size(), count);
  EXPECT_NE(over.err.find("warning: --modes"), std::string::npos) << over.err;
  const CliRun exact = runCli("--scene " + scene + " --modes " + std::to_string(count));
  EXPECT_EQ(exact.err.find("warning: --modes"), std::string::npos) << exact.err;
}
