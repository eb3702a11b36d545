// checkEquilibrium(): what a statics solution must satisfy before it is reported as one.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <sstream>

#include "modal_linearisation.h"
#include "riser_sim/run/linear_stability.h"
#include "statics_residual.h"

namespace riser_sim {
namespace statics_detail {

// The equilibrium is stable when its linearisation (the modal analysis's: K = -∂Q_θ/∂θ with the seabed's
// contacts sticking, C = -∂Q_θ/∂θ' from drag and damping, M of the independent formulation), on the motions that
// keep the end conditions (the null space of their Jacobian), has no growing mode (linear_stability.h).
std::string stabilityCheck(const Model& model, const StaticsProblem& problem, const Kinematics& kin,
                           const Vec2& end_force, double t, double current_factor) {
  using Kind = StaticsProblem::Kind;
  modal_detail::LinearisationOptions lo;
  lo.time = t;
  lo.current_factor = current_factor;
  lo.damping = true;
  const modal_detail::PlanarLinearisation lin = modal_detail::linearise(model, kin, end_force, lo);
  const int nt = static_cast<int>(lin.K.rows());
  const int m = problem.kind == Kind::kHanging ? 0 : problem.kind == Kind::kEndDisplaced ? 1 : 2;
  MatX N;
  if (m > 0) {
    // Jacobi-scaled rows (as K's), so the rank test sees the end conditions' geometry, not the units.
    VecX s(nt);
    for (int i = 0; i < nt; ++i) s[i] = std::abs(lin.K(i, i)) > 1e-300 ? 1.0 / std::sqrt(std::abs(lin.K(i, i))) : 1.0;
    const MatX Ct = s.asDiagonal() * lin.Ct.leftCols(m);
    Eigen::HouseholderQR<MatX> qr(Ct);
    const MatX R = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
    const double big = Ct.norm();
    for (int k = 0; k < m; ++k)
      if (!(std::abs(R(k, k)) > 1e-7 * big))  // central differences: ~1e-9 relative noise
        return "the end conditions are degenerate (their Jacobian has rank < " + std::to_string(m) +
               ", the end force is not determined): e.g. an inextensible line held at exactly its length, or "
               "folded at a joint straight below both its ends; move bottom.position or use axial flexibility";
    // The allowed motions: the null space of the unscaled Jacobian (orthonormal).
    Eigen::HouseholderQR<MatX> q0(lin.Ct.leftCols(m));
    N = MatX(q0.householderQ()).rightCols(nt - m);
  }
  // Noise of K's central differences (steps 1e-6): ~1e-9 of its entries (measured).
  return linearStability(lin.K, lin.C, lin.M, N, 1e-9).describe();
}

// Seabed geometries without a resting state (empty if none applies). An anchor deeper in the seabed
// than the whole line's weight could sink it is buried. A heavy line without bending stiffness that
// reaches the seabed lies on it in a straight run from the touchdown: if it is longer than the way down
// to the seabed and along it to the end (and up to an anchor), its end can only be held there by pushing
// the laid part back, folding it (a real chain would pile up; these rods are then balanced in
// compression). A pipe with bending stiffness can arch up instead: left to the solver and the checks.
std::string seabedGeometry(const Model& model, const StaticsProblem& p, const StaticTerms& terms) {
  using Kind = StaticsProblem::Kind;
  const double level = terms.seabedLevel(), k = terms.seabedStiffness(), L = model.length();
  if (!(k > 0.0) || p.kind == Kind::kHanging || !(netWeightPerLength(model, terms, p.top) > 0.0)) return "";
  const double h = p.top.y() - level;
  const bool chain = !model.hasBending();
  std::ostringstream o;
  if (p.kind == Kind::kEndDisplaced && chain && h > 0.0 && h + std::abs(p.end_dx) < L)
    o << "initial.end_dx: " << p.end_dx << " m, but the line (line.length " << L << " m) is longer than the way "
      << "down to seabed.level " << level << " m and along it to the end (" << h + std::abs(p.end_dx)
      << " m): its end cannot be held there without folding the line on the seabed; use a larger |end_dx| or "
         "initial.type hanging";
  if (p.kind == Kind::kBetweenPoints) {
    const double W = model.totalMass() * std::abs(model.gravity());
    const double ha = p.end_point.y() - level;
    if (ha < -2.0 * W / k)
      o << "bottom.position: " << -ha << " m below seabed.level " << level << " m, deeper than the whole line's "
        << "weight could sink it (" << 2.0 * W / k << " m with seabed.stiffness_normal " << k << " N/m): buried";
    else if (chain && h > 0.0 && h + std::abs(p.end_point.x() - p.top.x()) + std::max(ha, 0.0) < L)
      o << "bottom.position: the line (line.length " << L << " m) is longer than the way down to seabed.level " << level
        << " m, along it and up to the anchor (" << h + std::abs(p.end_point.x() - p.top.x()) + std::max(ha, 0.0)
        << " m): it would have to fold on the seabed; move the anchor farther from the top";
  }
  return o.str();
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
  // The bending springs see φ_i - φ_{i-1} as it is, not modulo 2π: Newton can turn an rfe a full turn past its
  // neighbour, where the spring holds a moment k (Δφ ∓ 2π) no geometry has (the rfes would fold through each
  // other to get there).
  int folded = 0;
  double turn = 0.0;
  for (int i = 1; i < nb; ++i)
    if (model.bendingStiffness(i) > 0.0 && std::abs(at[i].phi - at[i - 1].phi) > std::abs(turn))
      turn = at[i].phi - at[i - 1].phi, folded = i;
  if (std::abs(turn) > M_PI) {
    o << "fold: rfe " << folded << " is turned " << turn << " rad from rfe " << folded - 1
      << " (past pi: the bending spring between them is wound a full turn, as if the rfes had folded through each "
         "other), not a state of the line";
  } else if (!(c.residual <= problem.tolerance)) {
    o << "residual: the equilibrium residual " << c.residual << " (forces / line weight " << W
      << " N, with every term of the statics and the end force) exceeds initial.tolerance " << problem.tolerance;
  } else if (!(seabed_total <= kSeabedLoadFactor * c.load + problem.tolerance * W)) {
    const double level = terms.seabedLevel(), k = terms.seabedStiffness();
    const Vec2 p = worst == nb - 1 && at[nb - 1].end().y() < at[nb - 1].A.y() ? at[nb - 1].end() : at[worst].A;
    o << "seabed: the seabed carries " << seabed_total << " N, more than " << kSeabedLoadFactor
      << " x the line's load (" << c.load << " N): the line is pushed into it (deepest near rfe " << worst << ", "
      << level - p.y() << " m below seabed.level " << level << ", where the whole load would sink a point by "
      << c.load / k << " m)";
  } else if (!(c.max_joint_force <= kTensionLoadFactor * c.load + problem.tolerance * W)) {
    o << "tension: a joint carries " << c.max_joint_force << " N, more than " << kTensionLoadFactor
      << " x the line's load (" << c.load << " N)";
  } else {
    const std::string unstable = statics_detail::stabilityCheck(model, problem, at, end_force, t);
    if (!unstable.empty()) o << "stability: " << unstable;
  }
  c.message = o.str();
  c.ok = c.message.empty();
  return c;
}

}  // namespace riser_sim
