// The natural modes of a scene about its static state, for either engine (planar: sceneModes, modal.h;
// space: spatial: computeModes3 about the 3D equilibrium, spatial/modal.h), as one engine-neutral
// report: what riser_sim_cli --modes prints and the node's ~modes returns.
//
// The top is held where the scene has it at t = 0, the statics' end force stays as a dead load, and the
// modes are undamped. A planar (x, y) with y up is the 3D point (x, 0, y).
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "riser_sim/scene/scene.h"
#include "riser_sim/types.h"

namespace riser_sim {

// ω² below spatial::kZeroOmega2 (1e-12) x the largest |ω²| the engine returned counts as no oscillation.
enum class ModeStatus { kOscillating, kZero, kUnstable };  // unstable: ω² < 0
const char* name(ModeStatus status);

struct ModeEntry {
  double omega2 = 0.0;       // ω² [1/s²]
  double omega = 0.0;        // [rad/s], 0 when ω² <= 0
  double period = 0.0;       // 2π/ω [s], 0 when ω = 0
  double frequency = 0.0;    // ω/2π [Hz]
  std::string character;     // one of modeCharacters(space)
  double axial_share = 0.0;  // share of the kinetic energy (rigid parts) moving along the line, 0..1
  ModeStatus status = ModeStatus::kOscillating;
  // Displacement of each point (ModesReport::points), unitless: the largest |displacement| is 1.
  AlignedVector<Eigen::Vector3d> displacement;
};

struct ModesReport {
  SpaceKind space = SpaceKind::kPlanar;
  int coordinates = 0;                // generalised coordinates of the linearisation
  int dofs = 0;                       // size of the eigenproblem: the most modes there are
  double equilibrium_residual = 0.0;  // max generalised force at the state / force scale: ~0 at equilibrium
  double asymmetry = 0.0;             // ||K - Kᵀ||_F / ||K||_F before symmetrisation
  // What the modes are about ("displaced static state", "hanging equilibrium (initial.type straight is none)",
  // "equilibrium relaxed from the straight start (...)"), and one line with it, the statics, the coordinates,
  // the end load and the residuals.
  std::string about, header;
  std::vector<double> arc_length;         // unstretched arc length of A_0..A_n and the end [m] (n + 2)
  AlignedVector<Eigen::Vector3d> points;  // A_0..A_n and the end at the state [m]
  std::vector<ModeEntry> modes;           // the lowest min(count, dofs), lowest first
};

// The scene's statics (its initial state with the top where scene.top has it at t = 0), then the lowest
// `count` modes about that equilibrium (fewer when the line has fewer: see dofs). Throws
// std::invalid_argument naming the key for bad input (count < 1, a 3D bottom that moves), std::runtime_error
// when the statics or the eigen-solve fail.
ModesReport sceneModesReport(const Scene& scene, int count);

// The characters an engine names its modes with: planar "transverse", "axial"; 3D "in-plane", "out-of-plane"
// (of the statics' vertical plane), "axial", "torsional".
const std::vector<std::string>& modeCharacters(SpaceKind space);

}  // namespace riser_sim
