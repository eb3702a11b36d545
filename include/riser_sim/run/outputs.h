// What the simulator reports after every step (points, angles, elongations, tension,
// bending moments, reactions at both ends, energy, constraint error).
#pragma once
#include <cmath>
#include <vector>

#include "riser_sim/types.h"

namespace riser_sim {

struct LineOutputs {
  double t = 0.0;                      // [s]
  AlignedVector<Vec2> points;          // A_0..A_n and the end point of rfe n (n+2 points) [m]
  std::vector<double> angles;          // φ_i [rad], n+1
  std::vector<double> elongations;     // Δ_i [m], n+1
  std::vector<double> axial_force;     // tension in rfe i [N], n+1 (positive = tension)
  std::vector<double> arc_length;      // unstretched arc length of the middle of rfe i from the top [m]
  std::vector<double> bending_moment;  // at bending spring i = 1..n (between rfe i-1 and i) [N m], n
  Vec2 top_force = Vec2::Zero();       // force the line exerts on the hang-off point [N]
  Vec2 bottom_force = Vec2::Zero();    // force the line exerts on the bottom anchor (pinned) [N]
  double top_tension = 0.0;            // |top_force| [N]
  double bottom_tension = 0.0;         // axial force at the bottom rfe [N]
  double max_tension = 0.0;            // max over rfes [N]
  double kinetic_energy = 0.0;         // [J]
  double potential_energy = 0.0;       // [J]
  double work_in = 0.0;                // work done on the line by the top motion and non-conservative terms [J]
  double constraint_error = 0.0;       // largest joint-constraint violation [m]
};

// Every output is finite (what may be published).
inline bool allFinite(const LineOutputs& o) {
  for (const auto& p : o.points)
    if (!p.allFinite()) return false;
  for (const auto* v : {&o.angles, &o.elongations, &o.axial_force, &o.arc_length, &o.bending_moment})
    for (double x : *v)
      if (!std::isfinite(x)) return false;
  if (!o.top_force.allFinite() || !o.bottom_force.allFinite()) return false;
  for (double x : {o.t, o.top_tension, o.bottom_tension, o.max_tension, o.kinetic_energy, o.potential_energy, o.work_in,
                   o.constraint_error})
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace riser_sim
