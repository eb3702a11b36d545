#include "riser_sim/planar/modal.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "riser_sim/planar/chain_kinematics.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/independent_formulation.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "modal_linearisation.h"
#include "statics_residual.h"

namespace riser_sim {

namespace {

// θ ↔ kinematics of the chain hanging from A_0 (zero velocities), k = 2 (Δ, φ) or 1 (φ) per rfe.
class Chain {
 public:
  Chain(const Model& m, const statics_detail::StaticTerms& terms, const TermDataSet& data, const Vec2& top, double t)
      : model_(m), terms_(terms), data_(data), top_(top), t_(t) {
    k_ = m.options().axial_flexibility ? 2 : 1;
    kin_.resize(m.bodies());
    Q_.setZero(m.dofs());
  }
  int k() const { return k_; }
  int size() const { return k_ * model_.bodies(); }

  void pack(const Kinematics& kin, VecX& theta) const {
    theta.resize(size());
    for (int i = 0; i < model_.bodies(); ++i) {
      if (k_ == 2) theta[2 * i] = kin[i].delta;
      theta[k_ * i + k_ - 1] = kin[i].phi;
    }
  }
  const Kinematics& kinematics(const VecX& theta, const VecX* theta_dot = nullptr) {
    chainKinematics(model_, top_, Vec2::Zero(), theta.data(), theta_dot ? theta_dot->data() : nullptr, kin_);
    return kin_;
  }
  // Absolute forces of every term plus the dead end load at the end of rfe n (the line moving at θ').
  const VecX& absoluteForces(const VecX& theta, const Vec2& end_force, const VecX* theta_dot = nullptr) {
    kinematics(theta, theta_dot);
    Q_.setZero();
    for (size_t k = 0; k < terms_.terms().size(); ++k) terms_.terms()[k]->addForces(model_, data_.at(k), kin_, t_, Q_);
    const int n = model_.bodies() - 1;
    Q_.segment<4>(4 * n) += pointForce(kin_[n], model_.rfe(n).length, 1.0, end_force);
    return Q_;
  }
  // Q_θ = J^T Q_abs in O(n).
  void project(const VecX& Q, VecX& Qt) const {
    Qt.resize(size());
    projectToChain(model_, kin_, Q.data(), Qt.data());
  }
  void generalised(const VecX& theta, const Vec2& end_force, VecX& Qt) {
    project(absoluteForces(theta, end_force), Qt);
  }
  void generalised(const VecX& theta, const VecX& theta_dot, const Vec2& end_force, VecX& Qt) {
    project(absoluteForces(theta, end_force, &theta_dot), Qt);
  }

 private:
  const Model& model_;
  const statics_detail::StaticTerms& terms_;  // in a steady sea, as the statics
  const TermDataSet& data_;
  Vec2 top_;
  double t_;
  int k_;
  Kinematics kin_;
  VecX Q_;
};

// Displacements of A_0..A_n, end for a mode θ; kinetic-energy split along / normal to the line.
void modeShape(const Model& model, const Kinematics& kin, int k, const VecX& th, Mode& mode) {
  const int nb = model.bodies();
  mode.displacement.assign(nb + 1, Vec2::Zero());
  double along = 0.0, normal = 0.0;
  Vec2 dA = Vec2::Zero();
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics& b = kin[i];
    const Rfe& r = model.rfe(i);
    const double dd = k == 2 ? th[2 * i] : 0.0, dp = th[k * i + k - 1];
    mode.displacement[i] = dA;
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& q = r.part[p];
      const Vec2 v = dA + q.kappa * dd * b.e() + (q.s0 + q.kappa * b.delta) * dp * b.nrm();
      along += q.mass * std::pow(b.e().dot(v), 2);
      normal += q.mass * std::pow(b.nrm().dot(v), 2) + q.inertia * dp * dp;
    }
    dA += dd * b.e() + b.len * dp * b.nrm();
  }
  mode.displacement[nb] = dA;
  mode.axial_fraction = along + normal > 0.0 ? along / (along + normal) : 0.0;
  mode.character = mode.axial_fraction > 0.5 ? "axial" : "transverse";
  // Unit largest displacement, its largest component positive.
  double big = 0.0, comp = 0.0;
  for (const Vec2& d : mode.displacement) {
    big = std::max(big, d.norm());
    for (int c = 0; c < 2; ++c)
      if (std::abs(d[c]) > std::abs(comp)) comp = d[c];
  }
  if (big > 0.0) {
    const double scale = (comp < 0.0 ? -1.0 : 1.0) / big;
    for (Vec2& d : mode.displacement) d *= scale;
  }
}

}  // namespace

namespace modal_detail {

PlanarLinearisation linearise(const Model& model, const Kinematics& equilibrium, const Vec2& end_force,
                              const LinearisationOptions& options) {
  const int nb = model.bodies();
  PlanarLinearisation lin;
  // Terms with history (seabed anchors) start from the static state: contacts stick where they are.
  TermDataSet data(model);
  data.startRun(model, equilibrium);

  const Vec2 top = equilibrium[0].A;
  statics_detail::StaticTerms steady(model, options.time);  // no waves: modes about the still-water state
  if (options.current_factor != 1.0) steady.scaleCurrent(options.current_factor);
  Chain chain(model, steady, data, top, options.time);
  const int nt = chain.size(), k = chain.k();
  lin.k = k;
  VecX& theta0 = lin.theta;
  chain.pack(equilibrium, theta0);
  lin.kin = chain.kinematics(theta0);
  const Kinematics& kin0 = lin.kin;

  // Equilibrium check: residual generalised forces (forces / F, moments / (F L)) with F the largest
  // force any term applies.
  double F = std::max(model.totalMass() * std::abs(model.gravity()), end_force.norm());
  for (size_t k = 0; k < steady.terms().size(); ++k) {
    VecX Qa = VecX::Zero(model.dofs());
    steady.terms()[k]->addForces(model, data.at(k), kin0, options.time, Qa);
    for (int i = 0; i < nb; ++i) F = std::max(F, Qa.segment<3>(4 * i).lpNorm<Eigen::Infinity>());
  }
  Vec2& load = lin.load;
  load = end_force;
  VecX Q0t;
  chain.generalised(theta0, load, Q0t);
  lin.Ct.resize(nt, 2);
  for (int i = 0; i < nb; ++i) {
    if (k == 2) lin.Ct.row(2 * i) = kin0[i].e().transpose();
    lin.Ct.row(k * i + k - 1) = kin0[i].len * kin0[i].nrm().transpose();
  }
  if (options.solve_anchor) {
    // The anchor's reaction (when not given as end_force) is what balances Q_θ along the end
    // constraints' normals: C^T λ = -Q_θ in least squares; it joins the dead end load.
    const Vec2 lam = lin.Ct.colPivHouseholderQr().solve(-Q0t);
    load += lam;
    chain.generalised(theta0, load, Q0t);
  }
  double r0 = 0.0;
  for (int c = 0; c < nt; ++c) {
    const bool is_delta = k == 2 && c % 2 == 0;
    r0 = std::max(r0, std::abs(Q0t[c]) / (is_delta ? 1.0 : model.length()));
  }
  lin.residual = r0 > 0.0 ? r0 / F : 0.0;

  // Stiffness by central differences of Q_θ; damping (at rest) by central differences in θ'.
  MatX& K = lin.K;
  K.resize(nt, nt);
  VecX th(theta0), Qp, Qm;
  for (int c = 0; c < nt; ++c) {
    const bool is_delta = k == 2 && c % 2 == 0;
    const double h = options.fd_step * (is_delta ? model.segmentLength() : 1.0);
    th[c] = theta0[c] + h;
    chain.generalised(th, load, Qp);
    th[c] = theta0[c] - h;
    chain.generalised(th, load, Qm);
    th[c] = theta0[c];
    K.col(c) = -(Qp - Qm) / (2.0 * h);
  }
  if (options.damping) {
    lin.C.resize(nt, nt);
    VecX v = VecX::Zero(nt);
    for (int c = 0; c < nt; ++c) {
      const bool is_delta = k == 2 && c % 2 == 0;
      const double h = options.fd_step * (is_delta ? model.segmentLength() : 1.0);  // [1/s] or [m/s]
      v[c] = h;
      chain.generalised(theta0, v, load, Qp);
      v[c] = -h;
      chain.generalised(theta0, v, load, Qm);
      v[c] = 0.0;
      lin.C.col(c) = -(Qp - Qm) / (2.0 * h);
    }
  }

  // Mass matrix: the dense M_II of the independent formulation at the static state (θ' = 0).
  {
    IndependentFormulation f(model, 0.0);
    const std::unique_ptr<FormulationData> fd = f.makeData();
    VecX y = VecX::Zero(2 * nt), dy(2 * nt);
    y.head(nt) = theta0;
    PointMotion pm;
    pm.p = top;
    f.derivative(options.time, y, pm, dy, *fd);
    lin.M = f.massMatrix(*fd).selfadjointView<Eigen::Lower>();
  }
  return lin;
}

}  // namespace modal_detail

ModalResult computeModes(const Model& model, const Kinematics& equilibrium, const Vec2& end_force,
                         const ModalOptions& options) {
  const int nb = model.bodies();
  if (static_cast<int>(equilibrium.size()) != nb)
    throw std::invalid_argument("modal: the equilibrium has " + std::to_string(equilibrium.size()) +
                                " rfes, the model " + std::to_string(nb));
  if (options.modes < 1) throw std::invalid_argument("modes: must be >= 1");
  if (!(options.fd_step > 0.0)) throw std::invalid_argument("modal fd_step: must be > 0");

  ModalResult res;
  res.pinned = model.bottom() == BottomBoundary::kPinned;
  modal_detail::LinearisationOptions lo;
  lo.time = options.time;
  lo.fd_step = options.fd_step;
  lo.solve_anchor = res.pinned;
  modal_detail::PlanarLinearisation lin = modal_detail::linearise(model, equilibrium, end_force, lo);
  const Kinematics& kin0 = lin.kin;
  const int nt = static_cast<int>(lin.theta.size()), k = lin.k;
  res.coordinates = nt;
  for (int i = 0; i < nb; ++i) {
    res.points.push_back(kin0[i].A);
    res.arc_length.push_back(model.rfe(i).s_begin);
  }
  res.points.push_back(kin0[nb - 1].end());
  res.arc_length.push_back(model.length());
  res.equilibrium_residual = lin.residual;

  MatX K = std::move(lin.K);
  const double knorm = K.norm();
  res.asymmetry = knorm > 0.0 ? (K - K.transpose()).norm() / knorm : 0.0;
  K = 0.5 * (K + K.transpose()).eval();
  MatX M = std::move(lin.M);

  // Pinned bottom: orthonormal null space of the end-point Jacobian C (E' = C θ').
  MatX N;
  if (res.pinned) {
    Eigen::ColPivHouseholderQR<MatX> qr(lin.Ct);
    qr.setThreshold(1e-10);
    if (qr.rank() < 2)
      throw std::runtime_error(
          "modal: the pinned end's constraint Jacobian is singular (an inextensible line pinned at exactly "
          "its length is locked); use axial flexibility");
    const MatX Qfull = qr.householderQ();
    N = Qfull.rightCols(nt - 2);
    K = (N.transpose() * K * N).eval();
    M = (N.transpose() * M * N).eval();
    K = 0.5 * (K + K.transpose()).eval();
    M = 0.5 * (M + M.transpose()).eval();
  }
  res.dofs = static_cast<int>(K.rows());

  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(K, M);
  if (es.info() != Eigen::Success)
    throw std::runtime_error("modal: the generalised eigen-solve failed (mass matrix not positive definite?)");
  const int count = std::min(options.modes, res.dofs);
  for (int m = 0; m < count; ++m) {
    Mode mode;
    mode.omega2 = es.eigenvalues()[m];
    mode.omega = mode.omega2 > 0.0 ? std::sqrt(mode.omega2) : 0.0;
    mode.frequency = mode.omega / (2.0 * M_PI);
    mode.period = mode.omega > 0.0 ? 1.0 / mode.frequency : 0.0;
    mode.theta = res.pinned ? VecX(N * es.eigenvectors().col(m)) : VecX(es.eigenvectors().col(m));
    modeShape(model, kin0, k, mode.theta, mode);
    res.modes.push_back(std::move(mode));
  }
  res.stiffness = std::move(K);
  res.mass = std::move(M);
  return res;
}

ModalResult sceneModes(const Scene& scene, const ModalOptions& options, StaticsResult* statics) {
  if (scene.space != SpaceKind::kPlanar)
    throw std::invalid_argument("space: the modal analysis is planar; 'spatial' scenes have no modes yet");
  // About the static state: in the steady sea, as the statics (the waves at t = 0 would move the state and its drag).
  BuildOptions steady;
  steady.terms.steady_sea = true;
  std::shared_ptr<Model> model = buildModel(scene, steady);
  const InitialState init = solveInitialState(scene, *model, buildTopMotion(scene.top)->at(0.0).p, true);
  if (statics) *statics = init.statics;
  return computeModes(*model, init.kin, init.end_force, options);
}

}  // namespace riser_sim
