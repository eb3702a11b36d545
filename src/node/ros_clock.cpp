#include "riser_sim_ros/ros_clock.h"

#include <cstdio>
#include <thread>

#include <ros/console.h>

namespace riser_sim_ros {

RosClockWatch::RosClockWatch(double timeout, std::string name)
    : timeout_(timeout), name_(std::move(name)), last_advance_(WallClock::now()) {}

RosClockWatch::Look RosClockWatch::look(const ros::Time& now, WallClock::time_point wall) {
  Look l;
  if (!now.isZero() && !last_now_.isZero() && now < last_now_) {
    char buf[200];
    std::snprintf(buf, sizeof(buf), "ROS time jumped back by %.3f s (to %.3f s; bag loop or simulator restart?)",
                  (last_now_ - now).toSec(), now.toSec());
    last_jump_ = buf;
    ++jumps_;
    l.jumped_back = true;
  }
  l.advanced = !now.isZero() && now != last_now_;
  if (l.advanced) {
    if (stalled_) {
      ROS_INFO("%s: ROS time advances again after %.1f s (wall): simulation resumed", name_.c_str(), stillFor(wall));
      stalled_ = false;
      l.resumed = true;
    }
    last_advance_ = wall;
    last_now_ = now;
  } else if (!stalled_ && stillFor(wall) > timeout_) {
    stalled_ = true;
    ROS_WARN("%s: ROS time has not advanced for %.1f s of wall time (%s): simulation paused", name_.c_str(),
             stillFor(wall), now.isZero() ? "/use_sim_time set, no /clock yet" : "/clock stalled");
  }
  return l;
}

bool Schedule::due(const ros::Time& now) {
  if (period <= 0.0 || now < next) return false;
  next += ros::Duration(period);
  if (next <= now) next = now + ros::Duration(period);  // fell behind by more than a period: skip
  return true;
}

LoopPacer::LoopPacer(double rate)
    : period_(std::chrono::duration_cast<WallClock::duration>(std::chrono::duration<double>(1.0 / rate))),
      next_(WallClock::now()) {}

void LoopPacer::wait() {
  next_ += period_;
  const auto now = WallClock::now();
  if (next_ < now) next_ = now;
  std::this_thread::sleep_until(next_);
}

}  // namespace riser_sim_ros
