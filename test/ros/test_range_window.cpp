// RangeWindow (range_window.h), no master: which samples its envelopes hold. A two-rfe line whose axial force
// and top tension equal the time, sampled every 0.125 s: the window (5 s in 10 blocks of 0.5 s; binary fractions, so
// the block of each sample is exact) at t holds the samples from the start of the block nine blocks before t's, so its
// minimum is that block's first sample and its maximum t; clear() starts the next window at the next sample.
#include <gtest/gtest.h>

#include <cmath>

#include "riser_sim_ros/range_window.h"

namespace riser_sim_ros {
namespace {

riser_sim::RunOutputs line(double t) {
  riser_sim::RunOutputs o;
  o.t = t;
  o.arc_length = {0.5, 1.5};
  o.axial_force = {t, 2.0 * t};
  o.top_tension = t;
  o.points.assign(3, riser_sim::Vec3::Zero());
  o.bending_moment = {-t};
  o.curvature = {0.1 * t};
  return o;
}

TEST(RangeWindow, HoldsTheLastTenBlocks) {
  const double window = 5.0, dt = 0.125;
  RangeWindow w(line(0.0), riser_sim::SeabedPlane{}, window, "world");
  const ros::Time origin(100.0);
  for (int k = 1; k <= 100; ++k) {
    const double t = k * dt;
    w.add(line(t));
    ASSERT_TRUE(w.fill(origin + ros::Duration(t)));
    // Block b = floor(t / 0.5); the window starts at block b - 9's start (or at 0), a sample time.
    const long b = static_cast<long>(std::floor(t / 0.5));
    const double first = std::max(0.0, (b - 9) * 0.5);
    SCOPED_TRACE(t);
    EXPECT_NEAR(w.msg.top_tension_min, first, 1e-9);
    EXPECT_NEAR(w.msg.top_tension_max, t, 1e-12);
    EXPECT_NEAR(w.msg.tension_min[1], 2.0 * first, 1e-9);
    EXPECT_NEAR(w.msg.tension_max[1], 2.0 * t, 1e-12);
    EXPECT_NEAR(w.msg.moment_min[0], -t, 1e-12);
    EXPECT_NEAR(w.msg.moment_max[0], -first, 1e-9);
    EXPECT_NEAR((w.msg.header.stamp - w.msg.window_start).toSec(), t - first, 1e-6);
    EXPECT_EQ(w.msg.samples, static_cast<uint32_t>(std::lround((t - first) / dt)) + 1);
    EXPECT_TRUE(w.msg.clearance_min.empty());
    EXPECT_EQ(w.msg.touchdown_samples, 0u);
  }
  w.clear();
  w.add(line(12.625));
  ASSERT_TRUE(w.fill(origin + ros::Duration(12.625)));
  EXPECT_EQ(w.msg.samples, 1u);
  EXPECT_EQ(w.msg.top_tension_min, 12.625);
  EXPECT_EQ(w.msg.window_start, w.msg.header.stamp);
}

}  // namespace
}  // namespace riser_sim_ros

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::Time::init();
  return RUN_ALL_TESTS();
}
