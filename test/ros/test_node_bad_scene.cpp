// Runs the node binary (RISER_SIM_NODE_BIN) under each prepared name and checks its exit code and
// its message. No master interaction beyond the parameters node_bad_scene.test sets.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include <ros/ros.h>

namespace {

struct Run {
  int code = -1;
  std::string output;
};

Run runNode(const std::string& name) {
  // `timeout` guards against a node that would not exit (then code 124; a valid node exits within a second).
  const std::string cmd = std::string("timeout 10 ") + RISER_SIM_NODE_BIN + " __name:=" + name + " 2>&1";
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[512];
  while (fgets(buf, sizeof(buf), p)) r.output += buf;
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

void expectFatal(const std::string& name, const std::string& message) {
  const Run r = runNode(name);
  EXPECT_EQ(r.code, 2) << name << ":\n" << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << name << ": expected '" << message << "' in:\n" << r.output;
  EXPECT_NE(r.output.find("FATAL"), std::string::npos) << r.output;
}

TEST(NodeBadScene, SceneErrorsNameTheKey) {
  expectFatal("bad_elements", "~scene/line/elements: must be >= 1, got 0");
  expectFatal("bad_key", "~scene/line/lenght: unknown key (did you mean 'length'?)");
  expectFatal("bad_dt", "~scene/solver/dt");
  expectFatal("bad_type", "~scene/line/mass_per_length: expected a number");
  // A 3D scene with what the 3D core cannot run yet is refused at start, naming the key.
  expectFatal("spatial_unsupported", "~scene/solver/formulation: 'recursive' is planar");
}

TEST(NodeBadScene, MissingSceneIsFatal) { expectFatal("no_scene_here", "~scene: missing"); }

TEST(NodeBadScene, NodeParameterErrorsNameTheParameter) {
  expectFatal("bad_rate", "~rates/tension: must be >= 0 (0 = off), got -1");
  expectFatal("bad_input", "~vessel_input: unknown value 'gps' (accepted: pose, odom, tf)");
  expectFatal("bad_offset", "~hangoff_offset: expected [x, y, z]");
  // A point on the vessel, not 1e20 m off it (that ran and diverged, "reduce solver.dt").
  expectFatal("huge_offset", "~hangoff_offset: |[1e+20, 0, 0]| = 1e+20 m is beyond 1000 m");
  expectFatal("bad_motion", "~motion/stop_time: must be > 0");
  expectFatal("bad_wrench_frame", "~wrench_frame: unknown value 'vessel' (accepted: fixed, body)");
  expectFatal("planar_body_wrench", "~wrench_frame: body needs a 3D scene (space: spatial)");
}

// A misspelt private parameter is fatal like a misspelt scene key (it would be ignored silently).
TEST(NodeBadScene, UnknownParametersAreFatal) {
  expectFatal("misspelt_rate",
              "~rates/tensoin: unknown parameter (did you mean 'tension'?); accepted under "
              "~rates/: tension, state, wrench, tf, markers, range_graph, diagnostics");
  expectFatal("misspelt_loop_rate", "~loop_rat: unknown parameter (did you mean 'loop_rate'?)");
}

// Numbers in the forms the scene loader accepts (YAML 1.2: 1e8), also when rosparam (YAML 1.1) hands
// them over as strings; what is not a number still fails naming the parameter.
TEST(NodeBadScene, NumbersAsInSceneFiles) {
  const auto r = runNode("yaml11_floats");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("~max_pose_age: must be > 0, got -1"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("max_position"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("hangoff_offset"), std::string::npos) << r.output;
  expectFatal("not_a_number", "~max_position: expected a number, got '1e8x'");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_bad_scene");
  return RUN_ALL_TESTS();
}
