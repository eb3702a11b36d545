#include "riser_sim/integrators/integrator.h"

#include <stdexcept>

#include "riser_sim/integrators/dopri5.h"
#include "riser_sim/integrators/implicit_integrators.h"

namespace riser_sim {

void Rk4::reset(const StateLayout& layout) {
  const int n = layout.size;
  k1_.setZero(n);
  k2_.setZero(n);
  k3_.setZero(n);
  k4_.setZero(n);
  stats_ = Stats();
  tmp_.setZero(n);
}

bool Rk4::step(OdeSystem& sys, double t, VecX& y, double h) {
  sys.rhs(t, y, k1_);
  tmp_ = y + 0.5 * h * k1_;
  sys.rhs(t + 0.5 * h, tmp_, k2_);
  tmp_ = y + 0.5 * h * k2_;
  sys.rhs(t + 0.5 * h, tmp_, k3_);
  tmp_ = y + h * k3_;
  sys.rhs(t + h, tmp_, k4_);
  y += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
  ++stats_.substeps;
  stats_.rhs += 4;
  return true;  // no contract beyond the arithmetic: the Simulator checks the state
}

bool isImplicitIntegrator(IntegratorKind kind) {
  return kind == IntegratorKind::kRosenbrock2 || kind == IntegratorKind::kMidpoint ||
         kind == IntegratorKind::kGeneralizedAlpha;
}

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind, const IntegratorOptions& options) {
  switch (kind) {
    case IntegratorKind::kRk4: return std::make_unique<Rk4>();
    case IntegratorKind::kDopri5: return std::make_unique<Dopri5>(options);
    case IntegratorKind::kRosenbrock2: return std::make_unique<Rosenbrock2>(options);
    case IntegratorKind::kMidpoint: return std::make_unique<ImplicitMidpoint>(options);
    case IntegratorKind::kGeneralizedAlpha: return std::make_unique<GeneralizedAlpha>(options);
  }
  throw std::invalid_argument("solver.integrator: unknown integrator (accepted: " + choiceNames<IntegratorKind>() +
                              ")");
}

}  // namespace riser_sim
