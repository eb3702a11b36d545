// Static equilibrium for initial states: Newton on the independent coordinates (Δ_i, φ_i) with
// A_0 held, the end loads solved for alongside.
#pragma once
#include <string>

#include "riser_sim/kinematics.h"
#include "riser_sim/model.h"

namespace riser_sim {

struct StaticsProblem {
  enum class Kind {
    kHanging,        // (c) end free, hanging under its loads
    kEndDisplaced,   // (a) end moved horizontally by end_dx under an unknown horizontal force F_x
    kBetweenPoints,  // (b) end held at end_point (reaction unknown)
  };
  Kind kind = Kind::kHanging;
  Vec2 top = Vec2::Zero();        // A_0 [m]
  double end_dx = 0.0;            // x_end - x_0 for kEndDisplaced [m]
  Vec2 end_point = Vec2::Zero();  // for kBetweenPoints [m]
  double tolerance = 1e-9;        // on the largest residual force relative to the line's weight
  int max_iterations = 200;
};

struct StaticsResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;          // largest residual, relative to the total weight
  Vec2 end_force = Vec2::Zero();  // external force applied at the end [N] (F_x for kEndDisplaced)
  Kinematics kin;                 // the equilibrium (zero velocities)
  std::string message;
};

StaticsResult solveStatics(const Model& model, const StaticsProblem& problem, double t = 0.0);

// Straight line from A_0 at angle phi [rad], unstretched, at rest.
Kinematics straightLine(const Model& model, const Vec2& top, double phi);

}  // namespace riser_sim
