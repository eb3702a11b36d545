// node_bad_tf.test: the node (RISER_SIM_NODE_BIN, started here with its output to a file) on tf input.
// 1 s of NaN translations and 1 s of zero quaternions for the vessel frame at 50 Hz, between good
// transforms. Before: tf2 printed two stderr lines per message (~200 here) and /diagnostics said 0
// rejected poses.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <fstream>

#include <tf2_msgs/TFMessage.h>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

const std::string kName = "bad_tf_node";

int countLines(const std::string& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) n += line.find(text) != std::string::npos;
  return n;
}

// Ends the node (SIGINT, SIGKILL after 10 s) however the test leaves.
struct NodeProcess {
  pid_t pid = -1;
  ~NodeProcess() { stop(); }
  void stop() {
    if (pid <= 0) return;
    kill(pid, SIGINT);
    int status = 0;
    const bool ended = waitFor([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 10.0);
    if (!ended) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
    }
    pid = -1;
  }
};

TEST(NodeBadTf, RejectedCountedAndLogThrottled) {
  const std::string out = "/tmp/node_bad_tf_" + std::to_string(getpid()) + ".log";
  // posix_spawn, not fork: this process has threads (a child of fork may only make async-signal-safe
  // calls; building strings there can deadlock on malloc's lock).
  const std::string name_arg = "__name:=" + kName;
  char* const argv[] = {const_cast<char*>(RISER_SIM_NODE_BIN), const_cast<char*>(name_arg.c_str()), nullptr};
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  NodeProcess node;
  const int spawned = posix_spawn(&node.pid, RISER_SIM_NODE_BIN, &files, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&files);
  ASSERT_EQ(spawned, 0);

  ros::NodeHandle nh;
  ros::Publisher tf_pub = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  Recorder<riser_sim::Tension> tension(nh, kName + "/tension");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  enum Phase { kGood, kNan, kZeroQuaternion };
  std::atomic<int> phase{kGood}, bad_sent{0}, ticks{0};
  ros::WallTimer timer = nh.createWallTimer(ros::WallDuration(0.02), [&](const ros::WallTimerEvent&) {
    const int p = phase;  // read once: a message built in one phase and counted in another was a flake
    tf2_msgs::TFMessage m;
    m.transforms.resize(1);
    geometry_msgs::TransformStamped& t = m.transforms[0];
    t.header.stamp = ros::Time::now();
    t.header.frame_id = "world";
    t.child_frame_id = "vessel";
    t.transform.translation.x = p == kNan ? NAN : 2.0;
    t.transform.rotation.w = p == kZeroQuaternion ? 0.0 : 1.0;
    tf_pub.publish(m);
    if (p != kGood) ++bad_sent;
    ++ticks;
  });
  ASSERT_TRUE(tension.waitCount(1, 30.0)) << "the node did not start on good tf";

  // 1 s of each kind of bad transform, on wall time (the node's warnings are throttled on wall time).
  auto rejected = [&] {
    return diag.count() == 0 ? -1L : std::atol(diagValue(diag.last(), kName, "poses rejected").c_str());
  };
  ASSERT_TRUE(waitFor([&] { return rejected() == 0; }, 10.0));
  const ros::WallTime t0 = ros::WallTime::now();
  phase = kNan;
  ASSERT_TRUE(waitFor([&] { return ros::WallTime::now() - t0 > ros::WallDuration(1.0); }, 5.0));
  phase = kZeroQuaternion;
  ASSERT_TRUE(waitFor([&] { return ros::WallTime::now() - t0 > ros::WallDuration(2.0); }, 5.0));
  phase = kGood;
  const int tick = ticks;  // a tick in flight may still have read a bad phase: two more, and it has counted
  ASSERT_TRUE(waitFor([&] { return ticks >= tick + 2; }, 5.0));
  const int sent = bad_sent;
  EXPECT_GE(sent, 80);  // 50 Hz for 2 s, whatever the machine's load did to the timer

  // Every bad transform is a rejected pose (/tf's queue holds 100: none is dropped at 50 Hz).
  EXPECT_TRUE(waitFor([&] { return rejected() == sent; }, 10.0))
      << "poses rejected " << rejected() << ", sent " << sent;
  const std::string last = diagValue(diag.last(), kName, "last rejection");
  EXPECT_NE(last.find("zero quaternion"), std::string::npos) << last;
  const size_t before = tension.count();
  EXPECT_TRUE(tension.waitCount(before + 5, 10.0)) << "the node stopped publishing";
  timer.stop();
  node.stop();  // its output is complete

  // tf2's own errors never printed; the node's warnings at most one per 2 s (+1: the first).
  EXPECT_EQ(countLines(out, "TF_NAN_INPUT"), 0);
  EXPECT_EQ(countLines(out, "TF_DENORMALIZED_QUATERNION"), 0);
  const int warnings = countLines(out, "vessel pose from tf");
  EXPECT_GE(warnings, 1);
  EXPECT_LE(warnings, 2);
  std::printf("bad transforms sent %d, rejected %ld, node warnings %d, output lines with TF_: %d\n", sent, rejected(),
              warnings, countLines(out, "TF_"));
  std::remove(out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_bad_tf");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
