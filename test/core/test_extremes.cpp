// Stability at the extremes (issue 5), table-driven: every integrator through very small and very
// large n, soft and stiff material on short elements, no and huge end mass, all-bending and
// no-bending lines, slack/compression, a teleporting top and h around the explicit stability limit.
// Each case asserts either a sound result (finite outputs, energy balance and constraint error within
// the case's stated bound) or a clean, early divergence (step() false, a reason naming solver.dt) -
// never NaN in the outputs of a run that reports success.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "riser_sim/scene.h"
#include "validation_util.h"

namespace riser_sim {
namespace {

enum class Expect { kSound, kSoundOrClean, kCleanDivergence };

struct Case {
  std::string name;
  std::function<Scene()> scene;
  std::vector<std::string> integrators;
  double duration;      // simulated [s]
  Expect expect;
  double energy_bound;  // |E - E0 - W| / max(|E0|, m g L) for a sound run (see each case)
  double dt_factor;     // > 0: rk4 runs at this multiple of Simulator::stableStepEstimate()
  std::function<void(Simulator&)> setup = nullptr;  // e.g. replace the top motion
};

// Constraint error of a sound run: explicit schemes at a resolved step keep joint gaps ≤ 1e-9 m; the
// implicit schemes on the absolute formulation hold them only through Baumgarte (ω_c = 50 rad/s) at a
// large h (measured 1.3e-4 d: rosenbrock2, end mass 0). 1e-3 d: 50x below the divergence threshold 0.05 d.
constexpr double kConstraintBoundPerD = 1e-3;
// Energy: conservative runs at a resolved step hold E - E0 - W to ~1e-9 (docs/validation.md); the
// implicit L-stable rosenbrock2 damps the unresolved axial mode (measured 1e-5 on Table 1), so sound
// runs are held to 1e-3 unless a case states otherwise.
constexpr double kEnergyBound = 1e-3;

const std::vector<std::string> kAll = {"rk4", "dopri5", "rosenbrock2", "midpoint"};

Scene shortLine(double E, int n, double end_mass) {
  Scene s = validation::table1Scene(n, 1e-3);
  s.length = 10.0;  // short elements: d = 10 / n
  s.line = LineProperties::fromGeometry(0.05, 0.0, E, 2000.0);
  s.end_mass = end_mass;
  s.initial.end_dx = -5.0;
  return s;
}

// A top that jumps 1 m sideways at t = 0.05 s with zero velocity (a vessel-position glitch).
class TeleportMotion : public TopMotion {
 public:
  std::string name() const override { return "teleport"; }
  PointMotion at(double t) const override {
    PointMotion m;
    m.p = Vec2(t < 0.05 ? 0.0 : 1.0, 0.0);
    return m;
  }
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"n1", [] { return validation::table1Scene(1); }, kAll, 2.0, Expect::kSound, kEnergyBound, 0.8});
  c.push_back({"n1000_absolute", [] { return validation::table1Scene(1000); }, {"rk4", "dopri5"}, 0.004,
               Expect::kSound, kEnergyBound, 0.8});
  c.push_back({"n1000_recursive_implicit",
               [] {
                 Scene s = validation::table1Scene(1000, 4e-4);  // ~20x rk4's limit at n = 1000
                 s.solver.formulation = "recursive";
                 s.solver.jacobian_interval = 10.0;  // one dense Jacobian (p = 2002) for the run
                 return s;
               },
               {"rosenbrock2"}, 0.008, Expect::kSound, kEnergyBound, 0.0});
  for (double E : {1e6, 1e9, 2.1e11}) {
    c.push_back({"E" + std::to_string(int(std::log10(E))) + "_short", [E] { return shortLine(E, 20, 10.0); }, kAll,
                 0.2, Expect::kSound, kEnergyBound, 0.8});
  }
  c.push_back({"end_mass_0", [] { return shortLine(1e9, 10, 0.0); }, kAll, 0.5, Expect::kSound, kEnergyBound, 0.8});
  c.push_back({"end_mass_1e6", [] { return shortLine(2.1e11, 10, 1e6); }, kAll, 0.5, Expect::kSound, kEnergyBound,
               0.8});
  c.push_back({"all_bending",
               [] {
                 Scene s = shortLine(2.1e11, 20, 0.0);
                 s.line = LineProperties::fromGeometry(0.05, 0.045, 2.1e11, 100.0);  // thin light tube
                 s.options.bending = true;
                 s.options.axial_flexibility = false;
                 s.initial.type = "straight";
                 s.initial.angle = -0.3;  // released 17 deg off horizontal: bending and pendulum
                 return s;
               },
               kAll, 0.5, Expect::kSound, kEnergyBound, 0.8});
  c.push_back({"no_bending", [] { return validation::table1Scene(20); }, kAll, 1.0, Expect::kSound, kEnergyBound,
               0.8});
  // Slack: a horizontal straight line (no tension) falls while the top is driven down at 20 m/s.
  c.push_back({"slack_top_down_fast",
               [] {
                 Scene s = shortLine(2.1e11, 20, 10.0);
                 s.initial.type = "straight";
                 s.initial.angle = 0.0;
                 s.top.type = "velocity_profile";
                 s.top.knots = {{0.0, Vec2(0.0, 0.0)}, {0.05, Vec2(0.0, -20.0)}};
                 return s;
               },
               kAll, 0.5, Expect::kSoundOrClean, 1e-2, 0.8});
  // Teleport: the energy balance does not hold (the jump does no tracked work), so only finiteness or
  // a clean stop is asserted.
  c.push_back({"vessel_teleport", [] { return shortLine(2.1e11, 10, 10.0); }, kAll, 0.2, Expect::kSoundOrClean,
               INFINITY, 0.8, [](Simulator& sim) { sim.setTopMotion(std::make_unique<TeleportMotion>()); }});
  // Around rk4's limit: 0.9x stable, 1.5x stops early with the limit in the message.
  c.push_back({"rk4_0.9x_limit", [] { return validation::table1Scene(40); }, {"rk4"}, 1.0, Expect::kSound,
               kEnergyBound, 0.9});
  // Midpoint's Newton cannot follow the undamped axial mode at h = 1 s (5400x rk4's limit, n = 100),
  // not even on h/8 (h = 0.05 s works through 2-4 substeps): it must stop at once, naming solver.dt,
  // with the last good state kept.
  c.push_back({"midpoint_beyond_newton",
               [] {
                 Scene s = validation::table1Scene(100, 1.0);
                 s.solver.formulation = "recursive";
                 return s;
               },
               {"midpoint"}, 2.0, Expect::kCleanDivergence, 0.0, 0.0});
  c.push_back({"rk4_1.5x_limit", [] { return validation::table1Scene(40); }, {"rk4"}, 1.0,
               Expect::kCleanDivergence, 0.0, 1.5});
  return c;
}

bool outputsFinite(const LineOutputs& o) {
  bool ok = std::isfinite(o.top_tension) && std::isfinite(o.max_tension) && std::isfinite(o.kinetic_energy) &&
            std::isfinite(o.potential_energy) && std::isfinite(o.constraint_error);
  for (const Vec2& p : o.points) ok = ok && p.allFinite();
  for (double f : o.axial_force) ok = ok && std::isfinite(f);
  return ok;
}

// Early: a divergence must be caught within this much simulated time (h · 2000 steps, or 0.2 s).
constexpr long kEarlySteps = 2000;

TEST(Extremes, Table) {
  for (const Case& c : cases()) {
    for (const std::string& integ : c.integrators) {
      SCOPED_TRACE(c.name + " / " + integ);
      Scene s = c.scene();
      s.solver.integrator = integ;
      if (integ == "dopri5") s.solver.tolerance = 1e-7;
      if (integ != "rk4" && integ != "dopri5" && c.dt_factor > 0.0) s.solver.dt = 1e-3;
      std::unique_ptr<Simulator> sim;
      try {
        sim = buildSimulator(s);
      } catch (const std::exception& e) {
        ADD_FAILURE() << "setup threw: " << e.what();
        continue;
      }
      if (integ == "rk4" && c.dt_factor > 0.0) {
        s.solver.dt = c.dt_factor * sim->stableStepEstimate();
        sim = buildSimulator(s);
      }
      if (c.setup) c.setup(*sim);
      const bool ok = sim->advanceTo(c.duration);
      std::printf("  %-26s %-12s dt %-10.3g %s\n", c.name.c_str(), integ.c_str(), s.solver.dt,
                  ok ? ("ok, energy drift " + std::to_string(sim->energyDrift()) + ", constraint " +
                        std::to_string(sim->constraintError()) + " m").c_str()
                     : ("stopped at step " + std::to_string(sim->steps()) + ": " + sim->divergenceReason()).c_str());
      if (!ok) {
        EXPECT_NE(c.expect, Expect::kSound) << "diverged: " << sim->divergenceReason();
        EXPECT_NE(sim->divergenceReason().find("solver.dt"), std::string::npos) << sim->divergenceReason();
        EXPECT_LE(sim->steps(), kEarlySteps) << "divergence caught late";
        if (integ != "rk4") EXPECT_TRUE(outputsFinite(sim->outputs())) << "last good state kept";
        if (integ == "rk4" && c.dt_factor > 1.0)
          EXPECT_NE(sim->divergenceReason().find("a safe solver.dt is"), std::string::npos)
              << sim->divergenceReason();
        continue;
      }
      EXPECT_NE(c.expect, Expect::kCleanDivergence) << "expected a clean divergence at dt = " << s.solver.dt;
      const LineOutputs& o = sim->outputs();
      EXPECT_TRUE(outputsFinite(o));
      EXPECT_LE(o.constraint_error, kConstraintBoundPerD * sim->model().segmentLength());
      if (std::isfinite(c.energy_bound)) EXPECT_LE(std::abs(sim->energyDrift()), c.energy_bound);
    }
  }
}

}  // namespace
}  // namespace riser_sim

namespace riser_sim {
namespace {

// One hour of the conservative Table 1 case (inextensible, n = 10, recursive) with the symmetric
// midpoint rule at h = 0.02 s: the energy error must stay bounded, not drift. Measured: |E - E0| ≤
// 2.4e-8 m g L at every 10-minute mark (docs/integrators.md); the bound leaves 4x for platforms.
constexpr double kLongRunDuration = 3600.0;  // [s] issue 5: "1 hour of simulated time"
constexpr double kLongRunEnergyBound = 1e-7;
TEST(Extremes, OneHourMidpointEnergyBounded) {
  Scene s = validation::table1Scene(10, 0.02);
  s.options.axial_flexibility = false;
  s.solver.formulation = "recursive";
  s.solver.integrator = "midpoint";
  auto sim = buildSimulator(s);
  double worst = 0.0;
  for (double t = 600.0; t <= kLongRunDuration + 1e-9; t += 600.0) {
    ASSERT_TRUE(sim->advanceTo(t)) << sim->divergenceReason();
    worst = std::max(worst, std::abs(sim->energyDrift()));
  }
  std::printf("  1 h, midpoint, h = 0.02 s: max |energy drift| %.3g, constraint error %.3g m\n", worst,
              sim->maxConstraintError());
  EXPECT_LE(worst, kLongRunEnergyBound);
  EXPECT_LE(sim->maxConstraintError(), 1e-9);  // free bottom, recursive: joints hold by construction
  EXPECT_TRUE(outputsFinite(sim->outputs()));
}

}  // namespace
}  // namespace riser_sim
