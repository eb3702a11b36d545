// rosrun finds the package's programs once and quietly: the workspace lives inside the repository, so
// a package tree that reached it made rosrun's `find -L` report a file-system loop and duplicates.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

namespace {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

Result run(const std::string& command) {
  Result r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t got;
  while ((got = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), got);
  r.status = pclose(pipe);
  return r;
}

TEST(Rosrun, FindsTheCliOnceWithoutWarnings) {
  const Result r = run("rosrun riser_sim riser_sim_cli --help");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("File system loop"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("non-unique"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--scene"), std::string::npos) << "not the CLI's help:\n" << r.output;
}

TEST(Rosrun, PackagePathHoldsNoWorkspace) {
  const Result r = run("find -L \"$(rospack find riser_sim)\" -name riser_sim_cli -type f");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("loop"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("riser_sim_cli"), std::string::npos) << "a built program inside the package tree:\n"
                                                               << r.output;
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
