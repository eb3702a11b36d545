// The spatial formulation's solve on random states (joints slightly open, |e| slightly off 1, moving):
// - the accelerations it returns satisfy every constraint's Baumgarte law c'' + 2ω c' + ω² c = 0 (top,
//   joints, pinned end, unit length), i.e. the block-Thomas solve and the per-rfe elimination are right;
// - the closed-form per-rfe inverse equals the dense 7x7 Cholesky + Schur path.
#include <gtest/gtest.h>

#include <random>

#include "spatial_test_util.h"

namespace riser_sim {
namespace {

using namespace spatial;

constexpr double kOmega = 50.0;  // [rad/s] Baumgarte
// Both are round-off: accelerations ~1e2..1e4 m/s² (light stiff parts) from O(n) 3x3 solves, relative
// 1e-10 of the largest acceleration (measured ~1e-14).
constexpr double kRelTol = 1e-10;

VecX randomState(const Model3& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kinematics3 kin(m.bodies());
  Vec3 A(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics3& b = kin[i];
    b.A = A;
    b.A_dot = Vec3(u(rng), u(rng), u(rng));
    b.delta = 1e-3 * u(rng);
    b.delta_dot = 0.1 * u(rng);
    b.e = Vec3(u(rng), u(rng), -1.5 + u(rng)).normalized() * (1.0 + 1e-6 * u(rng));
    b.e_dot = Vec3(u(rng), u(rng), u(rng));
    b.len = m.rfe(i).length + b.delta;
    A = b.end() + 1e-4 * Vec3(u(rng), u(rng), u(rng));
  }
  VecX y = VecX::Zero(2 * m.dofs());
  NaturalFormulation(m, kOmega).packState(kin, y);
  return y;
}

struct Case {
  bool axial, pinned;
};

void check(const Case& c) {
  spatial_test::LineSpec s = spatial_test::flexibleLine();
  s.segments = 6;
  s.options.axial_flexibility = c.axial;
  auto m = spatial_test::spatialModel(s, Vec3(0.5, -0.3, -9.81));
  if (c.pinned) m->setBottom(BottomBoundary::kPinned, Vec3(1.0, 0.5, -9.0));
  NaturalFormulation closed(*m, kOmega, true), dense(*m, kOmega, false);
  auto dc = closed.makeData(), dd = dense.makeData();
  std::mt19937 rng(c.axial * 2 + c.pinned);
  const PointMotion3 top{Vec3(0.01, 0.02, -0.01), Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5)};
  const int nq = m->dofs(), nb = m->bodies();
  for (int trial = 0; trial < 5; ++trial) {
    const VecX y = randomState(*m, rng);
    VecX f1 = VecX::Zero(y.size()), f2 = VecX::Zero(y.size());
    closed.derivative(0.0, y, top, f1, *dc);
    dense.derivative(0.0, y, top, f2, *dd);
    const double scale = f1.cwiseAbs().maxCoeff();
    const double diff = (f1 - f2).cwiseAbs().maxCoeff() / scale;
    EXPECT_LT(diff, kRelTol);
    // Constraint accelerations from the returned u'' (E'' = A'' + Δ'' e + 2Δ' e' + len e'').
    Kinematics3 kin(nb);
    closed.kinematics(y, kin);
    auto acc = [&](int i, int k) { return Vec3(f1.segment<3>(nq + kDofPerBody3 * i + k)); };
    auto endAcc = [&](int i) {
      return Vec3(acc(i, kA) + f1[nq + kDofPerBody3 * i + kDelta3] * kin[i].e + 2.0 * kin[i].delta_dot * kin[i].e_dot +
                  kin[i].len * acc(i, kE));
    };
    double worst = 0.0;
    auto law = [&](const Vec3& c0, const Vec3& c1, const Vec3& c2) {
      worst = std::max(worst, (c2 + 2 * kOmega * c1 + kOmega * kOmega * c0).norm() / scale);
    };
    law(top.p - kin[0].A, top.v - kin[0].A_dot, top.a - acc(0, kA));
    for (int k = 1; k < nb; ++k)
      law(kin[k - 1].end() - kin[k].A, kin[k - 1].endVelocity() - kin[k].A_dot, endAcc(k - 1) - acc(k, kA));
    if (c.pinned) law(kin[nb - 1].end() - m->bottomPoint(), kin[nb - 1].endVelocity(), endAcc(nb - 1));
    for (int i = 0; i < nb; ++i) {
      const Vec3& e = kin[i].e;
      const Vec3& ed = kin[i].e_dot;
      law(Vec3(0.5 * (e.squaredNorm() - 1), 0, 0), Vec3(e.dot(ed), 0, 0),
          Vec3(e.dot(acc(i, kE)) + ed.squaredNorm(), 0, 0));
    }
    EXPECT_LT(worst, kRelTol);
    if (trial == 0)
      std::printf(
          "[spatial solve axial=%d pinned=%d] |closed - dense| %.1e, Baumgarte law residual %.1e (of max |u''| %.1e)\n",
          c.axial, c.pinned, diff, worst, scale);
  }
}

TEST(SpatialFormulation, ConstraintLawsHoldAndClosedFormEqualsDense) {
  for (bool axial : {true, false})
    for (bool pinned : {false, true}) check(Case{axial, pinned});
}

}  // namespace
}  // namespace riser_sim
