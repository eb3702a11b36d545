// The planar line at rest linearised about an equilibrium (modal.cpp): the one linearisation the modal analysis
// and the statics' stability check (statics_check.cpp) share.
#pragma once
#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {
namespace modal_detail {

struct LinearisationOptions {
  double time = 0.0;            // the steady sea's t [s]
  double fd_step = 1e-6;        // central differences: rad for φ, x segment length for Δ (θ' alike, per s)
  bool solve_anchor = false;    // add the anchor's reaction (least squares on the end point's Jacobian) to the load
  bool damping = false;         // also C = -∂Q_θ/∂θ' at rest
  double current_factor = 1.0;  // the current's velocity x this (the statics' continuation in the current)
};

// In the independent coordinates θ (k per rfe), A_0 held, the end load a dead load:
//   M θ'' + C θ' + K θ = 0,  K = -∂Q_θ/∂θ (not symmetrised: drag's follower part stays), C = -∂Q_θ/∂θ'.
struct PlanarLinearisation {
  int k = 1;                 // coordinates per rfe
  VecX theta;                // the equilibrium
  Kinematics kin;            // at theta
  Vec2 load = Vec2::Zero();  // the dead end load [N] (with the anchor's reaction when solved)
  double residual = 0.0;     // max |Q_θ| / the largest force (moments / that x L)
  MatX K, C, M;
  MatX Ct;  // the end point's Jacobian transposed (nt x 2): E' = Ctᵀ θ'
};

PlanarLinearisation linearise(const Model& model, const Kinematics& equilibrium, const Vec2& end_force,
                              const LinearisationOptions& options);

}  // namespace modal_detail
}  // namespace riser_sim
