// Adaptive Dormand-Prince 5(4) (Hairer, Nørsett & Wanner, "Solving ODEs I", II.5): error control on
// positions and velocities (atol = rtol = tolerance; the trailing work entry is integrated but not
// controlled), PI step-size controller, first-same-as-last. step(h) advances exactly h with as many
// internal substeps as the tolerance needs; the last accepted internal step is kept between calls.
#pragma once
#include "riser_sim/integrators/integrator.h"

namespace riser_sim {

class Dopri5 : public Integrator {
 public:
  explicit Dopri5(const IntegratorOptions& options) : options_(options) {}
  std::string name() const override { return "dopri5"; }
  void reset(const StateLayout& layout) override;
  bool step(OdeSystem& sys, double t, VecX& y, double h) override;
  int stages() const override { return 6; }  // per accepted substep (FSAL)
  void restart() override {
    fsal_valid_ = false;
    failure_.clear();
  }
  const std::string& failure() const override { return failure_; }
  Stats stats() const override { return stats_; }
  double lastSubstep() const { return h_; }

 private:
  double initialStep(OdeSystem& sys, double t, const VecX& y, double h_max);
  double errorNorm(const VecX& y0, const VecX& y1) const;

  IntegratorOptions options_;
  int controlled_ = 0;  // entries under error control: q and v
  VecX k1_, k2_, k3_, k4_, k5_, k6_, k7_, tmp_, y1_, err_, y_last_;
  double h_ = 0.0, err_old_ = 1e-4, t_last_ = 0.0;
  bool fsal_valid_ = false;
  std::string failure_;
  Stats stats_;
};

}  // namespace riser_sim
