// Checks of a spatial force term against its energy (test_spatial_forces.cpp, test_spatial_sea.cpp), on random
// states of a Model3:
// - conservative parts (velocities zero): Q = -∂V/∂q on the tangent space (the e part projected
//   orthogonally to e), by central differences of V;
// - power identity with velocities: Q·q' = -dV/dt + P, dV/dt by central differences along q'.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/natural_formulation.h"

namespace riser_sim {
namespace spatial_test {

using spatial::BodyKinematics3;
using spatial::ForceTerm3;
using spatial::kDofPerBody3;
using spatial::kE;
using spatial::Kinematics3;
using spatial::Model3;
using spatial::NaturalFormulation;
using spatial::Vec3;

// Central differences with step ε: truncation ε² V''' / 6 ~ 1e-10 of the force scale, round-off
// 1e-16 |V| / ε ~ 1e-11 of it; bound 1e-6 relative to the largest |Q| entry (measured 1.4e-10 gravity,
// 2.1e-11 bending, 3e-15 axial).
inline constexpr double kFdStep = 1e-5;
inline constexpr double kRelTol = 1e-6;

// Random state near a hanging line: Δ ~ 1e-3 m, directions spread over the sphere around -z, with a
// straight joint (θ = 0 exactly) between rfes 1 and 2; velocities random, e' tangent.
inline VecX randomState(const Model3& m, std::mt19937& rng, bool moving) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kinematics3 kin(m.bodies());
  Vec3 A(u(rng), u(rng), u(rng));
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics3& b = kin[i];
    b.A = A;
    b.delta = 1e-3 * u(rng);
    b.e = i == 2 ? kin[1].e : Vec3(0.9 * u(rng), 0.9 * u(rng), -1.0 + 0.5 * u(rng)).normalized();
    b.len = m.rfe(i).length + b.delta;
    if (moving) {
      b.A_dot = Vec3(u(rng), u(rng), u(rng));
      b.delta_dot = 0.1 * u(rng);
      const Vec3 r(u(rng), u(rng), u(rng));
      b.e_dot = r - r.dot(b.e) * b.e;
    }
    A = b.end() + Vec3(1e-3 * u(rng), 0, 0);  // joints need not close for a term's check
  }
  NaturalFormulation f(m, 50.0);
  VecX y = VecX::Zero(2 * m.dofs());
  f.packState(kin, y);
  return y;
}

inline double energy(const ForceTerm3& term, const Model3& m, const NaturalFormulation& f, const VecX& y,
                     double t = 0.0) {
  Kinematics3 kin(m.bodies());
  f.kinematics(y, kin);
  return term.potentialEnergy(m, kin, t);
}

// Projects the e part of every rfe's generalised vector orthogonally to e.
inline VecX tangent(const Model3& m, const VecX& y, VecX g) {
  for (int i = 0; i < m.bodies(); ++i) {
    const Vec3 e = y.segment<3>(kDofPerBody3 * i + kE);
    auto ge = g.segment<3>(kDofPerBody3 * i + kE);
    ge -= ge.dot(e) / e.squaredNorm() * e;
  }
  return g;
}

inline void checkGradient(const ForceTerm3& term, const Model3& m, double t = 0.0) {
  std::mt19937 rng(7);
  NaturalFormulation f(m, 50.0);
  const int nq = m.dofs();
  for (int trial = 0; trial < 5; ++trial) {
    VecX y = randomState(m, rng, false);
    Kinematics3 kin(m.bodies());
    f.kinematics(y, kin);
    VecX Q = VecX::Zero(nq);
    term.addForces(m, kin, t, Q);
    VecX grad = VecX::Zero(nq);
    for (int j = 0; j < nq; ++j) {
      VecX yp = y, ym = y;
      yp[j] += kFdStep;
      ym[j] -= kFdStep;
      grad[j] = (energy(term, m, f, yp, t) - energy(term, m, f, ym, t)) / (2 * kFdStep);
    }
    const VecX q_t = tangent(m, y, Q), g_t = tangent(m, y, grad);
    const double scale = std::max(q_t.cwiseAbs().maxCoeff(), 1e-12);
    const double err = (q_t + g_t).cwiseAbs().maxCoeff() / scale;
    EXPECT_LT(err, kRelTol) << term.name() << " trial " << trial;
    if (trial == 0) std::printf("[spatial %s] |Q + dV/dq| / |Q| = %.2e (tangent)\n", term.name().c_str(), err);
  }
}

// Q·v + dV/dt = P along the motion, dV/dt = ∂V/∂q v + ∂V/∂t (a term whose potential moves with time, e.g. a
// flex joint on a turning holder, reports ∂V/∂t in its power: the work its holder does).
inline void checkPower(const ForceTerm3& term, const Model3& m, double t = 0.0) {
  std::mt19937 rng(11);
  NaturalFormulation f(m, 50.0);
  const int nq = m.dofs();
  for (int trial = 0; trial < 5; ++trial) {
    const VecX y = randomState(m, rng, true);
    Kinematics3 kin(m.bodies());
    f.kinematics(y, kin);
    VecX Q = VecX::Zero(nq);
    const double P = term.addForcesAndPower(m, kin, t, Q);
    const double Qv = Q.dot(y.segment(nq, nq));
    VecX yp = y, ym = y;
    yp.head(nq) += kFdStep * y.segment(nq, nq);
    ym.head(nq) -= kFdStep * y.segment(nq, nq);
    const double dV = (energy(term, m, f, yp, t + kFdStep) - energy(term, m, f, ym, t - kFdStep)) / (2 * kFdStep);
    const double scale = std::max({std::abs(Qv), std::abs(P), 1e-12});
    EXPECT_LT(std::abs(Qv + dV - P) / scale, kRelTol) << term.name() << " trial " << trial;
    if (trial == 0)
      std::printf("[spatial %s] Q·v = %.6e, -dV/dt + P = %.6e, P = %.3e\n", term.name().c_str(), Qv, -dV + P, P);
  }
}

// The term's C = -∂Q/∂q' (addStiffness, rate part) against central differences of Q in each rate at state y and
// time t: max |C - C_fd| over the largest |C_fd| entry.
inline double rateJacobianError(const ForceTerm3& term, const Model3& m, const VecX& y, double t) {
  const NaturalFormulation f(m, 50.0);
  const int nq = m.dofs();
  Kinematics3 kin(m.bodies()), kp(m.bodies()), km(m.bodies());
  f.kinematics(y, kin);
  spatial::Stiffness3 S;
  S.resize(m.bodies());
  term.addStiffness(m, kin, t, S);
  double scale = 0.0, err = 0.0;
  for (int j = 0; j < nq; ++j) {
    VecX yp = y, ym = y;
    const double h = 1e-6;
    yp[nq + j] += h, ym[nq + j] -= h;
    f.kinematics(yp, kp);
    f.kinematics(ym, km);
    VecX Qp = VecX::Zero(nq), Qm = VecX::Zero(nq);
    term.addForces(m, kp, t, Qp);
    term.addForces(m, km, t, Qm);
    const VecX col = -(Qp - Qm) / (2 * h);
    const int body = j / kDofPerBody3, c = j % kDofPerBody3;
    for (int r = 0; r < nq; ++r) {
      const double a = r / kDofPerBody3 == body ? S.C_diag[body](r % kDofPerBody3, c) : 0.0;
      err = std::max(err, std::abs(a - col[r]));
      scale = std::max(scale, std::abs(col[r]));
    }
  }
  return scale > 0.0 ? err / scale : err;
}

}  // namespace spatial_test
}  // namespace riser_sim
