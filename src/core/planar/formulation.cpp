#include "riser_sim/planar/formulation.h"

#include "riser_sim/line/rfe_inertia.h"

namespace riser_sim {

FormulationData::FormulationData(const Formulation& owner, int bodies)
    : kin(bodies), owner_(&owner), energy_kin_(bodies), energy_M_(bodies, Mat4::Zero()) {
  reactions.joint.assign(bodies + 1, Vec2::Zero());
  energy_h_.setZero(4 * bodies);
}

double Formulation::kineticEnergy(double t, const VecX& y, const PointMotion& top, FormulationData& data) const {
  checkOwner(data);
  kinematics(y, top, data.energy_kin_);
  rfeMassBlocks(model_, data.energy_kin_, t, data.energy_M_, data.energy_h_);
  double T = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics& b = data.energy_kin_[i];
    const Vec4 v(b.A_dot.x(), b.A_dot.y(), b.delta_dot, b.phi_dot);
    T += 0.5 * v.dot(data.energy_M_[i] * v);
  }
  return T;
}

bool Formulation::evaluatedAt(double t, const VecX& y, const PointMotion& top, const FormulationData& data) const {
  return &data.owner() == this && data.t == t && data.top.p == top.p && data.top.v == top.v && data.top.a == top.a &&
         holdsState(y, data.kin);
}

void Formulation::linearize(double, const VecX&, const PointMotion&, FormulationData&) const {
  throw std::logic_error(name() + " formulation: no structured solves (linearize)");
}

void Formulation::factorShifted(double, FormulationData&) const {
  throw std::logic_error(name() + " formulation: no structured solves (factorShifted)");
}

void Formulation::solveShifted(const VecX&, VecX&, FormulationData&) const {
  throw std::logic_error(name() + " formulation: no structured solves (solveShifted)");
}

}  // namespace riser_sim
