// The checks of a solver setup: its values (any engine) and what the planar engine supports. A scene is
// checked by checkScene (scene_check.h: these, or the 3D engine's spatial::unsupported), which the loader
// (as a SceneError) and the node (a parameter error) call; the planar Simulator (std::invalid_argument)
// calls checkSolverSetup, so their limits cannot disagree.
#pragma once
#include <optional>
#include <string>

#include "riser_sim/scene/choices.h"

namespace riser_sim {

struct SolverSettings;

struct SetupError {
  std::string key;      // scene key, e.g. "solver.jacobian"
  std::string message;  // what is wrong and what to do instead
  std::string what() const { return key + ": " + message; }
};

// Largest dense implicit Jacobian: p coordinates (four p x p matrices: 128 MB, O(p^3) per refresh).
constexpr int kMaxDenseCoordinates = 2000;

// Coordinates per rfe of a formulation ("absolute": 4; chains: 2, or 1 for an inextensible line).
int coordinatesPerRfe(FormulationKind formulation, bool axial_flexibility);
// The linear solves an implicit scheme uses for solver.jacobian (auto -> structured where the
// formulation has them, else dense).
JacobianKind resolvedJacobian(const SolverSettings& s);

// The settings' own values (dt, names of the choices, tolerance, jacobian_interval, rho_inf,
// newton_tolerance), whatever the space; the 3D core checks its combinations itself
// (spatial/run_builder.h, unsupported()).
std::optional<SetupError> checkSolverValues(const SolverSettings& s);
// What the planar core does not run: its combination of integrator, formulation and jacobian and its size
// limits for a line of `elements` segments (the values assumed checked).
std::optional<SetupError> planarUnsupported(const SolverSettings& s, int elements, bool axial_flexibility);
// checkSolverValues, then planarUnsupported.
std::optional<SetupError> checkSolverSetup(const SolverSettings& s, int elements, bool axial_flexibility);

}  // namespace riser_sim
