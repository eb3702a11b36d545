// The range graph of the last `window` seconds of a run, for ~range_graph: the core's RangeGraph
// (riser_sim/run/range_graph.h) kept in kBlocks blocks of window / kBlocks seconds of run time each, in a ring
// sized at the start; a sample goes into the block of its time, and a block kBlocks blocks old is restarted
// from the sample that reuses it. The window is the current block and the kBlocks - 1 before it: it spans
// (1 - 1/kBlocks) window .. window. Allocates nothing after construction.
#pragma once
#include <string>
#include <vector>

#include <ros/time.h>

#include "riser_sim/RangeEnvelope.h"
#include "riser_sim/run/line_run.h"
#include "riser_sim/run/range_graph.h"

namespace riser_sim_ros {

class RangeWindow {
 public:
  static constexpr int kBlocks = 10;
  // Starts with `first` (its time first.t) as the first sample. window > 0 [s].
  RangeWindow(const riser_sim::RunOutputs& first, const riser_sim::SeabedPlane& seabed, double window,
              const std::string& fixed_frame);
  // One more sample at o.t (not before the last one's); `shift` [s]: the backlog the node dropped so far this
  // run (its stamps are the run time plus that), so that window_start is the first sample's stamp.
  void add(const riser_sim::RunOutputs& o, double shift = 0.0);
  // The next sample starts a new window.
  void clear() { cleared_ = true; }
  // Fills msg with the envelopes over the window, stamped `stamp` (the last sample's time on ROS time; the
  // window's start is that less the run time between them). False when a value is not finite (then msg is
  // not to be published).
  bool fill(const ros::Time& stamp);

  riser_sim::RangeEnvelope msg;

 private:
  struct Block {
    long index = -1;                      // floor((t - t0) / block length); -1: empty
    double t_first = 0.0, t_last = 0.0;   // run time plus shift of the first and last sample [s]
    double top_min = 0.0, top_max = 0.0;  // [N]
  };
  std::vector<riser_sim::RangeGraph> graphs_;
  std::vector<Block> blocks_;
  double t0_, block_length_;
  long latest_ = 0;  // index of the block of the last sample
  bool cleared_ = false;
};

}  // namespace riser_sim_ros
