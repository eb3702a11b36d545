#include "riser_sim/planar/chain_kinematics.h"

#include <cmath>

namespace riser_sim {

void chainKinematics(const Model& model, const Vec2& top, const Vec2& top_velocity, const double* theta,
                     const double* theta_dot, Kinematics& kin) {
  const int k = chainDofsPerRfe(model);
  Vec2 A = top, Ad = top_velocity;
  for (int i = 0; i < model.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = A;
    b.A_dot = Ad;
    b.delta = k == 2 ? theta[2 * i] : 0.0;
    b.phi = theta[k * i + k - 1];
    b.delta_dot = k == 2 && theta_dot ? theta_dot[2 * i] : 0.0;
    b.phi_dot = theta_dot ? theta_dot[k * i + k - 1] : 0.0;
    b.c = std::cos(b.phi);
    b.s = std::sin(b.phi);
    b.len = model.rfe(i).length + b.delta;
    const Vec2 e(b.c, b.s), n(-b.s, b.c);
    A += b.len * e;
    Ad += b.delta_dot * e + (b.len * b.phi_dot) * n;
  }
}

void projectToChain(const Model& model, const Kinematics& kin, const double* Q, double* Qt) {
  const int k = chainDofsPerRfe(model);
  Vec2 below = Vec2::Zero();  // net force on the rfes beyond rfe i
  for (int i = model.bodies() - 1; i >= 0; --i) {
    const BodyKinematics& b = kin[i];
    const double* q = Q + 4 * i;
    if (k == 2) Qt[2 * i] = q[kDelta] + b.e().dot(below);
    Qt[k * i + k - 1] = q[kPhi] + b.len * b.nrm().dot(below);
    below += Vec2(q[kX], q[kY]);
  }
}

}  // namespace riser_sim
