// The joint reactions λ_k of the spatial natural formulation (natural_formulation.h): the block-tridiagonal
// system of the joints' Baumgarte laws, from the evaluation's per-rfe compliances and free accelerations.
#include <algorithm>
#include <cmath>

#include "riser_sim/spatial/natural_formulation.h"

namespace riser_sim {
namespace spatial {

// Sets d.lambda (k = 0..n, n+1 when pinned: λ_{n+1} = 0 at a free end), d.diag, d.up, d.rhs and
// d.constraint_error from d.kin, d.body (or d.dense), d.top and d.bottom.
void NaturalFormulation::jointReactions(NaturalData& d) const {
  const int nb = model_.bodies();
  const bool pinned = model_.bottom() == BottomBoundary::kPinned;
  const int nc = nb + (pinned ? 1 : 0);
  // Rows k = 0..n (+ n+1 pinned): c_k = E_{k-1} - A_k, E_{-1} = top point, A_{n+1} = bottom point; the
  // force on rfe k at A_k is -λ_k, on rfe k-1 at its end +λ_k (as the planar AbsoluteFormulation). Row k:
  // low_k λ_{k-1} + D_k λ_k + up_k λ_{k+1} = rhs_k with up_k = -AE_k, low_k = -AE_{k-1}ᵀ.
  const double w = omega_;
  double cmax = 0.0;
  for (int k = 0; k < nc; ++k) {
    Vec3 c, cd, r;
    Mat3 dk;
    if (k == 0) {
      c = d.top.p - d.kin[0].A;
      cd = d.top.v - d.kin[0].A_dot;
      r = -d.top.a;
      dk.setZero();
    } else {
      const BodyKinematics3& bp = d.kin[k - 1];
      // A_{n+1}: the pinned bottom's anchor p_b(t), its acceleration prescribed as the top's.
      const Vec3 Ak = k < nb ? d.kin[k].A : d.bottom.p;
      const Vec3 Akd = k < nb ? d.kin[k].A_dot : d.bottom.v;
      c = bp.end() - Ak;
      cd = bp.endVelocity() - Akd;
      r = -d.body[k - 1].aE;
      if (k == nb) r += d.bottom.a;
      dk = d.body[k - 1].EE;
    }
    if (k < nb) {
      r += d.body[k].aA;
      dk += d.body[k].AA;
      if (k < nb - 1 || pinned)
        d.up[k] = -d.body[k].AE;
      else
        d.up[k].setZero();
    }
    d.rhs[k] = r - 2.0 * w * cd - (w * w) * c;
    cmax = std::max(cmax, c.squaredNorm());
    d.diag[k] = dk;
  }
  // Block Thomas from both ends at once (two independent chains of 3x3 inverses, which the CPU overlaps:
  // the chain is the evaluation's critical path), meeting at row m; diag[k] keeps the inverse of the
  // eliminated block.
  auto low = [&](int k) -> Mat3 { return -d.body[k - 1].AE.transpose(); };
  // The closed form's blocks are symmetric (its compliances are p n nᵀ + q (I - n nᵀ)): the inverse from the
  // upper triangle (6 cofactors), the dense path's in general.
  auto inverse = [this](const Mat3& A) -> Mat3 {
    if (!closed_form_) return A.inverse();
    const double a = A(0, 0), b = A(0, 1), c = A(0, 2), e = A(1, 1), f = A(1, 2), g = A(2, 2);
    const double c00 = e * g - f * f, c01 = c * f - b * g, c02 = b * f - c * e;
    const double inv = 1.0 / (a * c00 + b * c01 + c * c02);
    const double c11 = (a * g - c * c) * inv, c12 = (b * c - a * f) * inv, c22 = (a * e - b * b) * inv;
    Mat3 R;
    R << c00 * inv, c01 * inv, c02 * inv, c01 * inv, c11, c12, c02 * inv, c12, c22;
    return R;
  };
  const int m = nc / 2;
  for (int j = 0; j < nc - m; ++j) {
    const int kt = j, kb = nc - 1 - j;
    if (kt < m) {
      if (kt > 0) {
        const Mat3 L = low(kt) * d.diag[kt - 1];
        d.diag[kt].noalias() -= L * d.up[kt - 1];
        d.rhs[kt].noalias() -= L * d.rhs[kt - 1];
      }
      d.diag[kt] = inverse(d.diag[kt]);
    }
    if (kb > m) {
      if (kb < nc - 1) {
        const Mat3 U = d.up[kb] * d.diag[kb + 1];
        d.diag[kb].noalias() -= U * low(kb + 1);
        d.rhs[kb].noalias() -= U * d.rhs[kb + 1];
      }
      d.diag[kb] = inverse(d.diag[kb]);
    }
  }
  {
    Mat3 D = d.diag[m];
    Vec3 r = d.rhs[m];
    if (m > 0) {
      const Mat3 L = low(m) * d.diag[m - 1];
      D.noalias() -= L * d.up[m - 1];
      r.noalias() -= L * d.rhs[m - 1];
    }
    if (m < nc - 1) {
      const Mat3 U = d.up[m] * d.diag[m + 1];
      D.noalias() -= U * low(m + 1);
      r.noalias() -= U * d.rhs[m + 1];
    }
    d.lambda[m] = inverse(D) * r;
  }
  for (int j = 1; j < nc - m || m - j >= 0; ++j) {
    const int kt = m - j, kb = m + j;
    if (kt >= 0) d.lambda[kt] = d.diag[kt] * (d.rhs[kt] - d.up[kt] * d.lambda[kt + 1]);
    if (kb < nc) d.lambda[kb] = d.diag[kb] * (d.rhs[kb] - low(kb) * d.lambda[kb - 1]);
  }
  if (!pinned) d.lambda[nb] = Vec3::Zero();
  d.constraint_error = std::sqrt(cmax);
}

}  // namespace spatial
}  // namespace riser_sim
