// Bad topic data: a driver publishes the vessel path interleaved with every kind of bad pose, in
// bursts and with a silence, on wall-time phases; the test then checks the node's outputs over the run.
#include <rosgraph_msgs/Log.h>
#include <tf2_msgs/TFMessage.h>

#include <atomic>
#include <set>

#include "node_test_util.h"

using namespace riser_sim_test;

namespace {

// Vessel path [m] at t [s]: surge 2 m / 8 s, heave 0.5 m / 5 s; 20 poses per second when good.
constexpr double kSurge = 2.0, kSurgePeriod = 8.0, kHeave = 0.5, kHeavePeriod = 5.0, kRate = 20.0;
double surge(double t) { return kSurge * std::sin(2 * M_PI * t / kSurgePeriod); }
double heave(double t) { return kHeave * std::sin(2 * M_PI * t / kHeavePeriod); }
// As test_node_following: half of the vessel's largest motion in one pose period (3.9 cm); the top
// follows within it once the fit window (0.5 s) holds good samples again: 1 s allowed.
const double kTrackTol = 0.5 * kSurge * 2 * M_PI / kSurgePeriod / kRate;
constexpr double kSettle = 1.0;
constexpr double kBadX = 100.0;  // where every bad pose with a finite position puts the vessel

// Phases, in seconds of wall (= ROS) time since the driver started.
constexpr double kGoodUntil = 2.0;       // good poses at 20 Hz
constexpr double kMixedUntil = 5.0;      // bad poses of every kind at 200 Hz, nothing good
constexpr double kBadBurstUntil = 6.0;   // bad poses at 1 kHz
constexpr double kSilenceUntil = 8.0;    // nothing (2 s > pose_timeout 1 s)
constexpr double kGoodBurstUntil = 9.0;  // good poses at 1 kHz
constexpr double kJunkUntil = 11.0;      // good at 20 Hz, each followed by a repeated and an older stamp
constexpr double kEnd = 14.0;            // good at 20 Hz

class Driver {
 public:
  explicit Driver(ros::NodeHandle& nh) : pub_(nh.advertise<geometry_msgs::PoseStamped>("/vessel/pose", 1000)) {
    timer_ = nh.createWallTimer(
        ros::WallDuration(0.001), [this](const ros::WallTimerEvent&) { tick(); }, false, false);
  }
  void start() {
    t0_ = ros::Time::now();
    timer_.start();
  }
  bool connected() const { return pub_.getNumSubscribers() > 0; }
  bool done() const { return done_; }
  double t(const ros::Time& stamp) const { return (stamp - t0_).toSec(); }
  ros::Time at(double t) const { return t0_ + ros::Duration(t); }
  long bad() const { return bad_; }

 private:
  geometry_msgs::PoseStamped good(const ros::Time& stamp) const {
    geometry_msgs::PoseStamped m;
    m.header.stamp = stamp;
    m.header.frame_id = "world";
    const double t = (stamp - t0_).toSec();
    m.pose.position.x = surge(t);
    m.pose.position.z = heave(t);
    m.pose.orientation.w = 1.0;
    return m;
  }
  // Bad pose number k (cycling through the kinds).
  geometry_msgs::PoseStamped badPose(long k, const ros::Time& now) const {
    geometry_msgs::PoseStamped m = good(now);
    m.pose.position.x = kBadX;
    const double nan = std::nan(""), inf = INFINITY;
    switch (k % 16) {
      case 0: m.pose.position.x = nan; break;
      case 1: m.pose.position.z = inf; break;
      case 2: m.pose.position.y = -inf; break;
      case 3: m.pose.position.x = 1e30; break;
      case 4: m.pose.position.z = -1e30; break;
      case 5: m.pose.orientation.w = 0.0; break;  // zero quaternion
      case 6: m.pose.orientation.w = 2.0; break;  // norm 2
      case 7: m.pose.orientation.x = 0.3; break;  // norm 1.044
      case 8: m.pose.orientation.y = nan; break;
      case 9: m.pose.orientation.z = 1e30; break;
      case 10: m.header.frame_id = "map"; break;
      case 11: m.header.frame_id = ""; break;
      case 12: m.header.stamp = now + ros::Duration(1000.0); break;  // future
      case 13: m.header.stamp = now + ros::Duration(2.0); break;
      case 14: m.header.stamp = now - ros::Duration(100.0); break;  // past
      case 15: m.header.stamp = ros::Time(); break;                 // zero
    }
    return m;
  }
  // Publishes everything due up to now at `rate`; `make` builds each message.
  template <class F>
  void stream(double& next, double rate, double t, F make) {
    while (next <= t) {
      make(at(next));
      next += 1.0 / rate;
    }
  }
  void tick() {
    const ros::Time now = ros::Time::now();
    const double t = (now - t0_).toSec();
    if (t < kGoodUntil || (t >= kJunkUntil && t < kEnd)) {
      stream(next_good_, kRate, t, [&](const ros::Time& s) { pub_.publish(good(s)); });
    } else if (t < kMixedUntil) {
      stream(next_bad_, 200.0, t, [&](const ros::Time& s) { pub_.publish(badPose(bad_++, s)); });
    } else if (t < kBadBurstUntil) {
      stream(next_bad_, 1000.0, t, [&](const ros::Time& s) { pub_.publish(badPose(bad_++, s)); });
    } else if (t < kSilenceUntil) {
      next_good_ = next_bad_ = t;
    } else if (t < kGoodBurstUntil) {
      stream(next_good_, 1000.0, t, [&](const ros::Time& s) { pub_.publish(good(s)); });
    } else if (t < kJunkUntil) {
      stream(next_good_, kRate, t, [&](const ros::Time& s) {
        pub_.publish(good(s));
        geometry_msgs::PoseStamped repeat = good(s), older = good(s - ros::Duration(0.2));
        repeat.pose.position.x = older.pose.position.x = kBadX;
        pub_.publish(repeat);
        pub_.publish(older);
        bad_ += 2;
      });
    } else {
      done_ = true;
      timer_.stop();
    }
    if (t < kGoodUntil || t >= kSilenceUntil) next_bad_ = t;
    if (t >= kGoodUntil && t < kSilenceUntil) next_good_ = t;
  }

  ros::Publisher pub_;
  ros::WallTimer timer_;
  ros::Time t0_;
  double next_good_ = 0.0, next_bad_ = 0.0;
  std::atomic<long> bad_{0};
  std::atomic<bool> done_{false};
};

TEST(NodeHammer, KeepsRunningRatesNoNaNThrottledWarningsAndTracksAgain) {
  ros::NodeHandle nh;
  Driver vessel(nh);
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  Recorder<riser_sim::LineState> state(nh, "/riser_sim/state");
  Recorder<geometry_msgs::WrenchStamped> wrench(nh, "/riser_sim/top_wrench");
  Recorder<visualization_msgs::MarkerArray> markers(nh, "/riser_sim/markers");
  Recorder<tf2_msgs::TFMessage> tf(nh, "/tf");
  Recorder<diagnostic_msgs::DiagnosticArray> diag(nh, "/diagnostics");
  Recorder<rosgraph_msgs::Log> rosout(nh, "/rosout");
  ASSERT_TRUE(waitFor([&] { return vessel.connected(); }, 20.0));
  vessel.start();
  ASSERT_TRUE(tension.waitCount(1, 20.0)) << "the node did not start on the good poses";
  ASSERT_TRUE(waitFor([&] { return vessel.done(); }, 40.0)) << "driver did not finish";
  const ros::Time end = vessel.at(kEnd);

  // Alive and at its rate: tension at 20 Hz of ROS time over the bad phases and after. The schedule is
  // exact in ROS time; a message is lost only when the loop wakes more than a period late: 10 %.
  const ros::Time from = vessel.at(kGoodUntil), to = end;
  const double span = (to - from).toSec();
  const double rate = tension.countBetween(from, to) / span;
  std::printf("[hammer] tension %.2f Hz over %.1f s (bad poses sent %ld)\n", rate, span, vessel.bad());
  EXPECT_NEAR(rate, 20.0, 0.1 * 20.0);
  EXPECT_NEAR(state.countBetween(from, to) / span, 20.0, 0.1 * 20.0);
  ASSERT_TRUE(
      waitFor([&] { return !diag.all().empty() && diagValue(diag.last(), "riser_sim", "mode") == "running"; }, 5.0));
  EXPECT_TRUE(ros::service::exists("/riser_sim/reset", false));

  // Nothing non-finite, anywhere; and no bad pose ever reached the top (|x| <= 2 m path + 5 cm).
  for (const auto& m : tension.all()) ASSERT_TRUE(finite(m));
  for (const auto& m : wrench.all()) ASSERT_TRUE(finite(m));
  for (const auto& m : markers.all()) ASSERT_TRUE(finite(m));
  for (const auto& m : tf.all()) ASSERT_TRUE(finite(m));
  double worst_x = 0.0;
  for (const auto& m : state.all()) {
    ASSERT_TRUE(finite(m));
    worst_x = std::max(worst_x, std::abs(m.points.front().x));
  }
  EXPECT_LT(worst_x, kSurge + 0.05);

  // Tracking after the bad phases: from kSettle after good poses return.
  double worst = 0.0;
  int n = 0;
  for (const auto& m : state.all()) {
    const double t = vessel.t(m.header.stamp);
    if (t < kSilenceUntil + kSettle || t > kEnd) continue;
    const double e = std::hypot(m.points.front().x - surge(t), m.points.front().z - heave(t));
    worst = std::max(worst, e);
    ++n;
  }
  std::printf("[hammer] tracking after the bad phases: max error %.4f m over %d states (bound %.4f m)\n", worst, n,
              kTrackTol);
  EXPECT_GT(n, 60);
  EXPECT_LT(worst, kTrackTol);

  // Rejections counted; warnings rate-limited (one per 2 s of wall time at most) and informative.
  const long rejected = std::stol(diagValue(diag.last(), "riser_sim", "poses rejected"));
  int warnings = 0, counted = 0, silence_ended = 0;
  for (const auto& l : rosout.all()) {
    if (l.name != "/riser_sim") continue;
    if (l.msg.find("vessel pose from /vessel/pose ignored: ") != std::string::npos) {
      ++warnings;
      EXPECT_EQ(l.level, rosgraph_msgs::Log::WARN);
      counted += l.msg.find("more ignored since the last warning") != std::string::npos;
      std::printf("[hammer] warning: %s\n", l.msg.c_str());
    }
    silence_ended += l.msg.find("valid vessel poses again after") != std::string::npos;
  }
  const double bad_span = kJunkUntil - kGoodUntil;  // 9 s of bad input
  std::printf("[hammer] %ld poses rejected, %d warnings\n", rejected, warnings);
  EXPECT_GT(rejected, 1000);
  EXPECT_GE(warnings, 2);
  EXPECT_LE(warnings, bad_span / 2.0 + 2);
  EXPECT_GE(counted, 1);
  EXPECT_EQ(silence_ended, 1);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_hammer");
  ros::AsyncSpinner spinner(3);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
