#include "riser_sim/spatial/added_mass.h"

namespace riser_sim {
namespace spatial {

// With T_x = x_n P + x_t N per moment x: AA += T_m, Ae += T_S, ee += T_I; T e = x_t e gives the Δ column
// (m_k,t e; S_k,t e; m_k,t e·e) and h = 2Δ' [T_mk e'; m_k,t e·e'; T_Sk e'].
namespace {

// x_n P + x_t N with N = n nᵀ, n = e/|e|.
Mat3 tensor(const Vec3& e, double normal, double axial) {
  const Vec3 n = e / e.norm();
  Mat3 T = (axial - normal) * (n * n.transpose());
  T.diagonal().array() += normal;
  return T;
}

}  // namespace

void addAddedMassBlock(const AddedMass3& a, const BodyKinematics3& b, bool axial_dof, Mat7& M) {
  const RfeMoments &cn = a.normal, &ct = a.axial;
  const Mat3 TS = tensor(b.e, cn.S, ct.S);
  M.block<3, 3>(kA, kA) += tensor(b.e, cn.m, ct.m);
  M.block<3, 3>(kA, kE) += TS;
  M.block<3, 3>(kE, kA) += TS;
  M.block<3, 3>(kE, kE) += tensor(b.e, cn.I, ct.I);
  if (axial_dof) {
    M.block<3, 1>(kA, kDelta3) += ct.mk * b.e;
    M.block<1, 3>(kDelta3, kA) += ct.mk * b.e.transpose();
    M.block<3, 1>(kE, kDelta3) += ct.Sk * b.e;
    M.block<1, 3>(kDelta3, kE) += ct.Sk * b.e.transpose();
    M(kDelta3, kDelta3) += ct.mk * b.e.squaredNorm();
  }
}

void addAddedVelocityTerms(const AddedMass3& a, const BodyKinematics3& b, double* h) {
  if (b.delta_dot == 0.0) return;
  const double w = 2.0 * b.delta_dot;
  const Vec3 hA = w * (tensor(b.e, a.normal.mk, a.axial.mk) * b.e_dot);
  const Vec3 he = w * (tensor(b.e, a.normal.Sk, a.axial.Sk) * b.e_dot);
  for (int k = 0; k < 3; ++k) h[kA + k] += hA[k], h[kE + k] += he[k];
  h[kDelta3] += w * a.axial.mk * b.e.dot(b.e_dot);
}

}  // namespace spatial
}  // namespace riser_sim
