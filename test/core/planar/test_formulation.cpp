// Consistency of the absolute formulation with its own energies: generalised forces vs finite
// differences of the potential, kinetic energy vs an independent sum over the rigid parts, the
// accelerations and reactions vs Lagrange's equations built from finite differences of T, the
// constraint accelerations, and free fall (top accelerating at g: no internal forces at all).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "riser_sim/planar/absolute_formulation.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/forces/end_load.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

// Central differences with step δ: truncation δ² V''' ~ 1e-10 of the force scale, round-off
// ε_mach |V| / δ ~ 1e-16 * 1e6 J / 1e-5 = 1e-5 N against forces of 1e2..1e4 N. Bound: 1e-7 of the
// largest generalised force of the term (measured: gravity 4e-10, axial 1e-15, bending 5e-12).
constexpr double kFdStep = 1e-5;
constexpr double kForceFdRelTol = 1e-7;
// T is quadratic in v, so the polarisation M_kl = (T(e_k + e_l) - T(e_k - e_l)) / 2 is exact up to
// round-off; the Lagrange residual adds the q-differences of T (as above). Bound relative to the
// largest term of the equation (measured ≤ 1e-12).
constexpr double kLagrangeRelTol = 1e-6;
// Kinetic energy: same quantity summed two ways, round-off only.
constexpr double kEnergyRelTol = 1e-12;
// Constraint accelerations by central differences in time (step ε = 1e-6 s): truncation ε² c''' and
// round-off 1e-16 / ε; measured ≤ 2e-9 m/s² with accelerations up to 3e3 m/s². Bound 1e-6 m/s².
constexpr double kConstraintAccTol = 1e-6;
// Free fall: the exact solution has λ = 0 and uniform acceleration, which RK4 integrates exactly;
// only round-off remains (relative to the weight / to the fall distance).
constexpr double kFreeFallForceRelTol = 1e-9;
constexpr double kFreeFallShapeTol = 1e-9;  // [m] after a 1 s fall (4.9 m); measured 7e-11 m
// The top joint of the absolute formulation is held by Baumgarte terms evaluated at the RK4 stage
// states, whose A_0 lags p(t) by O(h² g): a gap of that order (measured 1.5e-9 m at h = 1e-3 s)
// stays; formulations that eliminate the joints show 0.
constexpr double kFreeFallConstraintTol = 1e-8;  // [m]

// Table-1 line with bending, damping and an end mass, n = 4 (20 coordinates).
Scene smallScene() {
  Scene s = validation::table1Scene(4);
  s.options.bending = true;
  s.line.EI *= 1e3;  // bending forces comparable to the others
  s.line.axial_damping = 1e4;
  s.line.bending_damping = 1e3;
  return s;
}

// Random state near a bent hanging line; consistent = joints closed (positions and velocities).
VecX randomState(const Model& m, std::mt19937& rng, bool consistent) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int nq = m.dofs();
  VecX y = VecX::Zero(2 * nq);
  Vec2 A = Vec2::Zero(), Ad = Vec2::Zero();
  for (int i = 0; i < m.bodies(); ++i) {
    const double delta = 1e-4 * u(rng), phi = -M_PI / 2 + 0.8 * u(rng);
    const double delta_d = 0.1 * u(rng), phi_d = 0.5 * u(rng);
    if (!consistent) {
      A += Vec2(0.3 * u(rng), 0.3 * u(rng));
      Ad = Vec2(u(rng), u(rng));
    }
    y.segment<4>(4 * i) = Vec4(A.x(), A.y(), delta, phi);
    y.segment<4>(nq + 4 * i) = Vec4(Ad.x(), Ad.y(), delta_d, phi_d);
    const double len = m.rfe(i).length + delta;
    const Vec2 e = unit(phi), nrm = perp(e);
    Ad += delta_d * e + len * phi_d * nrm;  // velocity of the end of rfe i
    A += len * e;
  }
  return y;
}

double potential(const ForceTerm& term, const Model& m, const AbsoluteFormulation& f, const VecX& y) {
  Kinematics kin(m.bodies());
  f.kinematics(y, PointMotion(), kin);  // absolute: A_0 is in y
  return term.potentialEnergy(m, nullptr, kin);
}

TEST(Formulation, ForcesAreMinusGradientOfPotential) {
  const Scene s = smallScene();
  auto model = buildModel(s);
  model->addTerm(std::make_unique<EndLoad>(Vec2(3e2, -2e2)));  // initial.end_force: hold
  AbsoluteFormulation f(*model, 50.0);
  std::mt19937 rng(7);
  const int nq = model->dofs();
  for (int trial = 0; trial < 5; ++trial) {
    VecX y = randomState(*model, rng, false);
    y.tail(nq).setZero();  // no velocity: damping off, the forces are the conservative ones
    Kinematics kin(model->bodies());
    f.kinematics(y, PointMotion(), kin);  // absolute: A_0 is in y
    for (const auto& term : model->terms()) {
      VecX Q = VecX::Zero(nq);
      term->addForces(*model, nullptr, kin, 0.0, Q);
      double worst = 0.0;
      for (int j = 0; j < nq; ++j) {
        VecX yp = y, ym = y;
        yp[j] += kFdStep;
        ym[j] -= kFdStep;
        const double dV = (potential(*term, *model, f, yp) - potential(*term, *model, f, ym)) / (2 * kFdStep);
        worst = std::max(worst, std::abs(Q[j] + dV));
      }
      const double scale = Q.lpNorm<Eigen::Infinity>();
      if (trial == 0)
        std::printf("[formulation] %s: max |Q + dV/dq| = %.2e (max |Q| %.2e)\n", term->name().c_str(), worst, scale);
      EXPECT_GT(scale, 0.0) << term->name();
      EXPECT_LT(worst, kForceFdRelTol * scale) << term->name() << " trial " << trial;
    }
  }
}

TEST(Formulation, KineticEnergyIsSumOverRigidParts) {
  const Scene s = smallScene();
  auto model = buildModel(s);
  AbsoluteFormulation f(*model, 50.0);
  const auto fd = f.makeData();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const VecX y = randomState(*model, rng, false);
    Kinematics kin(model->bodies());
    f.kinematics(y, PointMotion(), kin);  // absolute: A_0 is in y
    double T = 0.0;
    for (int i = 0; i < model->bodies(); ++i) {
      const Rfe& r = model->rfe(i);
      for (int p = 0; p < r.num_parts; ++p) {
        const RigidPart& part = r.part[p];
        T += 0.5 * part.mass * kin[i].velocity(part.s0, part.kappa).squaredNorm() +
             0.5 * part.inertia * kin[i].phi_dot * kin[i].phi_dot;
      }
    }
    EXPECT_NEAR(f.kineticEnergy(0.0, y, PointMotion(), *fd), T, kEnergyRelTol * T);
  }
}

// M(q) v̇ + Ṁ v - ∂T/∂q = Q + constraint forces, with M and the velocity terms taken from finite
// differences of Formulation::kineticEnergy and the joint forces from the data's reactions.
TEST(Formulation, AccelerationsSatisfyLagrangeEquations) {
  const Scene s = smallScene();
  auto model = buildModel(s);
  AbsoluteFormulation f(*model, 50.0);
  const auto fd = f.makeData();
  const int nq = model->dofs(), nb = model->bodies();
  std::mt19937 rng(3);
  const PointMotion top{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  auto T = [&](const VecX& q, const VecX& v) {
    VecX y(2 * nq);
    y << q, v;
    return f.kineticEnergy(0.0, y, top, *fd);
  };
  auto massMatrix = [&](const VecX& q) {
    MatX M(nq, nq);
    for (int k = 0; k < nq; ++k)
      for (int l = 0; l < nq; ++l) {
        VecX a = VecX::Zero(nq), b = VecX::Zero(nq);
        a[k] += 1.0;
        a[l] += 1.0;
        b[k] += 1.0;
        b[l] -= 1.0;
        M(k, l) = 0.5 * (T(q, a) - T(q, b));  // T(a) - T(b) = ½(aᵀMa - bᵀMb) = 2 M_kl
      }
    return M;
  };
  for (int trial = 0; trial < 3; ++trial) {
    const VecX y = randomState(*model, rng, trial > 0);
    const VecX q = y.head(nq), v = y.tail(nq);
    VecX dy(2 * nq);
    f.derivative(0.0, y, top, dy, *fd);
    const VecX acc = dy.tail(nq);
    const Reactions re = fd->reactions;
    Kinematics kin(nb);
    f.kinematics(y, PointMotion(), kin);  // absolute: A_0 is in y
    VecX Q = VecX::Zero(nq);
    for (const auto& term : model->terms()) term->addForces(*model, nullptr, kin, 0.0, Q);
    for (int i = 0; i < nb; ++i) {  // joint forces: -λ_i at A_i, +λ_{i+1} at the end of rfe i
      Q.segment<4>(4 * i) += pointForce(kin[i], 0.0, 0.0, -re.joint[i]);
      if (i + 1 < nb) Q.segment<4>(4 * i) += pointForce(kin[i], model->rfe(i).length, 1.0, re.joint[i + 1]);
    }
    const MatX M = massMatrix(q);
    VecX lhs = M * acc;
    VecX dTdq(nq), Mdot_v = VecX::Zero(nq);
    for (int j = 0; j < nq; ++j) {
      VecX qp = q, qm = q;
      qp[j] += kFdStep;
      qm[j] -= kFdStep;
      dTdq[j] = (T(qp, v) - T(qm, v)) / (2 * kFdStep);
      Mdot_v += (massMatrix(qp) - massMatrix(qm)) * v * (v[j] / (2 * kFdStep));
    }
    lhs += Mdot_v - dTdq;
    const double scale = std::max({Q.lpNorm<Eigen::Infinity>(), (M * acc).lpNorm<Eigen::Infinity>(), 1.0});
    const double res = (lhs - Q).lpNorm<Eigen::Infinity>();
    std::printf("[formulation] Lagrange residual %.2e (scale %.2e), %s state\n", res, scale,
                trial > 0 ? "consistent" : "random");
    EXPECT_LT(res, kLagrangeRelTol * scale) << "trial " << trial;
  }
}

// For a state with closed joints (c = 0, c' = 0) the accelerations keep them closed: c'' = 0.
TEST(Formulation, ConstraintAccelerationsVanish) {
  const Scene s = smallScene();
  auto model = buildModel(s);
  AbsoluteFormulation f(*model, 50.0);
  const auto fd = f.makeData();
  const int nq = model->dofs(), nb = model->bodies();
  std::mt19937 rng(5);
  const PointMotion top{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  auto jointVelocityGaps = [&](const VecX& y) {
    Kinematics kin(nb);
    f.kinematics(y, PointMotion(), kin);  // absolute: A_0 is in y
    VecX g(2 * nb);
    g.head<2>() = top.v - kin[0].A_dot;
    for (int k = 1; k < nb; ++k) g.segment<2>(2 * k) = kin[k - 1].endVelocity() - kin[k].A_dot;
    return g;
  };
  for (int trial = 0; trial < 3; ++trial) {
    const VecX y = randomState(*model, rng, true);
    EXPECT_LT(f.constraintError(y, top), 1e-12);
    EXPECT_LT(jointVelocityGaps(y).lpNorm<Eigen::Infinity>(), 1e-12);
    VecX dy(2 * nq);
    f.derivative(0.0, y, top, dy, *fd);
    const double eps = 1e-6;
    const VecX cdd = (jointVelocityGaps(y + eps * dy) - jointVelocityGaps(y - eps * dy)) / (2 * eps);
    std::printf("[formulation] constraint acceleration %.2e m/s^2 (accelerations up to %.2e)\n",
                cdd.lpNorm<Eigen::Infinity>(), dy.tail(nq).lpNorm<Eigen::Infinity>());
    EXPECT_LT(cdd.lpNorm<Eigen::Infinity>(), kConstraintAccTol);
  }
}

// A_0 accelerating downward at g: the whole line falls freely, the joints carry nothing.
class FreeFall : public TopMotion {
 public:
  explicit FreeFall(double g) : g_(g) {}
  std::string name() const override { return "free_fall"; }
  PointMotion at(double t) const override {
    return PointMotion{Vec2(0.0, -0.5 * g_ * t * t), Vec2(0.0, -g_ * t), Vec2(0.0, -g_)};
  }

 private:
  double g_;
};

void freeFall(const std::string& formulation, bool bending) {
  Scene s = smallScene();
  s.options.bending = bending;
  s.solver.formulation = toChoice<FormulationKind>(formulation);
  s.solver.dt = 1e-3;
  auto model = buildModel(s);
  Simulator sim(model, std::make_unique<FreeFall>(s.gravity), s.solver);
  // Unstressed shape: Δ = 0; a zig-zag when there are no bending springs, straight otherwise.
  Kinematics kin = straightLine(*model, Vec2::Zero(), -1.0);
  if (!bending) {
    for (int i = 0; i < model->bodies(); ++i) {
      kin[i].phi = (i % 2 ? -0.3 : -2.5);
      kin[i].c = std::cos(kin[i].phi);
      kin[i].s = std::sin(kin[i].phi);
      if (i > 0) kin[i].A = kin[i - 1].end();
    }
  }
  sim.setInitialState(kin, 0.0);
  const double weight = model->totalMass() * s.gravity;
  const LineOutputs& o = sim.outputs();
  double worst = o.top_force.norm();
  for (double n : o.axial_force) worst = std::max(worst, std::abs(n));
  std::printf("[free fall %s, %s] largest internal force %.2e N (weight %.0f N)\n", formulation.c_str(),
              bending ? "straight, bending" : "zig-zag", worst, weight);
  EXPECT_LT(worst, kFreeFallForceRelTol * weight);
  ASSERT_TRUE(sim.advanceTo(1.0)) << sim.divergenceReason();
  Kinematics now(model->bodies());
  sim.kinematics(now);
  double shape = 0.0;
  const Vec2 drop = sim.topMotion().at(sim.time()).p;
  for (int i = 0; i < model->bodies(); ++i) shape = std::max(shape, (now[i].end() - drop - kin[i].end()).norm());
  std::printf("[free fall %s] shape change after 1 s %.2e m, constraint error %.2e m\n", formulation.c_str(), shape,
              sim.maxConstraintError());
  EXPECT_LT(shape, kFreeFallShapeTol);
  EXPECT_LT(sim.maxConstraintError(), kFreeFallConstraintTol);
}

TEST(Formulation, FreeFallCarriesNoForce) {
  for (const char* name : {"absolute", "independent", "recursive"}) {
    freeFall(name, false);
    freeFall(name, true);
  }
}

}  // namespace
}  // namespace riser_sim
