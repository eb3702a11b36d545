// Fixed-size record of durations (or any values) with mean, max and percentiles; allocates only in
// the constructor.
#pragma once
#include <vector>

namespace riser_sim_ros {

class TimingStats {
 public:
  explicit TimingStats(int capacity = 1024);
  void add(double x);
  void clear();
  int size() const { return count_; }
  double mean() const;
  double max() const;
  // p in [0, 1]: nearest-rank percentile of the recorded values (0 when empty).
  double percentile(double p) const;

 private:
  std::vector<double> ring_;
  mutable std::vector<double> scratch_;
  int head_ = 0, count_ = 0;
};

}  // namespace riser_sim_ros
