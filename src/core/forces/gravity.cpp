#include "riser_sim/forces/gravity.h"

namespace riser_sim {

void Gravity::addForces(const Model& model, const Kinematics& kin, double, VecX& Q) const {
  const double g = model.gravity();
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics& b = kin[i];
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      Q.segment<4>(4 * i) += pointForce(b, part.s0, part.kappa, Vec2(0.0, -part.mass * g));
    }
  }
}

double Gravity::potentialEnergy(const Model& model, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    for (int p = 0; p < r.num_parts; ++p)
      v += r.part[p].mass * model.gravity() * kin[i].point(r.part[p].s0, r.part[p].kappa).y();
  }
  return v;
}

}  // namespace riser_sim
