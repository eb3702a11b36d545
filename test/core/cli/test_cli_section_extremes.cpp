// riser_sim_cli --summary on a sectioned line (section_extremes.h): per section the largest effective tension
// and curvature with their arc lengths, and a lazy wave's sag and hog bends, against the range graph of the same
// run (--range-graph: the envelopes per station) and the sections' layout.
#include <gtest/gtest.h>

#include "cli_test_util.h"

using namespace cli_test;

namespace {

const std::string kLazyWave = kScenes + "lazy_wave_riser.yaml";
// lazy_wave_riser.yaml: 560 m to the sag bend, 240 m of buoyancy modules, 600 m on; seabed at -500 m, 10 m
// segments.
constexpr double kBuoyStart = 560.0, kBuoyEnd = 800.0, kSeabed = -500.0, kD = 10.0;

struct Graph {
  std::vector<double> s, t_max, c_min, c_max, s_joint, k_max;
};

// The range graph's rows; the last row's joint columns are empty (NaN).
std::vector<std::vector<double>> graphRows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ls(line + ",");  // a trailing empty field is read too
    std::string field;
    while (std::getline(ls, field, ',')) row.push_back(field.empty() ? NAN : std::strtod(field.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

Graph readGraph(const std::string& path) {
  std::string header;
  const auto rows = graphRows(readFile(path), header);
  EXPECT_EQ(header,
            "s,tension_min,tension_max,clearance_min,clearance_max,s_joint,moment_min,moment_max,"
            "curvature_min,curvature_max");
  Graph g;
  for (const auto& r : rows) {
    g.s.push_back(r[0]);
    g.t_max.push_back(r[2]);
    g.c_min.push_back(r[3]);
    g.c_max.push_back(r[4]);
    if (r.size() > 9 && std::isfinite(r[5])) g.s_joint.push_back(r[5]), g.k_max.push_back(r[9]);
  }
  return g;
}

// The summary's section and wave keys against the range graph of the same run.
void checkAgainstGraph(std::map<std::string, std::string>& j, const Graph& g) {
  const double bounds[] = {0.0, kBuoyStart, kBuoyEnd, 1400.0};
  for (int k = 0; k < 3; ++k) {
    const std::string key = "section" + std::to_string(k);
    double t = -1e300, ts = NAN, c = -1e300, cs = NAN;
    for (size_t i = 0; i < g.s.size(); ++i)
      if (g.s[i] >= bounds[k] && (g.s[i] < bounds[k + 1] || k == 2) && g.t_max[i] > t) t = g.t_max[i], ts = g.s[i];
    for (size_t i = 0; i < g.s_joint.size(); ++i)
      if (g.s_joint[i] >= bounds[k] && g.s_joint[i] < bounds[k + 1] && g.k_max[i] > c)
        c = g.k_max[i], cs = g.s_joint[i];
    // The graph's CSV and the summary print the same doubles at %.9g.
    EXPECT_DOUBLE_EQ(num(j, key + "_tension_max"), t) << key;
    EXPECT_DOUBLE_EQ(num(j, key + "_tension_max_s"), ts) << key;
    EXPECT_DOUBLE_EQ(num(j, key + "_curvature_max"), c) << key;
    EXPECT_DOUBLE_EQ(num(j, key + "_curvature_max_s"), cs) << key;
    EXPECT_GE(num(j, key + "_tension_max_s"), bounds[k]);
    EXPECT_LE(num(j, key + "_tension_max_s"), bounds[k + 1]);
  }
  // The line's largest tension is its sections' largest.
  EXPECT_DOUBLE_EQ(
      std::max({num(j, "section0_tension_max"), num(j, "section1_tension_max"), num(j, "section2_tension_max")}),
      *std::max_element(g.t_max.begin(), g.t_max.end()));
  // Sag and hog: the bends of the points A_i, the graph's clearance at the rfes' middles (the middles of the
  // chords A_i A_i+1; level seabed: z = clearance + level). A point and the next chord middles differ in height by
  // at most d/2 |slope| + d² κ / 8; at a bend's extreme the slope is within d κ of level: a bound of d² κ_max.
  const double sag = num(j, "sag_z"), hog = num(j, "hog_z");
  const double tol = kD * kD * num(j, "curvature_max");
  double low = 1e300, high = -1e300;
  for (size_t i = 0; i < g.s.size(); ++i) {
    if (g.s[i] < kBuoyStart) low = std::min(low, g.c_min[i] + kSeabed);
    if (g.s[i] > num(j, "sag_s")) high = std::max(high, g.c_max[i] + kSeabed);
  }
  EXPECT_NEAR(sag, low, tol);
  EXPECT_NEAR(hog, high, tol);
}

}  // namespace

// At t = 0 (--duration 0): three sections' extremes as the range graph has them; the hog above the sag and inside
// the buoyancy section, the sag before it.
TEST(CliSectionExtremes, LazyWaveAtRest) {
  const std::string path = tempPath("lazy_wave_range.csv");
  const CliRun r = runCli("--scene " + kLazyWave + " --duration 0 --quiet --summary --range-graph " + path);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = summary(r);
  ASSERT_TRUE(j.count("sag_z") && j.count("hog_z")) << r.out;
  EXPECT_GT(num(j, "hog_z"), num(j, "sag_z"));
  EXPECT_LT(num(j, "sag_s"), kBuoyStart);
  EXPECT_GE(num(j, "hog_s"), kBuoyStart);
  EXPECT_LT(num(j, "hog_s"), kBuoyEnd);
  EXPECT_GT(num(j, "sag_z"), kSeabed) << "the sag bend is off the seabed";
  EXPECT_FALSE(j.count("section3_tension_max"));
  // The top's tension is the first section's largest (the line hangs from it); the touch-down's curvature is the
  // third's.
  EXPECT_LT(num(j, "section0_tension_max_s"), 2.0 * kD);
  checkAgainstGraph(j, readGraph(path));
  std::printf("sag %.6g m at %.6g m, hog %.6g m at %.6g m\n", num(j, "sag_z"), num(j, "sag_s"), num(j, "hog_z"),
              num(j, "hog_s"));
}

// Over a short run (10 steps of the heave): the envelopes widen, so the sag can only go down and the hog up from
// their values at rest; still consistent with the run's range graph.
TEST(CliSectionExtremes, LazyWaveOverARun) {
  const CliRun r0 = runCli("--scene " + kLazyWave + " --duration 0 --quiet --summary");
  ASSERT_EQ(r0.code, 0) << r0.err;
  auto j0 = summary(r0);
  const std::string path = tempPath("lazy_wave_range_run.csv");
  const CliRun r = runCli("--scene " + kLazyWave + " --duration 0.5 --quiet --summary --range-graph " + path);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = summary(r);
  EXPECT_LE(num(j, "sag_z"), num(j0, "sag_z"));
  EXPECT_GE(num(j, "hog_z"), num(j0, "hog_z"));
  for (int k = 0; k < 3; ++k)
    EXPECT_GE(num(j, "section" + std::to_string(k) + "_tension_max"),
              num(j0, "section" + std::to_string(k) + "_tension_max"));
  checkAgainstGraph(j, readGraph(path));
}

// A uniform line has no section keys.
TEST(CliSectionExtremes, UniformLineHasNone) {
  const CliRun r = runCli("--scene " + kChain + " --duration 0 --quiet --summary");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = summary(r);
  EXPECT_FALSE(j.count("section0_tension_max"));
  EXPECT_FALSE(j.count("sag_z"));
}
