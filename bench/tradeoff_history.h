// Force histories of the speed/accuracy sweep: what a run records on a fixed time grid, shared with its
// reference, and the errors of one history against another.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

namespace tradeoff {

// Grid of the force histories: t_k = k kHistoryDt, k = 0 .. round(duration / kHistoryDt) [s]. A run whose
// steps do not land on t_k is interpolated linearly between the steps around it.
constexpr double kHistoryDt = 0.1;

inline int historySamples(double duration) { return int(std::lround(duration / kHistoryDt)) + 1; }

// Errors of a history T against the reference history Tref (same grid):
// rms = rms_k(T_k - Tref_k) / rms_k(Tref_k), max = max_k |T_k - Tref_k| / max_k |Tref_k|.
struct HistoryError {
  double rms = NAN, max = NAN;
};

inline HistoryError historyError(const std::vector<double>& T, const std::vector<double>& Tref) {
  HistoryError e;
  if (T.size() != Tref.size() || T.empty()) return e;
  double d2 = 0.0, r2 = 0.0, dmax = 0.0, rmax = 0.0;
  for (size_t k = 0; k < T.size(); ++k) {
    const double d = T[k] - Tref[k];
    d2 += d * d;
    r2 += Tref[k] * Tref[k];
    dmax = std::max(dmax, std::abs(d));
    rmax = std::max(rmax, std::abs(Tref[k]));
  }
  e.rms = std::sqrt(d2 / r2);  // the 1/K of both RMS cancel
  e.max = dmax / rmax;
  return e;
}

}  // namespace tradeoff
