#include "riser_sim/planar/forces/buoyancy.h"

#include "riser_sim/physics/buoyancy.h"

namespace riser_sim {

WetPart wetPart(const Model& model, const BodyKinematics& b, int i, int part, double surface) {
  const Rfe& r = model.rfe(i);
  const double start = part == 0 ? 0.0 : r.length1, len = part == 0 ? r.length1 : r.length2;
  const double kappa = part == 0 ? 0.0 : 1.0;
  const double s_begin = start + kappa * b.delta;
  const double y0 = b.A.y() + s_begin * b.s, y1 = y0 + len * b.s;
  double frac, cen;
  submerged(y0, y1, surface, frac, cen);
  return WetPart{frac * len, start + cen * len, kappa, frac};
}

// ρ_w g A_w of part p of rfe i (its section's displaced area) [N/m].
double Buoyancy::liftPerLength(const Model& model, int i, int p) const {
  return physics::liftPerLength(water_.density, model.partSection(i, p).props.externalArea(), model.gravity());
}

void Buoyancy::addForces(const Model& model, const TermData*, const Kinematics& kin, double, VecX& Q) const {
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const double f = liftPerLength(model, i, p);
      const WetPart w = wetPart(model, kin[i], i, p, water_.surface);
      if (w.length > 0.0)
        Q.segment<4>(4 * i) += pointForce(kin[i], w.s0, w.kappa, physics::buoyancyForce<2>(f, w.length, Vec2::UnitY()));
    }
}

double Buoyancy::potentialEnergy(const Model& model, const TermData*, const Kinematics& kin) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const double f = liftPerLength(model, i, p);
      const WetPart w = wetPart(model, kin[i], i, p, water_.surface);
      v += physics::buoyancyPotential(f, w.length, kin[i].point(w.s0, w.kappa).y() - water_.surface);
    }
  return v;
}

}  // namespace riser_sim

namespace riser_sim {

// The geometric part of the lift on each wet part (the change of the wet length at the surface is left
// to the explicit side).
bool Buoyancy::addStiffness(const Model& model, const TermData*, const Kinematics& kin, double,
                            StiffnessBlocks& S) const {
  const Mat2 zero = Mat2::Zero();
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const double f = liftPerLength(model, i, p);
      const WetPart w = wetPart(model, kin[i], i, p, water_.surface);
      if (w.length > 0.0)
        addPointStiffness(kin[i], w.s0, w.kappa, physics::buoyancyForce<2>(f, w.length, Vec2::UnitY()), zero, zero,
                          S.K_diag[i], S.C_diag[i]);
    }
  return true;
}

}  // namespace riser_sim
