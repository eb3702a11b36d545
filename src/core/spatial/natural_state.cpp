// NaturalFormulation: measures of a state and its projection (the kinetic energy, the joint gaps, the
// distance from the unit-length manifold).
#include <algorithm>
#include <cmath>

#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

double NaturalFormulation::kineticEnergy(const VecX& y) const {
  double T = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    const Rfe& r = model_.rfe(i);
    const BodyKinematics3 b = body(y, i);
    for (int p = 0; p < r.num_parts; ++p) {
      const RigidPart& part = r.part[p];
      T += 0.5 * part.mass * b.velocity(part.s0, part.kappa).squaredNorm() + 0.5 * part.inertia * b.e_dot.squaredNorm();
    }
  }
  const int nt = twistDofs();
  for (int i = firstSpin(model_); i < nt; ++i) {
    const double w = y[positionSize() + model_.dofs() + i];
    T += 0.5 * polarInertia(model_, i) * w * w;
  }
  return T;
}

double NaturalFormulation::constraintError(const VecX& y, const PointMotion3& top, const PointMotion3& bottom) const {
  const int nb = model_.bodies();
  double err = (top.p - body(y, 0).A).norm();
  for (int k = 1; k < nb; ++k) err = std::max(err, (body(y, k - 1).end() - body(y, k).A).norm());
  if (model_.bottom() == BottomBoundary::kPinned) err = std::max(err, (body(y, nb - 1).end() - bottom.p).norm());
  return err;
}

double NaturalFormulation::directorError(const VecX& y) const {
  double err = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) err = std::max(err, std::abs(body(y, i).e.norm() - 1.0));
  return err;
}

double NaturalFormulation::manifoldError(const VecX& y, double h) const {
  double err = 0.0;
  for (int i = 0; i < model_.bodies(); ++i) {
    const BodyKinematics3 b = body(y, i);
    err = std::max({err, std::abs(b.e.norm() - 1.0), std::abs(b.e.dot(b.e_dot)) * h});
  }
  return err;
}

void NaturalFormulation::project(VecX& y) const {
  const int nq = positionSize();
  for (int i = 0; i < model_.bodies(); ++i) {
    auto e = y.segment<3>(kDofPerBody3 * i + kE);
    auto ed = y.segment<3>(nq + kDofPerBody3 * i + kE);
    e /= e.norm();
    ed -= e.dot(ed) * e;
  }
}

}  // namespace spatial
}  // namespace riser_sim
