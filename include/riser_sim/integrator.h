// Time integrators behind one small interface (Drake-style). Workspaces are sized once in reset();
// step() allocates nothing.
#pragma once
#include <memory>
#include <string>

#include "riser_sim/types.h"

namespace riser_sim {

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual void rhs(double t, const VecX& y, VecX& dy) = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  virtual void reset(int state_size) = 0;
  // Advances y from t by h [s].
  virtual void step(OdeSystem& sys, double t, VecX& y, double h) = 0;
  // Number of rhs evaluations per step (for cost reports).
  virtual int stages() const = 0;
};

// Classical fixed-step fourth-order Runge-Kutta (the paper's scheme).
class Rk4 : public Integrator {
 public:
  std::string name() const override { return "rk4"; }
  void reset(int n) override;
  void step(OdeSystem& sys, double t, VecX& y, double h) override;
  int stages() const override { return 4; }

 private:
  VecX k1_, k2_, k3_, k4_, tmp_;
};

// Names accepted by solver.integrator; throws std::invalid_argument otherwise.
std::unique_ptr<Integrator> makeIntegrator(const std::string& name);

}  // namespace riser_sim
