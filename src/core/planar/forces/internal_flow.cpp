#include "riser_sim/planar/forces/internal_flow.h"

#include <cmath>

namespace riser_sim {

void InternalFlow::addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  const double u = this->u(t), ud = spec_.acceleration;
  const int nb = model.bodies();
  const double c3 = 0.5 * rho_l_ * u * u / 3.0;
  for (int i = 0; i < nb; ++i) {
    const int ip = std::max(i - 1, 0), in = std::min(i + 1, nb - 1);
    const BodyKinematics &b = kin[i], &bp = kin[ip], &bn = kin[in];
    const double l1 = model.rfe(i).length1, l2 = model.rfe(i).length2;
    const double dpi = bp.phi - b.phi, dni = bn.phi - b.phi;  // φ_prev - φ_i, φ_next - φ_i
    const double sp = std::sin(dpi), cp = std::cos(dpi), sn = std::sin(dni), cn = std::cos(dni);
    const double C1 = l1 * l1 / 6.0, C2 = (l1 + b.delta) * l2 / 2.0 + l2 * l2 / 3.0;
    // Coefficients a of the rfe's velocities in T2 / (ρ_l u) and their time derivatives.
    const Vec2 P = 0.5 * l1 * (bp.e() + b.e()) + 0.5 * l2 * (b.e() + bn.e());
    const double K = 0.5 * l2 * (1.0 + cn), R = C1 * sp + C2 * sn;
    const Vec2 Pd = 0.5 * l1 * (bp.phi_dot * bp.nrm() + b.phi_dot * b.nrm()) +
                    0.5 * l2 * (b.phi_dot * b.nrm() + bn.phi_dot * bn.nrm());
    const double Kd = 0.5 * l2 * sn * (b.phi_dot - bn.phi_dot);
    const double Rd =
        C1 * cp * (bp.phi_dot - b.phi_dot) + 0.5 * l2 * b.delta_dot * sn + C2 * cn * (bn.phi_dot - b.phi_dot);
    // -(u' a + u a') on the rfe's own coordinates.
    double* q = Q.data() + 4 * i;
    const Vec2 fA = -rho_l_ * (ud * P + u * Pd);
    q[kX] += fA.x();
    q[kY] += fA.y();
    q[kDelta] += -rho_l_ * (ud * K + u * Kd);
    q[kPhi] += -rho_l_ * (ud * R + u * Rd);
    // +u ∂(Σ t2)/∂q and +∂T3/∂q, spread over φ_prev, φ_i, φ_next and Δ_i.
    const double ru = rho_l_ * u;
    const Vec2& Ad = b.A_dot;
    const double g_prev = Ad.dot(0.5 * l1 * bp.nrm()) + b.phi_dot * C1 * cp;
    const double g_self =
        Ad.dot(0.5 * (l1 + l2) * b.nrm()) + b.delta_dot * 0.5 * l2 * sn - b.phi_dot * (C1 * cp + C2 * cn);
    const double g_next = Ad.dot(0.5 * l2 * bn.nrm()) - b.delta_dot * 0.5 * l2 * sn + b.phi_dot * C2 * cn;
    Q[4 * ip + kPhi] += ru * g_prev - c3 * l1 * sp;
    Q[4 * i + kPhi] += ru * g_self + c3 * l1 * sp + c3 * l2 * sn;
    Q[4 * in + kPhi] += ru * g_next - c3 * l2 * sn;
    Q[4 * i + kDelta] += ru * b.phi_dot * 0.5 * l2 * sn;
  }
}

double InternalFlow::sumT2(const Model& model, const Kinematics& kin) const {
  const int nb = model.bodies();
  double s = 0.0;
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics &b = kin[i], &bp = kin[std::max(i - 1, 0)], &bn = kin[std::min(i + 1, nb - 1)];
    const double l1 = model.rfe(i).length1, l2 = model.rfe(i).length2;
    const Vec2 P = 0.5 * l1 * (bp.e() + b.e()) + 0.5 * l2 * (b.e() + bn.e());
    const double K = 0.5 * l2 * (1.0 + std::cos(b.phi - bn.phi));
    const double R = l1 * l1 / 6.0 * std::sin(bp.phi - b.phi) +
                     ((l1 + b.delta) * l2 / 2.0 + l2 * l2 / 3.0) * std::sin(bn.phi - b.phi);
    s += b.A_dot.dot(P) + b.delta_dot * K + b.phi_dot * R;
  }
  return s;
}

double InternalFlow::shapeF(const Model& model, const Kinematics& kin) const {
  const int nb = model.bodies();
  double f = 0.0;
  for (int i = 0; i < nb; ++i) {
    const BodyKinematics &b = kin[i], &bp = kin[std::max(i - 1, 0)], &bn = kin[std::min(i + 1, nb - 1)];
    const double l1 = model.rfe(i).length1, l2 = model.rfe(i).length2;
    f += l1 * (2.0 / 3.0 + std::cos(bp.phi - b.phi) / 3.0) + l2 * (2.0 / 3.0 + std::cos(b.phi - bn.phi) / 3.0);
  }
  return f;
}

double InternalFlow::potentialEnergyAt(const Model& model, const TermData*, const Kinematics& kin, double t) const {
  const double u = this->u(t);
  return -0.5 * rho_l_ * u * u * shapeF(model, kin);
}

double InternalFlow::power(const Model& model, const TermData*, const Kinematics& kin, double t) const {
  const double u = this->u(t);
  return -spec_.acceleration * rho_l_ * (sumT2(model, kin) + u * shapeF(model, kin));
}

template <class Visit>
void PipeFlow::forces(const Model& model, const Kinematics& kin, double t, Visit&& visit) const {
  const double u = spec_.velocity + spec_.acceleration * t, ud = spec_.acceleration;
  for (int i = 0; i < model.bodies(); ++i) {
    const BodyKinematics& b = kin[i];
    const Rfe& r = model.rfe(i);
    if (i > 0) visit(i, 0.0, 0.0, Vec2(-rho_l_ * u * u * (b.e() - kin[i - 1].e())));
    const double lens[2] = {r.length1, r.length2}, s0[2] = {0.5 * r.length1, r.length1 + 0.5 * r.length2};
    for (int p = 0; p < 2; ++p)
      visit(i, s0[p], p == 0 ? 0.0 : 1.0, Vec2(-rho_l_ * lens[p] * (2.0 * u * b.phi_dot * b.nrm() + ud * b.e())));
    visit(i, r.length1, 1.0, Vec2(-2.0 * rho_l_ * u * b.delta_dot * b.e()));
  }
}

void PipeFlow::addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  forces(model, kin, t, [&](int i, double s0, double kappa, const Vec2& F) {
    Q.segment<4>(4 * i) += pointForce(kin[i], s0, kappa, F);
  });
}

double PipeFlow::addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                                   VecX& Q) const {
  double pw = 0.0;
  forces(model, kin, t, [&](int i, double s0, double kappa, const Vec2& F) {
    Q.segment<4>(4 * i) += pointForce(kin[i], s0, kappa, F);
    pw += F.dot(kin[i].velocity(s0, kappa));
  });
  return pw;
}

double PipeFlow::power(const Model& model, const TermData*, const Kinematics& kin, double t) const {
  double pw = 0.0;
  forces(model, kin, t,
         [&](int i, double s0, double kappa, const Vec2& F) { pw += F.dot(kin[i].velocity(s0, kappa)); });
  return pw;
}

}  // namespace riser_sim
