#include "riser_sim/spatial/forces/mass_damping.h"

namespace riser_sim {
namespace spatial {

void MassDamping::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  sweep(model, kin, &Q);
}

double MassDamping::power(const Model3& model, const Kinematics3& kin, double) const {
  return sweep(model, kin, nullptr);
}

void MassDamping::addStiffness(const Model3& model, const Kinematics3& kin, double, Stiffness3& S) const {
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      const Eigen::Matrix<double, 3, 7> J = pointJacobian(kin[i], part.s0, part.kappa);
      S.C_diag[i] += (alpha_ * part.mass) * J.transpose() * J;
      S.C_diag[i].block<3, 3>(kE, kE) += (alpha_ * part.inertia) * Mat3::Identity();
    }
  }
}

double MassDamping::sweep(const Model3& model, const Kinematics3& kin, VecX* Q) const {
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics3& b = kin[i];
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      const Vec3 v = b.velocity(part.s0, part.kappa);
      const Vec3 F = -alpha_ * part.mass * v;
      const Vec3 C = -alpha_ * part.inertia * b.e_dot;
      if (Q) {
        double* q = Q->data() + kDofPerBody3 * i;
        addPointForce(b, part.s0, part.kappa, F, q);
        for (int k = 0; k < 3; ++k) q[kE + k] += C[k];
      }
      pw += F.dot(v) + C.dot(b.e_dot);
    }
  }
  return pw;
}

}  // namespace spatial
}  // namespace riser_sim
