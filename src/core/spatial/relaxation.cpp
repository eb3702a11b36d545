#include "riser_sim/spatial/relaxation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/spatial/simulator.h"

namespace riser_sim {
namespace spatial {

namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

// Moves the points A_1..A_n of a chain from A_0 so that its end lies on `anchor`, each by the end's gap times its
// arc length's fraction of the whole (the planar statics' end is on it to round-off; a first guess's within ~1e-3
// of the length): every rfe keeps its direction and stretch to that order.
void closeOnto(Kinematics3& kin, const Vec3& anchor) {
  const Vec3 gap = anchor - kin.back().end();
  double total = 0.0;
  for (const BodyKinematics3& b : kin) total += b.len;
  std::vector<Vec3> points(kin.size() + 1);
  double s = 0.0;
  for (size_t i = 0; i < kin.size(); ++i) {
    points[i] = kin[i].A + (s / total) * gap;
    s += kin[i].len;
  }
  points.back() = anchor;
  for (size_t i = 0; i < kin.size(); ++i) {
    BodyKinematics3& b = kin[i];
    const Vec3 d = points[i + 1] - points[i];
    const double rest = b.len - b.delta;  // l_i
    b.A = points[i];
    b.len = d.norm();
    b.e = d / b.len;
    b.delta = b.len - rest;
  }
}

}  // namespace

namespace {

// The relaxation with the spins as `spins` says (BuildOptions).
Relaxed3 relax(const Scene& scene, BuildOptions::Spins spins, const Kinematics3& guess_in, const Vec3& top,
               double bound, const Vec3& end_force, double moment_bound) {
  // Torsion with isotropic bending: the shape first, with the spins off (a stiff GJ makes the twist's modes
  // fast and the relaxation's Newton stiff); the spins then start untwisted on that shape, where the twist
  // moments vanish unless something couples them to it (a torsional flex joint, a swivel, a held end force).
  Kinematics3 guess = guess_in;
  double pre_time = 0.0;
  int pre_steps = 0;
  if (scene.torsion.enabled && !scene.bending_axes.enabled && spins != BuildOptions::Spins::kOff) {
    const Relaxed3 shape = relax(scene, BuildOptions::Spins::kOff, guess, top, bound, end_force, moment_bound);
    guess = shape.kin;
    pre_time = shape.time;
    pre_steps = shape.steps;
  }
  // The scene's line in its steady sea, the end as the start holds it (a pinned one at bottom.position, a free one
  // under end_force). The rest does not depend on inertia, so the relaxation chooses the spins' (BuildOptions::
  // Spins::kRelaxation): no slow, lightly damped torsional mode (an end body's polar inertia on a soft twist)
  // outlasts the budget (its steps kill the fast ones); the translations keep their masses under the damping α M,
  // which decays every mode at α/2 whatever the masses. The seabed's friction and tangential damper vanish at rest
  // (they would only slow the creep to it), and the drag is the static load on the line held still (its damping
  // would overdamp the slow modes).
  BuildOptions o;
  o.terms.steady_sea = true;
  o.terms.drag_on_line_at_rest = true;
  o.terms.seabed_friction = false;
  o.spins = spins == BuildOptions::Spins::kOff ? spins : BuildOptions::Spins::kRelaxation;
  const bool pinned = scene.bottom == BottomBoundary::kPinned;
  if (pinned)
    closeOnto(guess, scene.bottom_point);
  else
    o.end_force = end_force;
  // The slowest mode of a hanging line is about its pendulum, ω1 ~ sqrt(g_wet / L) (g_wet: gravity less the
  // buoyancy of the whole line; the current and the pins stiffen it). α = 2 ω1 damps it critically and every
  // faster mode at α/2; a mode slower than the estimate would creep (at ω²/α), so ω1 errs low.
  const std::shared_ptr<const Model3> undamped = buildModel3(scene, o);
  const Model& line = undamped->line();
  double volume = 0.0;  // the line's displaced volume [m^3]
  for (int k = 0; k < line.sectionCount(); ++k) volume += line.section(k).props.externalArea() * line.section(k).length;
  const double lift = scene.water.enabled ? scene.water.density * volume : 0.0;
  const double g_wet = scene.gravity * std::max(1.0 - lift / line.totalMass(), 0.05);
  const double w1 = std::sqrt(std::max(g_wet, 1e-3) / scene.length);
  o.mass_damping = 2.0 * w1;
  const std::shared_ptr<Model3> model = buildModel3(scene, o);
  // The checks at rest see the start's model (restModel3) with the end held where this one holds it.
  BuildOptions at_rest;
  at_rest.terms.steady_sea = true;
  at_rest.spins = o.spins == BuildOptions::Spins::kOff ? o.spins : BuildOptions::Spins::kScene;
  if (pinned)
    at_rest.pinned_at = scene.bottom_point;
  else
    at_rest.end_force = end_force;
  const std::shared_ptr<Model3> rest = buildModel3(scene, at_rest);
  IntegratorOptions io;
  io.jacobian = JacobianKind::kStructured;
  io.rho_inf = 0.0;
  io.tolerance = scene.solver.tolerance;
  Simulator3 sim(model, std::make_unique<FixedMotion3>(top), IntegratorKind::kGeneralizedAlpha, io,
                 scene.solver.stabilization);
  sim.reset(guess, 0.0);
  Relaxed3 out;
  if (model->hasTorsion()) {  // the hang-off's frame the run holds: the check uses the same (torsion.h, HangOff)
    const TwistFrames& f = sim.lastEvaluation().twist.frames;
    out.hang_off = HangOff{f.top_axis, f.top_ref};
  }
  int where = 0, moment_where = 0;
  double moment = 0.0;
  out.kin = guess;
  out.time = pre_time;
  out.steps = pre_steps;
  const auto atRest = [&] {
    out.acceleration = restAcceleration(*rest, scene.solver.stabilization, out.kin, top, out.material_axes, where,
                                        moment, moment_where, out.hang_off);
    return out.acceleration <= 0.01 * bound && moment <= 0.01 * moment_bound;
  };
  // The untwisted spins on the relaxed shape: done when they are at rest within the bounds (a stiff GJ
  // turns the round-off of the twist into moments the relaxation's 1/100 margin would chase in vain).
  // The end's force in the state at rest: a pinned end's is its anchor's reaction.
  const auto finish = [&] {
    out.end_force = end_force;
    if (pinned) {
      sim.reset(out.kin, sim.time(), out.hang_off);
      if (!out.material_axes.empty()) sim.setMaterialAxes(out.material_axes);
      out.end_force = -sim.evaluate().reactions.bottom;
    }
    return out;
  };
  if (!atRest() && pre_steps > 0 && out.acceleration <= bound && moment <= moment_bound) return finish();
  double h = 0.2 / w1;              // 5 steps per time constant 1/ω1 of the slowest mode (ρ∞ = 0 damps the rest)
  const double budget = 60.0 / w1;  // 60 time constants: e^-60 of any start the planar statics give
  const int kCheck = 10;
  while (!atRest()) {
    if (sim.time() >= budget)
      throw std::runtime_error(
          "initial: the 3D equilibrium (dynamic relaxation from the planar statics) did not "
          "converge in " +
          fmt(out.time) + " s: acceleration at rest " + fmt(out.acceleration) + " m/s^2 at rfe " +
          std::to_string(where) + " (bound " + fmt(bound) + " m/s^2 from initial.tolerance), moment on a spin " +
          fmt(moment) + " N m at rfe " + std::to_string(moment_where));
    for (int k = 0; k < kCheck; ++k) {
      if (!sim.step(h)) {  // Newton failed at this step: restart from the last state with half the step
        if (h < 1e-4 / w1)
          throw std::runtime_error("initial: the 3D equilibrium (dynamic relaxation) failed: " +
                                   sim.integrator().failure());
        h *= 0.5;
        sim.reset(out.kin, sim.time(), out.hang_off);
        if (!out.material_axes.empty()) sim.setMaterialAxes(out.material_axes);
        break;
      }
      ++out.steps;
    }
    out.time = pre_time + sim.time();
    sim.kinematics(out.kin);
    for (BodyKinematics3& b : out.kin) b.A_dot.setZero(), b.delta_dot = 0.0, b.e_dot.setZero();
    if (model->hasTorsion()) {  // the spins as material axes (frame-free)
      const TwistFrames& f = sim.lastEvaluation().twist.frames;
      out.material_axes.resize(model->bodies());
      for (int i = 0; i < model->bodies(); ++i)
        out.material_axes[i] = materialDirector(f, i, out.kin[i].e.normalized(), sim.state()[model->dofs() + i]);
    }
  }
  return finish();
}

}  // namespace

Relaxed3 relaxToRest(const Scene& scene, const Kinematics3& guess, const Vec3& top, double bound, const Vec3& end_force,
                     double moment_bound) {
  return relax(scene, BuildOptions::Spins::kScene, guess, top, bound, end_force, moment_bound);
}

Relaxed3 relaxFromFirstGuess(const Scene& scene, const Model& planar, const StaticsProblem& problem, const Mat3& R,
                             const Vec3& offset, const Vec3& top, double bound) {
  Vec2 end_force = Vec2::Zero();  // a pinned end's is its anchor's; a free end hangs
  const Kinematics guess = staticsFirstGuess(planar, problem, end_force);
  return relaxToRest(scene, fromPlanar(guess, R, offset), top, bound);
}

double restAccelerationBound(const Scene& scene, const Model& line) {
  double m_min = INFINITY;
  for (int i = 0; i < line.bodies(); ++i) m_min = std::min(m_min, line.rfe(i).mass);
  const double W = line.totalMass() * scene.gravity;
  return 100.0 * scene.initial.tolerance * W / m_min + 1e-9 * std::max(scene.gravity, 1.0);
}

}  // namespace spatial
}  // namespace riser_sim
