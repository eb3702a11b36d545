#include "riser_sim/run/force_noise.h"

#include <algorithm>
#include <sstream>

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

std::string forceNoiseWarning(const ForceNoise& e, double dt, IntegratorKind integrator, double rho_inf) {
  if (!(e.worst() > kForceNoiseWarning)) return "";
  std::ostringstream why;
  why.precision(2);
  why << "forces not resolved: step-to-step noise of " << 100.0 * e.top << " % in the top tension and "
      << 100.0 * e.max_axial << " % in the largest axial force (bound " << 100.0 * kForceNoiseWarning
      << " %): modes faster than solver.dt " << dt << " s ring in them undamped; ";
  if (integrator == IntegratorKind::kGeneralizedAlpha)
    why << "lower solver.rho_inf (now " << rho_inf << "; 0 damps what the step does not resolve in one step)"
        << " or a smaller solver.dt";
  else
    why << "use solver.integrator " << name(IntegratorKind::kGeneralizedAlpha)
        << " (damps what the step does not resolve) or a smaller solver.dt";
  return why.str();
}

}  // namespace riser_sim
