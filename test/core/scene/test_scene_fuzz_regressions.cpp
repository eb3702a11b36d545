// Replays the scene fuzzer's inputs (test/fuzz/regressions: minimised crashers and findings;
// test/fuzz/seeds: hand-made edge cases) through the same path as the fuzzer (test/fuzz/scene_exercise.h):
// each one either builds and steps with finite outputs or is rejected with an error naming its key.
// Every file states its outcome in a first-line comment, checked here:
//   # expect: built                 builds and steps (divergence allowed: the run reports it)
//   # expect: parsed                valid, larger than the fuzzer builds
//   # expect: <message prefix>      rejected, e.g. "line.elements: must be <= 2000"
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene_exercise.h"

namespace fs = std::filesystem;
using riser_sim::fuzz::Outcome;

namespace {

std::vector<fs::path> inputs(const std::string& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(std::string(RISER_SIM_SOURCE_DIR) + "/" + dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The "# expect: ..." line, or "" if there is none.
std::string expectation(const std::string& data) {
  const std::string tag = "# expect: ";
  std::istringstream lines(data);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(tag, 0) == 0) return line.substr(tag.size());
  return "";
}

void replay(const std::string& dir) {
  const std::vector<fs::path> files = inputs(dir);
  ASSERT_FALSE(files.empty()) << dir;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const std::string data = readFile(f);
    const std::string expect = expectation(data);
    ASSERT_FALSE(expect.empty()) << "no '# expect: ...' line";
    const Outcome out = riser_sim::fuzz::exercise(data);
    EXPECT_EQ(out.defect, "") << out.message;
    if (expect == "built") {
      EXPECT_EQ(out.kind, Outcome::Kind::kBuilt) << out.message;
    } else if (expect == "parsed") {
      EXPECT_EQ(out.kind, Outcome::Kind::kParsed) << out.message;
    } else {
      EXPECT_NE(out.kind, Outcome::Kind::kBuilt) << out.message;
      EXPECT_EQ(out.message.rfind(expect, 0), 0u) << out.message;
    }
  }
}

}  // namespace

TEST(SceneFuzzRegressions, CrashersAndFindings) { replay("test/fuzz/regressions"); }

TEST(SceneFuzzRegressions, HandMadeEdgeCases) { replay("test/fuzz/seeds"); }

// The shipped scenes are fuzz seeds too: none breaks a rule (large ones are parsed only).
TEST(SceneFuzzRegressions, ShippedScenes) {
  for (const char* dir : {"config/scenes", "test/ros/scenes"})
    for (const fs::path& f : inputs(dir)) {
      SCOPED_TRACE(f.string());
      const Outcome out = riser_sim::fuzz::exercise(readFile(f));
      EXPECT_EQ(out.defect, "") << out.message;
      EXPECT_TRUE(out.kind == Outcome::Kind::kBuilt || out.kind == Outcome::Kind::kParsed) << out.message;
    }
}
