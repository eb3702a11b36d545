#include "riser_sim/force_noise.h"

#include <algorithm>

namespace riser_sim {

void ForceNoiseMonitor::add(double top_tension, double max_axial, double dt) {
  if (!std::isfinite(top_tension) || !std::isfinite(max_axial)) return;  // the divergence check reports it
  if (n_ >= 2) {
    const double dtop = top_tension - 2.0 * top_[1] + top_[0];
    const double da = max_axial - 2.0 * ax_[1] + ax_[0];
    sum_.d2_top += dtop * dtop;
    sum_.t2_top += top_[1] * top_[1];
    sum_.d2_ax += da * da;
    sum_.t2_ax += ax_[1] * ax_[1];
    const double keep = std::exp(-dt / kWindow);
    for (double* s : {&recent_.d2_top, &recent_.t2_top, &recent_.d2_ax, &recent_.t2_ax}) *s *= keep;
    recent_.d2_top += dtop * dtop;
    recent_.t2_top += top_[1] * top_[1];
    recent_.d2_ax += da * da;
    recent_.t2_ax += ax_[1] * ax_[1];
  }
  top_[0] = top_[1];
  top_[1] = top_tension;
  ax_[0] = ax_[1];
  ax_[1] = max_axial;
  ++n_;
}

ForceNoise ForceNoiseMonitor::estimate(const Sums& s) {
  // √(Σd²/6) / √(ΣT²): the count cancels. A force that is zero throughout has no relative noise.
  const auto rel = [](double d2, double t2) { return t2 > 0.0 ? std::sqrt(d2 / (6.0 * t2)) : 0.0; };
  return {rel(s.d2_top, s.t2_top), rel(s.d2_ax, s.t2_ax)};
}

}  // namespace riser_sim
