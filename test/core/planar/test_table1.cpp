// The paper's Table 1 case (section 2.3): m_s = 1000 kg on a 100 m line, released from the
// catenary with the end displaced by 50 m; x_s, y_s at t = 20 s. We establish the converged answer
// of the stated problem (in h and in n) and bracket it with limits; the comparison with the paper's
// -49.552 / -86.765 (which we do not reproduce) is documented in docs/validation.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "validation_util.h"

namespace riser_sim {
namespace {

constexpr double kDuration = 20.0;                      // [s] Table 1
constexpr double kSample = 0.01;                        // [s] trajectory sampling for the convergence norms
constexpr double kPaperX = -49.552, kPaperY = -86.765;  // Table 1, absolute coordinates, n >= 30

// h: RK4 is 4th order; the slowest relevant error is the pendulum phase ((ω h)^4 ~ 1e-16) and the
// fastest excited mode (axial end-mass mode, ω ≈ 42 rad/s: (ω h)^4 ~ 3e-8 of its ~2 mm amplitude).
// Measured |r(h) - r(h/2)| < 1e-8 m at n = 10. 1e-6 m: still 3 orders below the n-differences.
constexpr double kTimeStepTol = 1e-6;  // [m]
// n: the line is a midpoint-lumped (second-order) discretisation. For the inextensible line the
// RMS trajectory difference over [0, 20] s shrinks with measured orders (x, y) 1.85, 1.90
// (n = 10-20-40), then 1.92, 1.95 and 1.96, 1.97 (to n = 160). Accept [1.7, 2.3].
constexpr double kMinOrder = 1.7, kMaxOrder = 2.3;
// Elastic line: the release excites the axial end-mass mode (~6.7 Hz, ~2 mm amplitude, undamped),
// which couples to short transverse waves; their phase after 20 s converges slowly, so differences
// stall at ~1-2 mm beyond n = 40 (see docs/validation.md: n = 80, 160). Between n = 10, 20, 40 the
// RMS differences still shrink with orders 1.82 (x) and 1.49 (y); accept >= 1.3 for x, and a
// shrinking difference for y.
constexpr double kElasticMinOrder = 1.3;
// Converged answer: mean of n = 20, 40, 80, 160 (h <= 1e-4, docs/validation.md): x_s(20) =
// -49.9183, y_s(20) = -86.6038, spread 0.6 mm (x), 2.8 mm (y) between resolutions. Band: 5 mm.
constexpr double kConvergedX = -49.9183, kConvergedY = -86.6038, kConvergedTol = 5e-3;  // [m]

struct Trajectory {
  std::vector<double> t, x, y;  // end point relative to the top [m]
  double wall = 0.0;            // [s]
  Vec2 end() const { return Vec2(x.back(), y.back()); }
};

Trajectory simulate(int n, double dt, bool axial) {
  Scene s = validation::table1Scene(n, dt);
  s.options.axial_flexibility = axial;
  auto sim = buildSimulator(s);
  Kinematics kin(sim->model().bodies());
  Trajectory tr;
  const int samples = int(std::lround(kDuration / kSample));
  for (int k = 0; k <= samples; ++k) {
    EXPECT_TRUE(sim->advanceTo(k * kSample)) << sim->divergenceReason();
    sim->kinematics(kin);
    const Vec2 e = kin.back().end() - kin[0].A;
    tr.t.push_back(sim->time());
    tr.x.push_back(e.x());
    tr.y.push_back(e.y());
  }
  EXPECT_LT(std::abs(sim->energyDrift()), 1e-8);  // see test_energy.cpp
  return tr;
}

// Runs are shared between the tests of this binary (each costs 1-6 s).
const Trajectory& run(int n, double dt, bool axial) {
  static std::map<std::tuple<int, double, bool>, Trajectory> cache;
  auto key = std::make_tuple(n, dt, axial);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, simulate(n, dt, axial)).first;
  return it->second;
}

// Largest and RMS distance between two trajectories over the whole run [m] (x and y separately).
Vec2 maxDifference(const Trajectory& a, const Trajectory& b) {
  Vec2 d = Vec2::Zero();
  for (size_t k = 0; k < a.x.size(); ++k) {
    d.x() = std::max(d.x(), std::abs(a.x[k] - b.x[k]));
    d.y() = std::max(d.y(), std::abs(a.y[k] - b.y[k]));
  }
  return d;
}
Vec2 rmsDifference(const Trajectory& a, const Trajectory& b) {
  Vec2 d = Vec2::Zero();
  for (size_t k = 0; k < a.x.size(); ++k) {
    d.x() += std::pow(a.x[k] - b.x[k], 2);
    d.y() += std::pow(a.y[k] - b.y[k], 2);
  }
  return (d / double(a.x.size())).cwiseSqrt();
}

TEST(Table1, ConvergedInTimeStep) {
  const Trajectory& a = run(10, 1e-4, true);
  const Trajectory& b = run(10, 5e-5, true);
  const Vec2 d = maxDifference(a, b);
  std::printf("[table1 h] n=10: h=1e-4 (%.6f, %.6f), h=5e-5 (%.6f, %.6f), max trajectory difference (%.2e, %.2e) m\n",
              a.x.back(), a.y.back(), b.x.back(), b.y.back(), d.x(), d.y());
  EXPECT_LT(d.x(), kTimeStepTol);
  EXPECT_LT(d.y(), kTimeStepTol);
}

TEST(Table1, InextensibleLineConvergesAtSecondOrderInN) {
  const Trajectory &a = run(10, 1e-4, false), &b = run(20, 1e-4, false), &c = run(40, 1e-4, false);
  const Vec2 d1 = rmsDifference(a, b), d2 = rmsDifference(b, c);
  const double px = validation::order(d1.x(), d2.x()), py = validation::order(d1.y(), d2.y());
  std::printf("[table1 inextensible] x_s(20): %.6f %.6f %.6f; y_s(20): %.6f %.6f %.6f\n", a.x.back(), b.x.back(),
              c.x.back(), a.y.back(), b.y.back(), c.y.back());
  std::printf("[table1 inextensible] rms |x_n - x_2n| %.3e, %.3e (order %.2f); y %.3e, %.3e (order %.2f)\n", d1.x(),
              d2.x(), px, d1.y(), d2.y(), py);
  EXPECT_GT(px, kMinOrder);
  EXPECT_LT(px, kMaxOrder);
  EXPECT_GT(py, kMinOrder);
  EXPECT_LT(py, kMaxOrder);
}

TEST(Table1, ElasticLineConvergesInN) {
  const Trajectory &a = run(10, 1e-4, true), &b = run(20, 1e-4, true), &c = run(40, 1e-4, true);
  const Vec2 d1 = rmsDifference(a, b), d2 = rmsDifference(b, c);
  const double px = validation::order(d1.x(), d2.x());
  std::printf("[table1] x_s(20): n=10 %.6f, n=20 %.6f, n=40 %.6f (paper %.3f)\n", a.x.back(), b.x.back(), c.x.back(),
              kPaperX);
  std::printf("[table1] y_s(20): n=10 %.6f, n=20 %.6f, n=40 %.6f (paper %.3f)\n", a.y.back(), b.y.back(), c.y.back(),
              kPaperY);
  std::printf("[table1] rms |r_n - r_2n| x: %.3e, %.3e (order %.2f); y: %.3e, %.3e\n", d1.x(), d2.x(), px, d1.y(),
              d2.y());
  std::printf("[table1] n=40 minus paper: dx %.3f m, dy %.3f m\n", c.x.back() - kPaperX, c.y.back() - kPaperY);
  EXPECT_GT(px, kElasticMinOrder);
  EXPECT_LT(d2.y(), d1.y());
  // End values: the n = 20 -> 40 change is smaller than the 10 -> 20 one, and both sit in the band
  // of the converged answer.
  EXPECT_LT(std::abs(c.x.back() - b.x.back()), std::abs(b.x.back() - a.x.back()));
  EXPECT_LT(std::abs(c.y.back() - b.y.back()), std::abs(b.y.back() - a.y.back()));
  EXPECT_NEAR(c.x.back(), kConvergedX, kConvergedTol);
  EXPECT_NEAR(c.y.back(), kConvergedY, kConvergedTol);
}

// Limits of the pendulum period for the same mass distribution: the rigid compound pendulum (end
// mass plus a uniform rod; a chain has more freedom, so by Rayleigh's principle its period is not
// shorter) and the massless-line pendulum of length L (line mass raises the frequency).
TEST(Table1, PeriodBracketedByRigidAndMasslessPendulum) {
  const Scene s = validation::table1Scene(20);
  const double L = s.length, g = s.gravity, ms = s.end_mass, ml = s.line.mass_per_length * L;
  const double theta0 = std::asin(0.5);
  const double l_rigid = L * (ms + ml / 3) / (ms + ml / 2);
  const double t_rigid = validation::pendulumPeriod(l_rigid, g, theta0);
  const double t_massless = validation::pendulumPeriod(L, g, theta0);
  const Trajectory& tr = run(20, 1e-4, true);
  const std::vector<double> z = validation::zeroCrossings(tr.t, tr.x);
  ASSERT_EQ(z.size(), 2u);
  const double period = z[0] + z[1];  // crossings at T/4 and 3T/4
  std::printf("[table1 period] T = %.4f s (crossings %.4f, %.4f); rigid compound %.4f s, massless line %.4f s\n",
              period, z[0], z[1], t_rigid, t_massless);
  EXPECT_GT(period, t_rigid);
  EXPECT_LT(period, t_massless);
}

}  // namespace
}  // namespace riser_sim
