// Bending stiffness that differs about an rfe's two material axes (a non-circular line: a flat umbilical, a
// bundle, a strake): EI_1 about axis 1 (m1_i: the spin's material director, torsion.h), EI_2 about axis 2
// (m2_i = e_i × m1_i). Joint k (rfes a = k, b = k + 1, unit directors n_a, n_b) bends by the curvature vector
//   κ = (θ / sin θ) n_a × n_b   (|κ| = θ, the isotropic spring's angle; along the bending axis),
// split on each rfe's own axes and averaged over the two (they differ by the joint's twist):
//   V_k = (1/2d) · ½ Σ_{j=a,b} [EI_1 (κ·m1_j)² + EI_2 (κ·m2_j)²] = ½ (Ē/d) θ² + (σ/4) Σ_j κᵀ P_j κ,
// Ē = (EI_1 + EI_2)/2 (the isotropic BendingSpring carries it), σ = (EI_1 - EI_2)/(2d), P_j = m1 m1ᵀ - m2 m2ᵀ.
// EI_1 = EI_2 leaves ½ (EI/d) θ² exactly; bending in a principal plane of both rfes costs ½ (EI_j/d) θ².
// Forces (this file): with G = (σ/2)(P_a + P_b) κ and M_j = (σ/2) P_j κ × κ,
//   ∂V/∂n_a = φ n_b × G - ψ (G·X) n_b + M_a × n_a   (X = n_a × n_b, φ = θ/sin θ, ψ = φ'(θ)/sin θ),
//   ∂V/∂n_b = φ G × n_a - ψ (G·X) n_a + M_b × n_b,    ∂V/∂(spin_j) = M_j·n_j,
// the frames turned minimally with n (as the twist's forces: the spins' own rows take the rest).
#pragma once
#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

class Model3;

// Adds -∂V/∂e_i of the axes' part (frames turned minimally; any |e_i|) to Q's e parts and -∂V/∂(spin_i) to
// moment[i] [N m], at the spins θ (rfe 0's 0 when the hang-off holds it) in the frames f. Nothing without
// Model3::hasBendingAxes(). Zero within BendingSpring::kFoldedTol of a fully folded joint, as the spring.
void addBendingAxesForces(const Model3& model, const Kinematics3& kin, const double* theta, const TwistFrames& f,
                          AlignedVector<Vec3>& m1, VecX& Q, double* moment);
// Σ_k (σ/4) Σ_j κᵀ P_j κ [J] (the part beyond the isotropic spring's ½ (Ē/d) θ²; may be < 0).
double bendingAxesEnergy(const Model3& model, const Kinematics3& kin, const double* theta, const TwistFrames& f);

}  // namespace spatial
}  // namespace riser_sim
