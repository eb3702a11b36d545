#include "riser_sim/line/rfe_inertia.h"

#include "riser_sim/planar/force_term.h"

namespace riser_sim {

void rfeMassBlocks(const Model& model, const Kinematics& kin, double t, AlignedVector<Mat4>& M, VecX& h) {
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const BodyKinematics& b = kin[i];
    const double m = r.mass, mk = r.mass_k, S = r.firstMoment(b.delta), Sk = r.firstMomentK(b.delta);
    const double I = r.inertiaAboutA(b.delta);
    M[i] << m, 0, mk * b.c, -S * b.s,  //
        0, m, mk * b.s, S * b.c,       //
        mk * b.c, mk * b.s, mk, 0,     //
        -S * b.s, S * b.c, 0, I;
    const double w2 = b.phi_dot * b.phi_dot, dw = 2.0 * b.delta_dot * b.phi_dot;
    h.segment<4>(4 * i) = Vec4(-mk * dw * b.s - S * w2 * b.c, mk * dw * b.c - S * w2 * b.s, -Sk * w2, Sk * dw);
  }
  for (const auto& term : model.terms())
    if (term->hasInertia()) term->addInertia(model, kin, t, M, h);
}

}  // namespace riser_sim
