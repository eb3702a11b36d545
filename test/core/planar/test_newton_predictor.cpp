// The one-stage implicit schemes' Newton predictor (implicit_integrators.h): its weights solve their three
// conditions, and on a system whose solution is a smooth quadratic plus a stiff decaying mode (the
// unresolved modes the midpoint rule carries as (-1)^k) it starts Newton on the stage itself: one solve
// per step once three equal steps are behind it, two with the linear extrapolation (after a change of h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "riser_sim/integrators/implicit_integrators.h"

namespace {

using riser_sim::VecX;

// y = [q; v]: q' = a + b t (q quadratic in t; the midpoint rule integrates it exactly), v' = λ v with
// λ h = -1e14 (the rule's factor per step (1 + λh/2)/(1 - λh/2) = -1 + 4e-14). Exact shifted solves.
class QuadraticPlusStiff : public riser_sim::OdeSystem {
 public:
  static constexpr double a = 0.3, b = -1.7, lambda = -1e16;
  void rhs(double t, const VecX& y, VecX& dy) override {
    dy[0] = a + b * t;
    dy[1] = lambda * y[1];
  }
  bool hasShiftedSolve() const override { return true; }
  void factorShifted(double c) override { c_ = c; }
  void solveShifted(const VecX& r, VecX& x) override {
    x[0] = r[0];
    x[1] = r[1] / (1.0 - c_ * lambda);
  }

 private:
  double c_ = 0.0;
};

}  // namespace

TEST(NewtonPredictor, WeightsMeetTheirConditions) {
  riser_sim::IntegratorOptions o;
  const riser_sim::ImplicitMidpoint midpoint(o);
  EXPECT_NEAR(midpoint.predictorWeights()[0], 0.5, 1e-15);
  EXPECT_NEAR(midpoint.predictorWeights()[1], 0.5, 1e-15);
  EXPECT_NEAR(midpoint.predictorWeights()[2], -0.5, 1e-15);
  for (const double rho : {0.0, 0.3, 0.5, 1.0}) {
    SCOPED_TRACE(rho);
    o.rho_inf = rho;
    const riser_sim::GeneralizedAlpha ga(o);
    const Eigen::Vector3d w = ga.predictorWeights();
    const double theta = 1.0 / (1.0 + rho), r = -rho;  // α_f; the root at hλ -> -∞
    EXPECT_NEAR(w.sum(), theta, 1e-14);
    EXPECT_NEAR(w[0] + 2 * w[1] + 3 * w[2], 0.0, 1e-14);
    EXPECT_NEAR(w[0] * r * r + w[1] * r + w[2], theta * r * r * r, 1e-14);
  }
  o.rho_inf = 0.0;  // the stiff modes gone in one step: the quadratic extrapolation
  const Eigen::Vector3d w0 = riser_sim::GeneralizedAlpha(o).predictorWeights();
  EXPECT_NEAR(w0[0], 2.0, 1e-14);
  EXPECT_NEAR(w0[1], -1.0, 1e-14);
  EXPECT_NEAR(w0[2], 0.0, 1e-14);
}

TEST(NewtonPredictor, MidpointStartsOnTheStage) {
  QuadraticPlusStiff sys;
  riser_sim::IntegratorOptions o;
  o.jacobian = riser_sim::JacobianKind::kStructured;
  riser_sim::ImplicitMidpoint midpoint(o);
  midpoint.reset(riser_sim::StateLayout{2, 1});
  VecX y(2);
  y << 1.0, 1.0;
  double t = 0.0;
  std::vector<long> solves;
  const auto step = [&](double h) {
    const long before = midpoint.stats().newton;
    ASSERT_TRUE(midpoint.step(sys, t, y, h)) << midpoint.failure();
    t += h;
    solves.push_back(midpoint.stats().newton - before);
  };
  for (int k = 0; k < 10; ++k) step(0.01);
  for (int k = 0; k < 10; ++k) step(0.02);
  // The first step starts from y0; the next two extrapolate linearly (the stiff mode mispredicted by twice
  // its size: a second solve); from the fourth on the predictor is the stage to round-off.
  for (int k = 3; k < 10; ++k) EXPECT_EQ(solves[k], 1) << "step " << k;
  EXPECT_EQ(solves[1], 2);
  EXPECT_EQ(solves[2], 2);
  // After h changes: y0 (step 10), then the linear extrapolation, then one solve again.
  for (int k = 11; k < 13; ++k) EXPECT_EQ(solves[k], 2) << "step " << k;
  for (int k = 13; k < 20; ++k) EXPECT_EQ(solves[k], 1) << "step " << k;
  // The answer is the rule's own: q exact (a quadratic), v = R^20 with R = (1 + λh/2)/(1 - λh/2).
  const double q = 1.0 + QuadraticPlusStiff::a * t + 0.5 * QuadraticPlusStiff::b * t * t;
  EXPECT_NEAR(y[0], q, 1e-13);
  double v = 1.0;
  for (double h : {0.01, 0.02})
    v *= std::pow((1.0 + 0.5 * QuadraticPlusStiff::lambda * h) / (1.0 - 0.5 * QuadraticPlusStiff::lambda * h), 10);
  EXPECT_NEAR(y[1], v, 1e-12);
}
