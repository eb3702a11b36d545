#include "riser_sim/scene/solver_setup.h"

#include <cmath>

#include "riser_sim/integrators/integrator.h"
#include "riser_sim/planar/simulator.h"

namespace riser_sim {

int coordinatesPerRfe(FormulationKind formulation, bool axial_flexibility) {
  if (formulation == FormulationKind::kAbsolute) return 4;
  return axial_flexibility ? 2 : 1;
}

JacobianKind resolvedJacobian(const SolverSettings& s) {
  if (s.jacobian != JacobianKind::kAuto) return s.jacobian;
  return s.formulation == FormulationKind::kAbsolute ? JacobianKind::kDense : JacobianKind::kStructured;
}

std::optional<SetupError> checkSolverValues(const SolverSettings& s) {
  if (!(s.dt > 0.0) || !std::isfinite(s.dt)) return SetupError{"solver.dt", "must be > 0"};
  // Enums set in code can still hold a value outside their table.
  if (!parseChoice<IntegratorKind>(name(s.integrator)))
    return SetupError{"solver.integrator", "unknown integrator (accepted: " + choiceNames<IntegratorKind>() + ")"};
  if (!parseChoice<FormulationKind>(name(s.formulation)))
    return SetupError{"solver.formulation", "unknown formulation (accepted: " + choiceNames<FormulationKind>() + ")"};
  if (!parseChoice<JacobianKind>(name(s.jacobian)))
    return SetupError{"solver.jacobian", "unknown value (accepted: " + choiceNames<JacobianKind>() + ")"};
  if (!(s.tolerance > 0.0)) return SetupError{"solver.tolerance", "must be > 0"};
  if (!(s.jacobian_interval >= 0.0)) return SetupError{"solver.jacobian_interval", "must be >= 0"};
  if (!(s.rho_inf >= 0.0 && s.rho_inf <= 1.0)) return SetupError{"solver.rho_inf", "must be in [0, 1]"};
  if (!(s.newton_tolerance > 0.0 && s.newton_tolerance <= kMaxNewtonTolerance))
    return SetupError{"solver.newton_tolerance", "must be in (0, 1e-3]"};
  return std::nullopt;
}

std::optional<SetupError> checkSolverSetup(const SolverSettings& s, int elements, bool axial_flexibility) {
  if (const auto error = checkSolverValues(s)) return error;
  return planarUnsupported(s, elements, axial_flexibility);
}

std::optional<SetupError> planarUnsupported(const SolverSettings& s, int elements, bool axial_flexibility) {
  if (s.jacobian == JacobianKind::kStructured && s.formulation == FormulationKind::kAbsolute)
    return SetupError{"solver.jacobian",
                      "'structured' needs solver.formulation independent or recursive (absolute has none); use "
                      "'dense' or 'auto'"};
  const int k = coordinatesPerRfe(s.formulation, axial_flexibility);
  if (isImplicitIntegrator(s.integrator) && resolvedJacobian(s) == JacobianKind::kDense &&
      k * (elements + 1) > kMaxDenseCoordinates) {
    const int n_max = kMaxDenseCoordinates / k - 1;
    return SetupError{"line.elements",
                      "must be <= " + std::to_string(n_max) + " with a dense " + name(s.integrator) +
                          " Jacobian on the " + name(s.formulation) + " formulation (p = " + std::to_string(k) +
                          "(n + 1) coordinates, at most " + std::to_string(kMaxDenseCoordinates) +
                          ": O(p^2) memory, O(p^3) per refresh), got " + std::to_string(elements) +
                          "; use solver.formulation recursive or independent (structured O(n) solves)"};
  }
  return std::nullopt;
}

}  // namespace riser_sim
