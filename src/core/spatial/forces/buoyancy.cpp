#include "riser_sim/spatial/forces/buoyancy.h"

#include "riser_sim/physics/buoyancy.h"

namespace riser_sim {
namespace spatial {

namespace {
// ρ_w |g| A_w [N/m]: the lift per submerged length of part p of rfe i (its section's displaced area).
double liftPerLength(const Model3& model, const Water3& water, int i, int p) {
  return physics::liftPerLength(water.spec().density, model.line().partSection(i, p).props.externalArea(),
                                model.gravity().norm());
}
}  // namespace

void Buoyancy::addForces(const Model3& model, const Kinematics3& kin, double, VecX& Q) const {
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const double f = liftPerLength(model, water_, i, p);
      const WetPart3 w = wetPart3(model.line(), kin[i], i, p, water_);
      if (w.length > 0.0)
        addPointForce(kin[i], w.s0, w.kappa, physics::buoyancyForce<3>(f, w.length, water_.up()),
                      Q.data() + kDofPerBody3 * i);
    }
}

double Buoyancy::potentialEnergy(const Model3& model, const Kinematics3& kin, double) const {
  double v = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const double f = liftPerLength(model, water_, i, p);
      const WetPart3 w = wetPart3(model.line(), kin[i], i, p, water_);
      if (w.length > 0.0) v += physics::buoyancyPotential(f, w.length, water_.height(kin[i].point(w.s0, w.kappa)));
    }
  return v;
}

// Q = [F; κ e·F; s F] with F constant: -∂Q_Δ/∂e = -κ Fᵀ, -∂Q_e/∂Δ = -κ F.
void Buoyancy::addStiffness(const Model3& model, const Kinematics3& kin, double, Stiffness3& S) const {
  if (!model.options().axial_flexibility) return;
  for (int i = 0; i < model.bodies(); ++i) {
    const double f = liftPerLength(model, water_, i, 1);
    const WetPart3 w = wetPart3(model.line(), kin[i], i, 1, water_);  // part 0 has κ = 0
    if (!(w.length > 0.0)) continue;
    const Vec3 F = physics::buoyancyForce<3>(f, w.length, water_.up());
    S.K_diag[i].block<1, 3>(kDelta3, kE) -= F.transpose();
    S.K_diag[i].block<3, 1>(kE, kDelta3) -= F;
  }
}

}  // namespace spatial
}  // namespace riser_sim
