// Mass blocks of every rfe in absolute coordinates, shared by the formulations:
// M_i = Σ_p B_p^T m_p B_p + J_p (rigid parts) plus every term's inertia, and the velocity terms h_i
// (M q'' = Q - h).
#pragma once
#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {

void rfeMassBlocks(const Model& model, const Kinematics& kin, double t, AlignedVector<Mat4>& M, VecX& h);

}  // namespace riser_sim
