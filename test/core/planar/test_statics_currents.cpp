// Every shipped scene in currents of 0-3 m/s from every heading, in both engines: each start is either a stable
// equilibrium (no growing mode, nothing below the seabed, the rest checks) or refused with a message naming why,
// never accepted unstable. Long (~minutes of CPU): skipped by `make check` (RISER_SIM_CHECK=1) unless
// RISER_SIM_LONG=1; `make test` runs it.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim/planar/statics.h"

namespace riser_sim {
namespace {

namespace fs = std::filesystem;

bool longTestsSkipped() {
  const char* check = std::getenv("RISER_SIM_CHECK");
  const char* run_long = std::getenv("RISER_SIM_LONG");
  return check && std::string(check) == "1" && !(run_long && std::string(run_long) == "1");
}

std::string num(double v) {
  std::ostringstream o;
  o.precision(12);
  o << v;
  return o.str();
}

// The current override: a uniform vector of `speed` towards `heading`, or the scene's profile scaled so its
// fastest point has that speed and turned to that heading. Planar: along ±x only (heading 0 or π).
std::vector<std::string> currentOverrides(const Scene& s, double speed, double heading, bool planar) {
  const double c = std::cos(heading), sn = std::sin(heading);
  const CurrentSpec& cur = s.water.current;
  if (!cur.profile.empty()) {
    double fastest = 0.0;
    for (const auto& p : cur.profile) fastest = std::max(fastest, std::hypot(p.vx, p.vy));
    std::string prof = "environment.current.profile=[";
    for (size_t i = 0; i < cur.profile.size(); ++i) {
      const auto& p = cur.profile[i];
      const double mag = fastest > 0.0 ? std::hypot(p.vx, p.vy) / fastest * speed : speed;
      prof += (i ? ", [" : "[") + num(p.depth) + ", " + num(mag * c) + (planar ? "" : ", " + num(mag * sn)) + "]";
    }
    return {prof + "]"};
  }
  if (planar) return {"environment.current.velocity=[" + num(speed * c) + ", 0.0]"};
  return {"environment.current.velocity=[" + num(speed * c) + ", " + num(speed * sn) + ", 0.0]"};
}

// A refusal names its reason: a check, a scene key or the current's limit.
bool namesWhy(const std::string& m) {
  for (const char* why : {"stability:", "seabed", "residual", "tension:", "current", "bottom.position", "end_dx",
                          "initial.", "line.", "not an equilibrium", "twist", "plane"})
    if (m.find(why) != std::string::npos) return true;
  return false;
}

struct Tally {
  int accepted = 0, refused = 0;
  std::map<std::string, int> reasons;
};

std::string reasonOf(const std::string& m) {
  for (const char* why : {"stability:", "the equilibria from still water end", "in still water", "seabed:", "residual",
                          "not an equilibrium"})
    if (m.find(why) != std::string::npos) return why;
  return m.substr(0, 60);
}

TEST(StaticsCurrents, EveryShippedSceneInCurrentsIsStableOrRefused) {
  if (longTestsSkipped()) GTEST_SKIP() << "long: RISER_SIM_LONG=1 runs it under make check";
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  Tally planar, spatial;
  for (const fs::path& f : files) {
    const Scene base = loadSceneFile(f.string());
    if (!base.water.enabled) continue;  // no water, no current
    // Sectioned lines and attachments (their statics ramp loads, slower): 0 and 0.5 m/s, planar scenes in their
    // own engine towards +x (against it, the lazy wave's statics run to their 60 s limit), 3D scenes along and
    // across their plane (every speed and heading in 3D takes ~15 min).
    const bool reduced = !base.sections.empty() || !base.attachments.empty();
    // n small where the scene allows it (its first guess and checks do not depend on n).
    // (A sectioned line keeps its sections' element counts.)
    const std::string n =
        base.sections.empty() ? "line.elements=" + std::to_string(std::min(base.elements, 12)) : std::string();
    for (bool in3d : {false, true}) {
      if (!in3d && base.space == SpaceKind::kSpatial) continue;
      if (in3d && reduced && base.space != SpaceKind::kSpatial) continue;
      for (double speed : reduced ? std::vector<double>{0.0, 0.5} : std::vector<double>{0.0, 1.0, 2.0, 3.0}) {
        const int headings = speed == 0.0 || (reduced && !in3d) ? 1 : in3d ? (reduced ? 2 : 8) : 2;
        for (int h = 0; h < headings; ++h) {
          const double heading = in3d ? h * (reduced ? M_PI / 2.0 : M_PI / 4.0) : h * M_PI;
          std::vector<std::string> o;
          if (!n.empty()) o.push_back(n);
          if (in3d) o.push_back("space=spatial");
          for (const std::string& c : currentOverrides(base, speed, heading, !in3d)) o.push_back(c);
          Scene s;
          try {
            s = loadSceneFile(f.string(), o);
          } catch (const SceneError& e) {  // a planar scene with keys the 3D engine does not have
            ASSERT_TRUE(in3d) << e.what();
            ++(in3d ? spatial : planar).reasons[std::string("not a 3D scene: ") + e.key()];
            continue;
          }
          SCOPED_TRACE(f.filename().string() + (in3d ? " 3D" : " planar") + " at " + num(speed) + " m/s towards " +
                       num(heading * 180.0 / M_PI) + " deg");
          Tally& t = in3d ? spatial : planar;
          try {
            if (in3d) {
              const spatial::InitialState3 init =
                  spatial::solveInitialState3(s, spatial::buildTopMotion3(s.top)->at(0.0).p);
              // Accepted: at rest (the builder's bound), stable (the same check again: it throws), above the seabed
              // by at most the whole line's weight on one contact spring.
              EXPECT_LE(init.max_acceleration, init.acceleration_bound);
              if (init.equilibrium) spatial::checkStable(s, init, s.initial.type == InitialKind::kDisplaced);
              if (s.seabed.enabled && s.seabed.slope == 0.0)
                for (const auto& b : init.kin)
                  EXPECT_GT(b.end().z(), s.seabed.level - 2.0 * s.length * s.line.mass_per_length * s.gravity /
                                                              s.seabed.stiffness_normal);
            } else {
              const auto model = buildModel(s);
              // The top where the run starts it (a sinusoid's t = 0), as the check's problem has it.
              const InitialState init = solveInitialState(s, *model, staticsProblem(s).top);
              if (s.initial.type != InitialKind::kStraight) {
                const EquilibriumCheck c =
                    checkEquilibrium(*model, staticsProblem(s), init.kin, init.end_force);  // stability included
                EXPECT_TRUE(c.ok) << c.message;
              }
            }
            ++t.accepted;
          } catch (const std::exception& e) {
            ++t.refused;
            ++t.reasons[reasonOf(e.what())];
            std::printf("[currents] refused: %s %s at %g m/s towards %g deg: %.300s\n", f.filename().c_str(),
                        in3d ? "3D" : "planar", speed, heading * 180.0 / M_PI, e.what());
            EXPECT_TRUE(namesWhy(e.what())) << e.what();
          }
        }
      }
    }
  }
  const double cpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[currents] planar: %d accepted, %d refused; 3D: %d accepted, %d refused; %.1f s\n", planar.accepted,
              planar.refused, spatial.accepted, spatial.refused, cpu);
  for (const Tally* t : {&planar, &spatial})
    for (const auto& r : t->reasons)
      std::printf("[currents]   %s: %d x '%s'\n", t == &planar ? "planar" : "3D", r.second, r.first.c_str());
}

}  // namespace
}  // namespace riser_sim
