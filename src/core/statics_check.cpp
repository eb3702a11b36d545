// checkEquilibrium(): what a statics solution must satisfy before it is reported as one.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <sstream>

#include "statics_residual.h"

namespace riser_sim {
namespace statics_detail {

// The equilibrium is stable when K = -∂Q_θ/∂θ, reduced to the directions that keep the end conditions
// (the null space of their Jacobian C), is positive definite. K from central differences of the
// residual at x, Jacobi-scaled (unit diagonal). Its asymmetric part measures the finite-difference
// noise (K is symmetric for conservative loads; measured ~1e-9) plus the asymmetry of follower loads
// (drag in a current); eigenvalues of the symmetric part down to -(1e-9 + 2 x that) pass (noise,
// neutral directions such as a slack line lying on a frictionless seabed, benefit of the doubt for
// drag). Between that band and zero, a negative determinant (an odd number of real negative
// eigenvalues: a static divergence for any mass matrix) still marks the state unstable.
std::string stabilityCheck(const Model& model, StaticResidual& F, const VecX& x) {
  const int n = F.size(), nt = F.coordinates(), m = F.extra();
  VecX r(n);
  MatX J;
  F.centralJacobian(x, J);
  F(x, r);  // leave F at x
  const double W = F.weight(), L = model.length();
  MatX K(nt, nt);
  for (int i = 0; i < nt; ++i) {
    const bool is_delta = F.per() == 2 && i % 2 == 0;
    K.row(i) = -(is_delta ? W : W * L) * J.block(i, 0, 1, nt);
  }
  VecX s(nt);
  for (int i = 0; i < nt; ++i) s[i] = std::abs(K(i, i)) > 1e-300 ? 1.0 / std::sqrt(std::abs(K(i, i))) : 1.0;
  K = (s.asDiagonal() * K * s.asDiagonal()).eval();
  if (m > 0) {
    const MatX Ct = s.asDiagonal() * J.block(nt, 0, m, nt).transpose();  // nt x m
    Eigen::HouseholderQR<MatX> qr(Ct);
    const MatX R = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
    const double big = Ct.norm();
    for (int k = 0; k < m; ++k)
      if (!(std::abs(R(k, k)) > 1e-7 * big))  // central differences: ~1e-9 relative noise
        return "the end conditions are degenerate (their Jacobian has rank < " + std::to_string(m) +
               ", the end force is not determined): e.g. an inextensible line held at exactly its length, or "
               "folded at a joint straight below both its ends; move bottom.position or use axial flexibility";
    const MatX QtKQ = qr.householderQ().adjoint() * K * qr.householderQ();
    K = QtKQ.bottomRightCorner(nt - m, nt - m);
  }
  if (K.rows() == 0) return "";
  const double asym = 0.5 * (K - K.transpose()).norm();
  const MatX Ks = 0.5 * (K + K.transpose());
  auto definite = [&](double shift) {
    MatX A = Ks;
    A.diagonal().array() += shift;
    return Eigen::LLT<MatX>(A).info() == Eigen::Success;
  };
  constexpr double kFloor = 1e-9;
  if (definite(kFloor)) return "";
  std::ostringstream o;
  if (!definite(kFloor + 2.0 * asym)) {
    Eigen::SelfAdjointEigenSolver<MatX> es(Ks, Eigen::EigenvaluesOnly);
    o << "the equilibrium is unstable (the stiffness about it, scaled to a unit diagonal, has the eigenvalue "
      << es.eigenvalues()[0] << ", beyond its asymmetry " << asym << "): a balanced state, not a resting one "
      << "(e.g. a compressed or folded line)";
    return o.str();
  }
  if (Eigen::PartialPivLU<MatX>(K).determinant() < 0.0)
    return "the equilibrium is unstable (the stiffness about it has a negative determinant: a static divergence "
           "under the steady loads)";
  return "";
}

}  // namespace statics_detail

using statics_detail::StaticResidual;
using statics_detail::StaticTerms;

EquilibriumCheck checkEquilibrium(const Model& model, const StaticsProblem& problem, const Kinematics& kin,
                                  const Vec2& end_force, double t) {
  EquilibriumCheck c;
  std::ostringstream o;
  const int nb = model.bodies();
  bool finite = end_force.allFinite() && static_cast<int>(kin.size()) == nb;
  for (int i = 0; finite && i < nb; ++i) finite = std::isfinite(kin[i].phi) && std::isfinite(kin[i].delta);
  if (!finite) {
    c.message = "finite: the solution has non-finite coordinates or end force (NaN/Inf)";
    return c;
  }
  StaticTerms terms(model, t);
  StaticResidual F(model, problem, terms, t);
  VecX x = VecX::Zero(F.size()), r(F.size());
  F.fromKinematics(kin, x);
  F.setEndForce(end_force, x);
  F(x, r);
  c.residual = r.lpNorm<Eigen::Infinity>();
  const AlignedVector<Vec2> joints = F.jointForces();
  const Kinematics at = F.kinematics();
  // Loads (every term but the seabed) and contact forces (the seabed terms), per rfe.
  VecX Ql = VecX::Zero(model.dofs()), Qs = VecX::Zero(model.dofs());
  for (size_t k = 0; k < terms.terms().size(); ++k)
    terms.terms()[k]->addForces(model, nullptr, at, t, terms.isSeabed(k) ? Qs : Ql);
  c.load = end_force.norm();
  for (int i = 0; i < nb; ++i) c.load += Ql.segment<2>(4 * i).norm();
  double seabed_total = 0.0;
  int worst = -1;
  for (int i = 0; i < nb; ++i) {
    const double f = Qs.segment<2>(4 * i).norm();  // contacts at A_i and (rfe n) the end
    seabed_total += f;
    if (f > c.max_seabed_force) c.max_seabed_force = f, worst = i;
  }
  for (const Vec2& j : joints) c.max_joint_force = std::max(c.max_joint_force, j.norm());
  const double W = F.weight();
  if (!(c.residual <= problem.tolerance)) {
    o << "residual: the equilibrium residual " << c.residual << " (forces / line weight " << W
      << " N, with every term of the statics and the end force) exceeds initial.tolerance " << problem.tolerance;
  } else if (!(seabed_total <= kSeabedLoadFactor * c.load + problem.tolerance * W)) {
    const double level = terms.seabedLevel(), k = terms.seabedStiffness();
    const Vec2 p = worst == nb - 1 && at[nb - 1].end().y() < at[nb - 1].A.y() ? at[nb - 1].end() : at[worst].A;
    o << "seabed: the seabed carries " << seabed_total << " N, more than " << kSeabedLoadFactor
      << " x the line's load (" << c.load << " N): the line is pushed into it (deepest near rfe " << worst
      << ", " << level - p.y() << " m below seabed.level " << level << ", where the whole load would sink a point by "
      << c.load / k << " m)";
  } else if (!(c.max_joint_force <= kTensionLoadFactor * c.load + problem.tolerance * W)) {
    o << "tension: a joint carries " << c.max_joint_force << " N, more than " << kTensionLoadFactor
      << " x the line's load (" << c.load << " N)";
  } else {
    const std::string unstable = statics_detail::stabilityCheck(model, F, x);
    if (!unstable.empty()) o << "stability: " << unstable;
  }
  c.message = o.str();
  c.ok = c.message.empty();
  return c;
}

}  // namespace riser_sim
