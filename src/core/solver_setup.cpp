#include "riser_sim/solver_setup.h"

#include <cmath>

#include "riser_sim/integrator.h"
#include "riser_sim/simulator.h"

namespace riser_sim {
namespace {
bool oneOf(const std::string& v, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (v == n) return true;
  return false;
}
}  // namespace

int coordinatesPerRfe(const std::string& formulation, bool axial_flexibility) {
  if (formulation == "absolute") return 4;
  return axial_flexibility ? 2 : 1;
}

std::string resolvedJacobian(const SolverSettings& s) {
  if (s.jacobian != "auto") return s.jacobian;
  return s.formulation == "absolute" ? "dense" : "structured";
}

std::optional<SetupError> checkSolverSetup(const SolverSettings& s, int elements, bool axial_flexibility) {
  if (!(s.dt > 0.0) || !std::isfinite(s.dt)) return SetupError{"solver.dt", "must be > 0"};
  if (!oneOf(s.integrator, {"rk4", "dopri5", "rosenbrock2", "midpoint"}))
    return SetupError{"solver.integrator",
                      "unknown integrator '" + s.integrator + "' (accepted: " + integratorNames() + ")"};
  if (!oneOf(s.formulation, {"absolute", "independent", "recursive"}))
    return SetupError{"solver.formulation",
                      "unknown formulation '" + s.formulation + "' (accepted: absolute, independent, recursive)"};
  if (!oneOf(s.jacobian, {"auto", "structured", "dense"}))
    return SetupError{"solver.jacobian", "unknown value '" + s.jacobian + "' (accepted: auto, structured, dense)"};
  if (s.jacobian == "structured" && s.formulation == "absolute")
    return SetupError{"solver.jacobian",
                      "'structured' needs solver.formulation independent or recursive (absolute has none); use "
                      "'dense' or 'auto'"};
  if (!(s.tolerance > 0.0)) return SetupError{"solver.tolerance", "must be > 0"};
  if (!(s.jacobian_interval >= 0.0)) return SetupError{"solver.jacobian_interval", "must be >= 0"};
  const int k = coordinatesPerRfe(s.formulation, axial_flexibility);
  if (isImplicitIntegrator(s.integrator) && resolvedJacobian(s) == "dense" && k * (elements + 1) > kMaxDenseCoordinates) {
    const int n_max = kMaxDenseCoordinates / k - 1;
    return SetupError{"line.elements",
                      "must be <= " + std::to_string(n_max) + " with a dense " + s.integrator + " Jacobian on the " +
                          s.formulation + " formulation (p = " + std::to_string(k) + "(n + 1) coordinates, at most " +
                          std::to_string(kMaxDenseCoordinates) + ": O(p^2) memory, O(p^3) per refresh), got " +
                          std::to_string(elements) +
                          "; use solver.formulation recursive or independent (structured O(n) solves)"};
  }
  return std::nullopt;
}

}  // namespace riser_sim
