#include "riser_sim_ros/range_window.h"

#include <algorithm>
#include <cmath>

namespace riser_sim_ros {

namespace {
bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// msg's min/max over the live graphs (a live block's graph has at least one sample).
void merge(std::vector<double>& lo, std::vector<double>& hi, const riser_sim::Envelope& e, bool first) {
  for (size_t i = 0; i < lo.size(); ++i) {
    lo[i] = first ? e.min[i] : std::min(lo[i], e.min[i]);
    hi[i] = first ? e.max[i] : std::max(hi[i], e.max[i]);
  }
}
}  // namespace

RangeWindow::RangeWindow(const riser_sim::RunOutputs& first, const riser_sim::SeabedPlane& seabed, double window,
                         const std::string& fixed_frame)
    : graphs_(kBlocks, riser_sim::RangeGraph(first, seabed)),
      blocks_(kBlocks),
      t0_(first.t),
      block_length_(window / kBlocks) {
  const riser_sim::RangeGraph& g = graphs_[0];
  msg.header.frame_id = fixed_frame;
  msg.window = window;
  msg.arc_length = g.stations();
  msg.joint_arc_length = g.jointStations();
  const size_t nb = g.stations().size(), nj = g.jointStations().size();
  msg.tension_min.resize(nb);
  msg.tension_max.resize(nb);
  msg.moment_min.resize(nj);
  msg.moment_max.resize(nj);
  msg.curvature_min.resize(nj);
  msg.curvature_max.resize(nj);
  msg.clearance_min.resize(g.hasSeabed() ? nb : 0);
  msg.clearance_max.resize(g.hasSeabed() ? nb : 0);
  Block& b = blocks_[0];
  b.index = 0;
  b.t_first = b.t_last = first.t;
  b.top_min = b.top_max = first.top_tension;
}

void RangeWindow::add(const riser_sim::RunOutputs& o, double shift) {
  if (cleared_) {  // a new window from o: every block empty, o the first sample of block `latest_`
    for (Block& b : blocks_) b.index = -1;
    cleared_ = false;
  }
  const long index = std::max(latest_, static_cast<long>(std::floor((o.t - t0_) / block_length_)));
  const int slot = static_cast<int>(index % kBlocks);
  Block& b = blocks_[slot];
  if (b.index != index) {
    graphs_[slot].restart(o);
    b.index = index;
    b.t_first = o.t + shift;
    b.top_min = b.top_max = o.top_tension;
  } else {
    graphs_[slot].add(o);
    b.top_min = std::min(b.top_min, o.top_tension);
    b.top_max = std::max(b.top_max, o.top_tension);
  }
  b.t_last = o.t + shift;
  latest_ = index;
}

bool RangeWindow::fill(const ros::Time& stamp) {
  bool any = false;
  long samples = 0, td_samples = 0;
  double t_first = 0.0, t_last = 0.0, td_min = 0.0, td_max = 0.0;
  for (int k = 0; k < kBlocks; ++k) {
    const Block& b = blocks_[k];
    if (b.index < 0 || b.index <= latest_ - kBlocks) continue;  // empty, or older than the window
    const riser_sim::RangeGraph& g = graphs_[k];
    merge(msg.tension_min, msg.tension_max, g.tension(), !any);
    merge(msg.moment_min, msg.moment_max, g.moment(), !any);
    merge(msg.curvature_min, msg.curvature_max, g.curvature(), !any);
    if (g.hasSeabed()) merge(msg.clearance_min, msg.clearance_max, g.clearance(), !any);
    msg.top_tension_min = !any ? b.top_min : std::min(msg.top_tension_min, b.top_min);
    msg.top_tension_max = !any ? b.top_max : std::max(msg.top_tension_max, b.top_max);
    t_first = !any ? b.t_first : std::min(t_first, b.t_first);
    t_last = !any ? b.t_last : std::max(t_last, b.t_last);
    samples += g.samples();
    if (g.touchdownSamples() > 0) {
      td_min = td_samples == 0 ? g.touchdownMin() : std::min(td_min, g.touchdownMin());
      td_max = td_samples == 0 ? g.touchdownMax() : std::max(td_max, g.touchdownMax());
      td_samples += g.touchdownSamples();
    }
    any = true;
  }
  if (!any) return false;  // cleared, no sample since
  msg.header.stamp = stamp;
  msg.window_start = stamp - ros::Duration(t_last - t_first);
  msg.samples = static_cast<uint32_t>(samples);
  msg.touchdown_samples = static_cast<uint32_t>(td_samples);
  msg.touchdown_min = td_min;
  msg.touchdown_max = td_max;
  return std::isfinite(msg.top_tension_min) && std::isfinite(msg.top_tension_max) && std::isfinite(td_min) &&
         std::isfinite(td_max) && finite(msg.tension_min) && finite(msg.tension_max) && finite(msg.moment_min) &&
         finite(msg.moment_max) && finite(msg.curvature_min) && finite(msg.curvature_max) &&
         finite(msg.clearance_min) && finite(msg.clearance_max);
}

}  // namespace riser_sim_ros
