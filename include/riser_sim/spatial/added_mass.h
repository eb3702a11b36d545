// Added mass of an rfe in 3D (Morison inertia, the planar HydroInertia's added mass, normal and axial): each
// wet part lumped at its centroid c = s0 + κΔ from A_i with mass m_w = ρ_w A_w × wet length. The force on it is
// -(C_a,n P + C_a,t N) m_w a_c, N = n nᵀ, P = I - N, n = e/|e|, a_c the centroid's acceleration. Per rfe the
// coefficient-weighted moments of the centroids, across (normal) and along (axial) the rfe, give its
// 7x7 block J_cᵀ (..) J_c summed over the parts, J_c = [I, κ e, c I] on (A, Δ, e) (kinematics.h).
#pragma once
#include <vector>

#include "riser_sim/spatial/kinematics.h"

namespace riser_sim {
namespace spatial {

using Mat7 = Eigen::Matrix<double, kDofPerBody3, kDofPerBody3>;
using Vec7 = Eigen::Matrix<double, kDofPerBody3, 1>;

// Σ m, Σ m c, Σ m c², and over the parts beyond the spring (κ = 1) Σ m, Σ m c [kg, kg m, kg m²].
struct RfeMoments {
  double m = 0.0, S = 0.0, I = 0.0, mk = 0.0, Sk = 0.0;
  void add(double mass, double c, double kappa) {
    m += mass, S += mass * c, I += mass * c * c;
    if (kappa != 0.0) mk += mass, Sk += mass * c;
  }
};

struct AddedMass3 {
  RfeMoments normal, axial;
  bool empty() const { return normal.m == 0.0 && axial.m == 0.0; }
};

// Adds rfe b's added-mass block to M (7x7 on [A, Δ, e]); axial_dof = false leaves the Δ row and column alone
// (Δ locked). addAddedVelocityTerms: its velocity term J_cᵀ T (2κΔ' e') to h.
void addAddedMassBlock(const AddedMass3& a, const BodyKinematics3& b, bool axial_dof, Mat7& M);
void addAddedVelocityTerms(const AddedMass3& a, const BodyKinematics3& b, double* h);

}  // namespace spatial
}  // namespace riser_sim
