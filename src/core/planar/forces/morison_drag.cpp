#include "riser_sim/planar/forces/morison_drag.h"

#include <cmath>

#include "riser_sim/planar/forces/buoyancy.h"
#include "riser_sim/physics/morison_drag.h"

namespace riser_sim {

Vec2 MorisonDrag::force(const Model& model, const BodyKinematics& b, int i, int p, double t, double& s0, double& kappa,
                        Vec2& v) const {
  const WetPart w = wetPart(model, b, i, p, water_.spec().surface);
  s0 = w.s0;
  kappa = w.kappa;
  v = b.velocity(w.s0, w.kappa);
  if (w.length <= 0.0) return Vec2::Zero();
  Vec2 rel = v;
  if (water_.moving()) {
    Vec2 vw, aw;
    water_.at(b.point(w.s0, w.kappa), t, vw, aw);
    rel -= vw;
  }
  const LineSection& sec = model.partSection(i, p);
  const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
  return physics::morisonDrag<2>(rel, b.e(), water_.spec().density, sec.dragDiameter(), w.length, cd_t, cd_n);
}

void MorisonDrag::addForces(const Model& model, const TermData*, const Kinematics& kin, double t, VecX& Q) const {
  sweep(model, kin, t, &Q);
}

double MorisonDrag::addForcesAndPower(const Model& model, const TermData*, const Kinematics& kin, double t,
                                      VecX& Q) const {
  return sweep(model, kin, t, &Q);
}

double MorisonDrag::power(const Model& model, const TermData*, const Kinematics& kin, double t) const {
  return sweep(model, kin, t, nullptr);
}

bool MorisonDrag::addStiffness(const Model& model, const TermData*, const Kinematics& kin, double t,
                               StiffnessBlocks& S) const {
  const Mat2 zero = Mat2::Zero();
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      const BodyKinematics& b = kin[i];
      const WetPart w = wetPart(model, b, i, p, water_.spec().surface);
      if (w.length <= 0.0) continue;
      Vec2 rel = b.velocity(w.s0, w.kappa);
      if (water_.moving()) {
        Vec2 vw, aw;
        water_.at(b.point(w.s0, w.kappa), t, vw, aw);
        rel -= vw;
      }
      const LineSection& sec = model.partSection(i, p);
      const double cd_t = orLine(sec.hydro.drag_tangential, cd_t_), cd_n = orLine(sec.hydro.drag_normal, cd_n_);
      const Mat2 Cp =
          physics::morisonDragDamping<2>(rel, b.e(), water_.spec().density, sec.dragDiameter(), w.length, cd_t, cd_n);
      addPointStiffness(b, w.s0, w.kappa, Vec2::Zero(), zero, Cp, S.K_diag[i], S.C_diag[i]);
    }
  return true;
}

double MorisonDrag::sweep(const Model& model, const Kinematics& kin, double t, VecX* Q) const {
  double pw = 0.0;
  for (int i = 0; i < model.bodies(); ++i)
    for (int p = 0; p < 2; ++p) {
      double s0, kappa;
      Vec2 v;
      const Vec2 F = force(model, kin[i], i, p, t, s0, kappa, v);
      if (Q) Q->segment<4>(4 * i) += pointForce(kin[i], s0, kappa, F);
      pw += F.dot(v);
    }
  return pw;
}

}  // namespace riser_sim
