// Static equilibrium for initial states: Newton on the independent coordinates (Δ_i, φ_i) with
// A_0 held, the end loads solved for alongside; every solution is checked (checkEquilibrium).
#pragma once
#include <functional>
#include <string>

#include "riser_sim/planar/kinematics.h"
#include "riser_sim/planar/model.h"

namespace riser_sim {

// Progress of a statics solve, reported every Newton iteration: the stage (e.g. "from the first guess", "current
// ramp at 0.5 of the speed"), the iterations so far, the residual reached and the seconds spent.
using StaticsProgress = std::function<void(const std::string& stage, int iterations, double residual, double seconds)>;

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
  // When Newton from the first guess fails or finds no stable state: continuation in the current (from still
  // water, its drag ramped up) and, with a seabed, in the seabed's stiffness (docs/statics.md). false: the
  // first guess's Newton only.
  bool continuation = true;
  StaticsProgress progress;  // optional (the core never prints)
  // Wall-clock bound [s]: past it the solve stops, its message naming the stage and what to try.
  double time_limit = 60.0;
};

struct StaticsResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;          // largest residual, relative to the total weight
  Vec2 end_force = Vec2::Zero();  // external force applied at the end [N] (F_x for kEndDisplaced)
  Kinematics kin;                 // the equilibrium (zero velocities)
  std::string message;
};

// Solves in a steady sea at time t (no waves, the current at its velocity at t; ForceTerm::steadyTerm)
// and returns converged only if checkEquilibrium() passes; otherwise the message names the check.
StaticsResult solveStatics(const Model& model, const StaticsProblem& problem, double t = 0.0);

// What solveStatics() verifies before it reports success (docs/statics.md), each check named in
// the message when it fails:
// - finite: every coordinate and the end force are finite;
// - residual: the equilibrium residual with every term of the statics (steady sea, seabed, end
//   force) and the end conditions, relative to the line's weight, is <= problem.tolerance;
// - seabed: no contact point carries more than kSeabedLoadFactor x the load (it would sink deeper
//   than the whole line's load on one spring);
// - tension: the force through every joint is <= kTensionLoadFactor x the load;
// - stability: the stiffness about the equilibrium (reduced to the end conditions) is positive
//   definite: a resting state, not a balanced unstable one (a column on the seabed, a folded line).
// The load: the sum over the rfes of the magnitude of every force on it but the seabed's (weight
// in water, current drag), plus the end force.
struct EquilibriumCheck {
  bool ok = false;
  std::string message;            // "<check>: ..." when a check fails, empty when ok
  double residual = 0.0;          // as StaticsResult::residual
  double load = 0.0;              // [N]
  double max_joint_force = 0.0;   // [N]
  double max_seabed_force = 0.0;  // largest contact force [N]
};
constexpr double kSeabedLoadFactor = 2.0;
constexpr double kTensionLoadFactor = 3.0;
EquilibriumCheck checkEquilibrium(const Model& model, const StaticsProblem& problem, const Kinematics& kin,
                                  const Vec2& end_force, double t = 0.0);

// Whether a failed solve is one a dynamic relaxation may get past (spatial/relaxation.h): it iterated (not a
// refused input) on a line hanging free or held between two points (a displaced end is held by a force the
// relaxation has no constraint for).
bool relaxationMayReach(const StaticsProblem& problem, const StaticsResult& failed);

// Newton from a given state at rest (and its end force [N]), e.g. one relaxed to rest; converged only if
// checkEquilibrium() passes, as solveStatics().
StaticsResult solveStaticsFrom(const Model& model, const StaticsProblem& problem, const Kinematics& guess,
                               const Vec2& end_force, double t = 0.0);

// Newton's starting point for the problem in the steady sea at t (the catenary guesses of docs/statics.md, on the
// seabed where it reaches it), at rest; end_force gets its guess of the end's force [N].
Kinematics staticsFirstGuess(const Model& model, const StaticsProblem& problem, Vec2& end_force, double t = 0.0);

// Straight line from A_0 at angle phi [rad], unstretched, at rest.
Kinematics straightLine(const Model& model, const Vec2& top, double phi);

}  // namespace riser_sim
