// riser_sim_cli --range-graph: the min/max envelopes along the line over every step (range_graph.h), its
// summary keys, and an output path that cannot take it.
#include <gtest/gtest.h>

#include "cli_test_util.h"

using namespace cli_test;

namespace {

// The range graph's rows; the last row's joint columns are empty (read as NaN).
std::vector<std::vector<double>> rangeRows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ls(line + ",");  // a trailing empty field is read too
    std::string field;
    while (std::getline(ls, field, ',')) {
      char* end = nullptr;
      const double v = field.empty() ? NAN : std::strtod(field.c_str(), &end);
      EXPECT_TRUE(field.empty() || (*end == '\0' && std::isfinite(v))) << "bad field '" << field << "' in " << line;
      row.push_back(v);
    }
    rows.push_back(row);
  }
  return rows;
}

int column(const std::string& header, const std::string& name) {
  std::stringstream hs(header);
  std::string h;
  for (int k = 0; std::getline(hs, h, ','); ++k)
    if (h == name) return k;
  ADD_FAILURE() << name << " not in " << header;
  return 0;
}

}  // namespace

// n + 1 rows over the hanging chain's swing (n = 8); every CSV row (every output step) of a probed rfe lies
// inside its envelope, which is taken every step; the summary names the extremes' stations.
TEST(CliRangeGraph, EnvelopesHoldEveryRowOfTheRun) {
  const std::string path = tempPath("range.csv"), csv = tempPath("series.csv");
  const CliRun r = runCli("--scene " + kChain + " --duration 0.5 --quiet --summary --range-graph " + path + " --csv " +
                          csv + " --output-dt 0.01 --probe-rfe 3");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header, series_header;
  const auto rows = rangeRows(readFile(path), header);
  const auto series = csvRows(readFile(csv), series_header);
  EXPECT_EQ(header, "s,tension_min,tension_max,s_joint,moment_min,moment_max,curvature_min,curvature_max");
  ASSERT_EQ(rows.size(), 9u);
  ASSERT_GT(series.size(), 40u);
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u);
    EXPECT_NEAR(rows[i][0],
                i == 0                 ? 0.3125
                : i + 1 == rows.size() ? 9.6875
                                       : 1.25 * i,
                1e-12)
        << "rfe middles (half-length ends)";
    EXPECT_LE(rows[i][1], rows[i][2]);
    if (i + 1 < rows.size()) {
      EXPECT_NEAR(rows[i][3], 0.625 + 1.25 * i, 1e-12);
      EXPECT_LE(rows[i][6], rows[i][7]);
    } else {
      EXPECT_TRUE(std::isnan(rows[i][3]) && std::isnan(rows[i][7])) << "no joint past the end";
    }
  }
  const int t3 = column(series_header, "tension_rfe3");
  double lo = 1e300, hi = -1e300;
  for (const auto& row : series) {
    lo = std::min(lo, row[t3]);
    hi = std::max(hi, row[t3]);
  }
  EXPECT_LE(rows[3][1], lo);
  EXPECT_GE(rows[3][2], hi);
  EXPECT_LT(rows[3][1], rows[3][2]) << "the chain swings: its tension changes";
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
  double t_max = -1e300, s_at = NAN;
  for (const auto& row : rows)
    if (row[2] > t_max) t_max = row[2], s_at = row[0];
  EXPECT_DOUBLE_EQ(std::stod(j["tension_max_s"]), s_at);
  EXPECT_GT(std::stod(j["curvature_max"]), 0.0);
  EXPECT_EQ(j.count("touchdown_s_min"), 0u) << "no seabed";
}

// The statics alone (--duration 0): one sample, min == max; with a seabed, the clearance columns and the
// touch-down keys (demo_riser_3d rests its last ~30 m on the seabed).
TEST(CliRangeGraph, StaticsAloneAndSeabed) {
  const std::string path = tempPath("range_bed.csv");
  const CliRun r =
      runCli("--scene " + kScenes + "demo_riser_3d.yaml --duration 0 --quiet --summary --range-graph " + path);
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto rows = rangeRows(readFile(path), header);
  EXPECT_EQ(header,
            "s,tension_min,tension_max,clearance_min,clearance_max,s_joint,moment_min,moment_max,curvature_min,"
            "curvature_max");
  ASSERT_EQ(rows.size(), 31u);  // line.elements 30
  for (size_t i = 0; i < rows.size(); ++i)
    for (const size_t c : {1, 3, 6, 8})  // tension, clearance, moment, curvature: min, max
      if (c < 5 || i + 1 < rows.size()) EXPECT_EQ(rows[i][c], rows[i][c + 1]) << "row " << i << ", column " << c;
  EXPECT_GT(rows.front()[3], 90.0) << "the hang-off ~100 m above the seabed";
  EXPECT_LT(std::abs(rows.back()[3]), 0.05) << "the end rests on the seabed";
  std::map<std::string, std::string> j;
  ASSERT_TRUE(parseFlatJson(r.out, j)) << r.out;
  EXPECT_EQ(j["touchdown_s_min"], j["touchdown_s_max"]);
  EXPECT_GT(std::stod(j["touchdown_s_min"]), 100.0);
  EXPECT_LT(std::stod(j["touchdown_s_min"]), 150.0);
}

// As --csv: a directory fails to open (exit 2); /proc/version opens for root and fails at the write (exit 4)
// or fails to open (exit 2); /dev/full fails at the write (exit 4); each names the option and the file.
TEST(CliRangeGraph, UnwritablePathFails) {
  for (const std::string& path : std::vector<std::string>{"/proc/version", testing::TempDir(), "/dev/full"}) {
    SCOPED_TRACE(path);
    const CliRun r = runCli("--scene " + kChain + " --duration 0.01 --quiet --range-graph " + path);
    EXPECT_TRUE(path == "/dev/full" ? r.code == 4 : (r.code == 2 || r.code == 4)) << r.code << ": " << r.err;
    EXPECT_NE(r.err.find("--range-graph"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'" + path + "'"), std::string::npos) << r.err;
  }
  const CliRun r = runCli("--scene " + kChain + " --range-graph=");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--range-graph: empty file name"), std::string::npos) << r.err;
}
