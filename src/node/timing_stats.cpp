#include "riser_sim_ros/timing_stats.h"

#include <algorithm>
#include <cmath>

namespace riser_sim_ros {

TimingStats::TimingStats(int capacity) : ring_(std::max(capacity, 1)), scratch_(ring_.size()) {}

void TimingStats::add(double x) {
  ring_[head_] = x;
  head_ = (head_ + 1) % static_cast<int>(ring_.size());
  count_ = std::min(count_ + 1, static_cast<int>(ring_.size()));
}

void TimingStats::clear() { head_ = count_ = 0; }

double TimingStats::mean() const {
  if (count_ == 0) return 0.0;
  double s = 0.0;
  for (int i = 0; i < count_; ++i) s += ring_[i];
  return s / count_;
}

double TimingStats::max() const {
  if (count_ == 0) return 0.0;
  return *std::max_element(ring_.begin(), ring_.begin() + count_);
}

double TimingStats::percentile(double p) const {
  if (count_ == 0) return 0.0;
  std::copy(ring_.begin(), ring_.begin() + count_, scratch_.begin());
  const int k = std::clamp(static_cast<int>(std::ceil(p * count_)) - 1, 0, count_ - 1);
  std::nth_element(scratch_.begin(), scratch_.begin() + k, scratch_.begin() + count_);
  return scratch_[k];
}

}  // namespace riser_sim_ros
