#include "riser_sim/spatial/independent_formulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

namespace {

using Mat32 = Eigen::Matrix<double, 3, 2>;

// Orthonormal frame (t_1, t_2, d) with d the given unit vector; t_1 from `hint` (any vector not along d).
Mat3 frameAround(const Vec3& d, const Vec3& hint) {
  Vec3 t1 = hint - hint.dot(d) * d;
  if (t1.norm() < 0.5) {  // hint nearly along d: the world axis least aligned with d
    Vec3 a = Vec3::Zero();
    int k = 0;
    d.cwiseAbs().minCoeff(&k);
    a[k] = 1.0;
    t1 = a - a.dot(d) * d;
  }
  t1.normalize();
  Mat3 F;
  F.col(0) = t1;
  F.col(1) = d.cross(t1);
  F.col(2) = d;
  return F;
}

// Natural 7x7 mass block of rfe r at Δ with director e (the parts' m, m_k, S, S_k, I_A), as
// NaturalFormulation's dense path with axial flexibility.
Mat7 massBlock(const Rfe& r, double delta, const Vec3& e) {
  const double m = r.mass, mk = r.mass_k, S = r.firstMoment(delta), Sk = r.firstMomentK(delta);
  Mat7 M = Mat7::Zero();
  M.block<3, 3>(kA, kA).diagonal().setConstant(m);
  M.block<3, 3>(kA, kE).diagonal().setConstant(S);
  M.block<3, 3>(kE, kA).diagonal().setConstant(S);
  M.block<3, 3>(kE, kE).diagonal().setConstant(r.inertiaAboutA(delta));
  M.block<3, 1>(kA, kDelta3) = mk * e;
  M.block<1, 3>(kDelta3, kA) = mk * e.transpose();
  M.block<3, 1>(kE, kDelta3) = Sk * e;
  M.block<1, 3>(kDelta3, kE) = Sk * e.transpose();
  M(kDelta3, kDelta3) = mk;
  return M;
}

}  // namespace

// llt sized in place: Eigen's LLT(Index) leaves its info unset, so it must not be copied from.
IndependentData3::IndependentData3(const Model3& model, int k, int spins)
    : kin(model.bodies()), llt(k * model.bodies() + spins) {
  const int nb = model.bodies(), p = k * nb + spins;
  reactions.joint.assign(nb + 1, Vec3::Zero());
  Q.setZero(model.dofs());
  G.assign(nb, Mat32::Zero());
  C.assign(nb, Mat3::Zero());
  D.assign(nb, Mat3::Zero());
  e_bias.assign(nb, Vec3::Zero());
  A_bias.assign(nb + 1, Vec3::Zero());
  M7.assign(nb, Mat7::Zero());
  f.assign(nb, Vec7::Zero());
  M.setZero(p, p);
  rhs.setZero(p);
  theta_dd.setZero(p);
  Phi.setZero(3, p);
  X.setZero(p, 3);
  for (const auto& term : model.terms())
    if (term->hasInertia()) added.assign(nb, AddedMass3());
  if (model.hasTorsion()) {
    twist.resize(nb);
    phi.assign(nb, 0.0);
    omega.assign(nb, 0.0);
    conn.assign(nb, Vec3::Zero());
  }
}

IndependentFormulation3::IndependentFormulation3(const Model3& model, double stabilization)
    : model_(model),
      omega_(stabilization),
      k_(model.options().axial_flexibility ? 3 : 2),
      ku_(model.options().axial_flexibility ? 1 : 0),
      s0_(spatial::firstSpin(model)),
      nt_(model.hasTorsion() ? model.bodies() - s0_ : 0) {
  if (model.bottomMoves())
    throw std::invalid_argument("spatial independent formulation: a fixed or free bottom only (not a moving one)");
}

double IndependentFormulation3::constraintError(const Kinematics3& kin) const {
  return model_.bottom() == BottomBoundary::kPinned ? (kin.back().end() - model_.bottomPoint()).norm() : 0.0;
}

void IndependentFormulation3::packState(const Kinematics3& kin, SphereCharts& charts, VecX& y,
                                        const HangOff& hang_off) const {
  const int nb = model_.bodies(), p = positionSize();
  charts.frame.resize(nb);
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics3& b = kin[i];
    const Vec3 e = b.e.normalized();
    charts.frame[i] = frameAround(e, Vec3::UnitX());
    double* q = y.data() + k_ * i;
    double* v = y.data() + p + k_ * i;
    if (ku_) q[0] = b.delta, v[0] = b.delta_dot;
    q[ku_] = q[ku_ + 1] = 0.0;
    v[ku_] = charts.frame[i].col(0).dot(b.e_dot);  // at u = 0: e' = T u'
    v[ku_ + 1] = charts.frame[i].col(1).dot(b.e_dot);
  }
  if (nt_ == 0) return;
  charts.twist.centre.assign(nb, Vec3::Zero());
  charts.twist.ref.assign(nb, Vec3::Zero());
  charts.twist.mref.assign(nb - 1, 0.0);
  charts.kin = kin;
  initTwistFrames(kin, charts.twist, model_.bendingAxis(), hang_off);
  y.segment(k_ * nb, nt_).setZero();
  y.segment(p + k_ * nb, nt_).setZero();
}

void IndependentFormulation3::kinematics(const VecX& y, const SphereCharts& charts, const PointMotion3& top,
                                         Kinematics3& kin) const {
  const int p = positionSize();
  Vec3 A = top.p, Ad = top.v;
  for (int i = 0; i < model_.bodies(); ++i) {
    const double* q = y.data() + k_ * i;
    const double* v = y.data() + p + k_ * i;
    const Mat3& F = charts.frame[i];
    const Vec3 w = F.col(2) + q[ku_] * F.col(0) + q[ku_ + 1] * F.col(1);
    const Vec3 wd = v[ku_] * F.col(0) + v[ku_ + 1] * F.col(1);
    const double r = w.norm();
    BodyKinematics3& b = kin[i];
    b.A = A;
    b.A_dot = Ad;
    b.delta = ku_ ? q[0] : 0.0;
    b.delta_dot = ku_ ? v[0] : 0.0;
    b.e = w / r;
    b.e_dot = (wd - b.e.dot(wd) * b.e) / r;
    b.len = model_.rfe(i).length + b.delta;
    A = b.end();
    Ad = b.endVelocity();
  }
}

double IndependentFormulation3::kineticEnergy(const Kinematics3& kin) const {
  double T = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    const Rfe& r = model_.rfe(i);
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      T += 0.5 * part.mass * kin[i].velocity(part.s0, part.kappa).squaredNorm() +
           0.5 * part.inertia * kin[i].e_dot.squaredNorm();
    }
  }
  return T;
}

// Local coordinates of rfe i are (Δ, u_1, u_2), of which θ_i keeps the last k_ (Δ dropped when
// inextensible): c0 = 3 - k_ is the first kept one. L_i = ∂[Δ'; e']/∂(Δ', u') = [1 0; 0 G],
// C_i = ∂E_i'/∂(Δ', u') = [e, len G] (relative to A_i'), with the top at rest and θ'' = 0 giving the biases.
void IndependentFormulation3::forces(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top,
                                     IndependentData3& d) const {
  assemble(t, y, charts, top, d, false);
}

void IndependentFormulation3::derivative(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top,
                                         VecX& dy, IndependentData3& d) const {
  assemble(t, y, charts, top, d, true);
  solve(y, dy, d);
}

void IndependentFormulation3::assemble(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top,
                                       IndependentData3& d, bool mass) const {
  const int nb = model_.bodies(), p = positionSize(), c0 = 3 - k_;
  d.t = t;
  d.top = top;
  kinematics(y, charts, top, d.kin);
  d.Q.setZero();
  d.term_power = 0.0;
  for (const auto& term : model_.terms()) d.term_power += term->addForcesAndPower(model_, d.kin, t, d.Q);
  if (!d.added.empty()) {
    std::fill(d.added.begin(), d.added.end(), AddedMass3());
    for (const auto& term : model_.terms())
      if (term->hasInertia()) term->addInertia(model_, d.kin, d.added);
  }
  if (nt_ > 0) addTwistForces(y, charts, d);

  // Per rfe: G, the e'' bias of the gnomonic chart, C, the natural acceleration biases and f = Q - h - M7 b.
  Vec3 Ab = top.a;
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics3& b = d.kin[i];
    const Rfe& rf = model_.rfe(i);
    const Mat3& F = charts.frame[i];
    const double* q = y.data() + k_ * i;
    const double* v = y.data() + p + k_ * i;
    const double r = (F.col(2) + q[ku_] * F.col(0) + q[ku_ + 1] * F.col(1)).norm();
    const Vec3 wd = v[ku_] * F.col(0) + v[ku_ + 1] * F.col(1);
    const Mat3 P = Mat3::Identity() - b.e * b.e.transpose();
    d.G[i] = P * F.leftCols<2>() / r;
    // e = w/|w|: e'' = P w''/r - (2 (e·w') e' + (e'·w') e)/r.
    d.e_bias[i] = -(2.0 * b.e.dot(wd) * b.e_dot + b.e_dot.dot(wd) * b.e) / r;
    d.C[i].col(0) = b.e;
    d.C[i].rightCols<2>() = b.len * d.G[i];
    d.A_bias[i] = Ab;
    Ab += 2.0 * b.delta_dot * b.e_dot + b.len * d.e_bias[i];

    Mat7& M7 = d.M7[i];
    M7 = massBlock(rf, b.delta, b.e);
    Vec7 bias = Vec7::Zero();
    bias.segment<3>(kA) = d.A_bias[i];
    bias.segment<3>(kE) = d.e_bias[i];
    Vec7 h;
    const double w2 = 2.0 * b.delta_dot, Sk = rf.firstMomentK(b.delta);
    h.segment<3>(kA) = w2 * rf.mass_k * b.e_dot;
    h[kDelta3] = w2 * rf.mass_k * b.e.dot(b.e_dot);
    h.segment<3>(kE) = w2 * Sk * b.e_dot;
    if (!d.added.empty()) {
      addAddedMassBlock(d.added[i], b, true, M7);
      addAddedVelocityTerms(d.added[i], b, h.data());
    }
    d.f[i] = d.Q.segment<7>(kDofPerBody3 * i) - h - M7 * bias;
  }
  d.A_bias[nb] = Ab;  // E_n'' at θ'' = 0

  // M_θ: (j, k) blocks C_jᵀ D_k for j < k, D_k = M_{>k} C_k + M7_k(A, Δe) L_k (M_{>k} = Σ_{i>k} M7_i(A, A):
  // m_{>k} I without added mass); diagonal C_kᵀ M_{>k} C_k + L_kᵀ M7_k(Δe, Δe) L_k. Right side
  // C_jᵀ Σ_{i>j} f_i(A) + L_jᵀ f_j(Δe).
  Mat3 m_after = Mat3::Zero();
  Vec3 fA_after = Vec3::Zero();
  for (int kb = nb - 1; kb >= 0; --kb) {
    Eigen::Matrix<double, 4, 3> L = Eigen::Matrix<double, 4, 3>::Zero();
    L(0, 0) = 1.0;
    L.bottomRightCorner<3, 2>() = d.G[kb];
    const Mat7& M7 = d.M7[kb];
    const Mat3& C = d.C[kb];
    d.D[kb] = m_after * C + M7.block<3, 4>(kA, kDelta3) * L;
    const Vec3 r = C.transpose() * fA_after + L.transpose() * d.f[kb].segment<4>(kDelta3);
    for (int a = 0; a < k_; ++a) d.rhs[k_ * kb + a] = r[c0 + a];
    if (mass) {
      const Mat3 diag = C.transpose() * m_after * C + L.transpose() * M7.block<4, 4>(kDelta3, kDelta3) * L;
      for (int a = 0; a < k_; ++a)
        for (int c = 0; c < k_; ++c) d.M(k_ * kb + a, k_ * kb + c) = diag(c0 + a, c0 + c);
    }
    m_after += M7.block<3, 3>(kA, kA);
    fA_after += d.f[kb].segment<3>(kA);
    for (int a = 0; a < k_; ++a) d.Phi.col(k_ * kb + a) = C.col(c0 + a);  // E_n' = top' + Σ C_j θ'_j
  }
  for (int kb = 1; kb < nb && mass; ++kb)
    for (int j = 0; j < kb; ++j) {
      const Mat3 blk = d.C[j].transpose() * d.D[kb];
      for (int a = 0; a < k_; ++a)
        for (int c = 0; c < k_; ++c) d.M(k_ * kb + c, k_ * j + a) = d.M(k_ * j + a, k_ * kb + c) = blk(c0 + a, c0 + c);
    }
  if (nt_ > 0) addSpinInertia(y, charts, d);  // without `mass` its M entries are left as garbage, unused
}

void IndependentFormulation3::solve(const VecX& y, VecX& dy, IndependentData3& d) const {
  const int nb = model_.bodies(), p = positionSize(), c0 = 3 - k_;
  d.llt.compute(d.M);
  d.theta_dd = d.llt.solve(d.rhs);
  // Pinned: M θ'' = r + Φᵀ μ, Φ θ'' = γ (Baumgarte on c = E_n - p_b) -> (Φ M⁻¹ Φᵀ) μ = γ - Φ M⁻¹ r.
  Vec3 mu = Vec3::Zero();
  d.constraint_error = 0.0;
  if (model_.bottom() == BottomBoundary::kPinned) {
    const Vec3 c = d.kin[nb - 1].end() - model_.bottomPoint(), cd = d.kin[nb - 1].endVelocity();
    const Vec3 gamma = -d.A_bias[nb] - 2.0 * omega_ * cd - omega_ * omega_ * c;
    d.X = d.llt.solve(d.Phi.transpose());
    const Mat3 S = d.Phi * d.X;
    mu = S.llt().solve(gamma - d.Phi * d.theta_dd);
    d.theta_dd += d.X * mu;
    d.constraint_error = c.norm();
  }

  dy.head(p) = y.segment(p, p);
  dy.segment(p, p) = d.theta_dd;

  // Top reaction (force of the line on A_0): λ_0 = Σ_i (Q - h - M7 q'')_A with q''_i = B_i θ'' + b_i.
  Vec3 lambda0 = Vec3::Zero(), Add = Vec3::Zero();  // Add: A_i'' - A_bias_i
  for (int i = 0; i < nb; ++i) {
    Vec3 loc = Vec3::Zero();  // (Δ'', u'')
    for (int a = 0; a < k_; ++a) loc[c0 + a] = d.theta_dd[k_ * i + a];
    Vec7 qdd = Vec7::Zero();
    qdd.segment<3>(kA) = Add;
    qdd[kDelta3] = loc[0];
    qdd.segment<3>(kE) = d.G[i] * loc.tail<2>();
    lambda0 += (d.f[i] - d.M7[i] * qdd).segment<3>(kA);
    Add += d.C[i] * loc;
  }
  // The anchor's force μ on the line at E_n enters the sum of the A rows too.
  d.reactions.top = lambda0 + mu;
  d.reactions.joint[0] = d.reactions.top;
  d.reactions.bottom = -mu;
  d.reactions.joint[nb] = mu;
}

int IndependentFormulation3::recentre(VecX& y, SphereCharts& charts, double threshold) const {
  const int p = positionSize();
  int moved = 0;
  for (int i = 0; i < model_.bodies(); ++i) {
    double* q = y.data() + k_ * i;
    double* v = y.data() + p + k_ * i;
    if (std::hypot(q[ku_], q[ku_ + 1]) <= threshold) continue;
    Mat3& F = charts.frame[i];
    const Vec3 w = F.col(2) + q[ku_] * F.col(0) + q[ku_ + 1] * F.col(1);
    const Vec3 wd = v[ku_] * F.col(0) + v[ku_ + 1] * F.col(1);
    const double r = w.norm();
    const Vec3 e = w / r, ed = (wd - e.dot(wd) * e) / r;
    F = frameAround(e, F.col(0));
    q[ku_] = q[ku_ + 1] = 0.0;
    v[ku_] = F.col(0).dot(ed);
    v[ku_ + 1] = F.col(1).dot(ed);
    ++moved;
  }
  charts.switches += moved;
  if (moved > 0 && nt_ > 0) recentreTwist(y, charts);
  return moved;
}

// ---------------------------------------------------------------------------------------------

IndependentSimulator3::IndependentSimulator3(std::shared_ptr<const Model3> model, std::shared_ptr<const TopMotion3> top,
                                             IntegratorKind kind, const IntegratorOptions& options,
                                             double stabilization)
    : model_(std::move(model)),
      top_(std::move(top)),
      formulation_(*model_, stabilization),
      data_(formulation_.makeData()),
      kin_(model_->bodies()) {
  IntegratorOptions o = options;
  o.jacobian = JacobianKind::kDense;  // no structured solves here
  integrator_ = makeIntegrator(kind, o);
  const int n = 2 * formulation_.positionSize() + 1;
  y_.setZero(n);
  dy_.setZero(n);
  charts_.frame.assign(model_->bodies(), Mat3::Identity());
  integrator_->reset(StateLayout{n, formulation_.positionSize()});
}

void IndependentSimulator3::reset(const Kinematics3& kin, double t0) {
  t_ = t0;
  y_.setZero();
  charts_.switches = 0;
  formulation_.packState(kin, charts_, y_);
  if (model_->hasTorsion()) holdHangOff(charts_.twist, top_->at(t0).R);
  integrator_->restart();
}

void IndependentSimulator3::setTwist(const VecX& theta, const VecX& omega) {
  formulation_.setSpins(theta, omega, y_);
  integrator_->restart();
}

void IndependentSimulator3::rhs(double t, const VecX& y, VecX& dy) {
  const PointMotion3 top = top_->at(t);
  if (model_->hasTorsion()) turnHangOff(charts_.twist, top.R, top.w, firstSpin(*model_) > 0);
  formulation_.derivative(t, y, charts_, top, dy, *data_);
  dy[dy.size() - 1] = -data_->reactions.top.dot(top.v) + data_->term_power;
}

bool IndependentSimulator3::step(double h) {
  const bool ok = integrator_->step(*this, t_, y_, h);
  t_ += h;
  if (model_->hasTorsion()) {  // the hang-off's frame at t_ (the stages left it at theirs), the twists' branches
    const PointMotion3 top = top_->at(t_);
    turnHangOff(charts_.twist, top.R, top.w, firstSpin(*model_) > 0);
    formulation_.refreshTwist(y_, charts_);
  }
  // Chart switches between steps only: the state moved under the integrator.
  if (formulation_.recentre(y_, charts_, threshold_) > 0) integrator_->restart();
  return ok && y_.allFinite();
}

void IndependentSimulator3::positions(AlignedVector<Vec3>& p) const {
  kinematics(kin_);
  const int nb = model_->bodies();
  for (int i = 0; i < nb; ++i) p[i] = kin_[i].A;
  p[nb] = kin_[nb - 1].end();
}

double IndependentSimulator3::constraintError() const {
  kinematics(kin_);
  return formulation_.constraintError(kin_);
}

double IndependentSimulator3::kineticEnergy() const {
  kinematics(kin_);
  double T = formulation_.kineticEnergy(kin_) + formulation_.spinKineticEnergy(y_, charts_, kin_);
  for (const auto& term : model_->terms()) T += term->kineticEnergy(*model_, kin_);
  return T;
}

double IndependentSimulator3::potentialEnergy() const {
  kinematics(kin_);
  double v = formulation_.twistEnergy(y_, charts_, kin_, *data_);
  for (const auto& term : model_->terms()) v += term->potentialEnergy(*model_, kin_, t_);
  return v;
}

const IndependentData3& IndependentSimulator3::evaluate() {
  rhs(t_, y_, dy_);
  return *data_;
}

}  // namespace spatial
}  // namespace riser_sim
