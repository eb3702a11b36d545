// ROS time as the integration loop sees it, and the loop's pacing on wall time.
// RosClockWatch: did ROS time advance since the last look, go backwards (a looping bag, a restarted
// simulator) or stay still for ~clock_timeout of wall time (stalled: /use_sim_time without /clock)?
// Schedule: something due at a fixed rate of ROS time. LoopPacer: the loop's wake-ups per wall second.
#pragma once
#include <chrono>
#include <string>

#include <ros/time.h>

namespace riser_sim_ros {

using WallClock = std::chrono::steady_clock;

inline double seconds(WallClock::duration d) { return std::chrono::duration<double>(d).count(); }

class RosClockWatch {
 public:
  struct Look {
    bool advanced = false;     // ROS time moved (forward or back): there is something to step
    bool jumped_back = false;  // it went backwards: the simulated past is gone
    bool resumed = false;      // it advanced again after a stall
  };
  // `timeout`: wall seconds without progress before the clock counts as stalled; `name` starts log lines.
  RosClockWatch(double timeout, std::string name);
  Look look(const ros::Time& now, WallClock::time_point wall);
  bool stalled() const { return stalled_; }
  double stillFor(WallClock::time_point wall) const { return seconds(wall - last_advance_); }
  long jumps() const { return jumps_; }
  const std::string& lastJump() const { return last_jump_; }  // the last backwards jump, for /diagnostics

 private:
  double timeout_;
  std::string name_;
  ros::Time last_now_;
  WallClock::time_point last_advance_;
  bool stalled_ = false;
  long jumps_ = 0;
  std::string last_jump_;
};

struct Schedule {
  double period = 0.0;  // [s], 0 = off
  ros::Time next;
  // True when `now` reached `next` (then moves on by one period, or past now when it fell behind).
  bool due(const ros::Time& now);
  void restart(const ros::Time& now) { next = now; }
};

inline double periodOf(double hz) { return hz > 0.0 ? 1.0 / hz : 0.0; }

class LoopPacer {
 public:
  explicit LoopPacer(double rate);
  void wait();  // until the next wake-up; skips the missed ones

 private:
  WallClock::duration period_;
  WallClock::time_point next_;
};

}  // namespace riser_sim_ros
