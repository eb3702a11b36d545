#include "tradeoff_cases.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/scene/scene_yaml.h"
#include "validation_util.h"

namespace tradeoff {

using namespace riser_sim;

namespace {

// The paper's Table 1 line (the validation tests' definition).
Scene table1(int n, bool axial) {
  Scene s = validation::table1Scene(n);
  s.options.axial_flexibility = axial;
  return s;
}

Scene fromFile(const std::string& path, int n, bool axial) {
  Scene s = loadSceneFile(path);
  s.elements = n;
  s.options.axial_flexibility = axial;
  return s;
}

// The J-lay with a reference that converges in h and n (docs/benchmarks.md, "Tension against cost").
// Undamped, touch-down and lift-off on the stiff seabed springs keep ringing the axial mode, whose
// phase depends on h (contacts are detected at step ends); and the springs are per contact point, so
// the seabed's stiffness per metre, and the axial mode with it, grow with n (9.8 / 10.5 / 11.3 / 12.1 Hz
// at n = 40 / 100 / 160 / 300). The variant adds
//  - axial structural damping c_EA = 2 zeta EA / omega_1 = 2.21e6 N s: zeta = 2 % at the first axial
//    mode, omega_1 = 66.0 rad/s (10.51 Hz, riser_sim_cli --modes at n = 100), EA = E pi/4 (D_out^2 -
//    D_in^2) = 3.642e9 N; Kelvin-Voigt damping gives mode k zeta_k = c_EA omega_k / (2 EA), so the
//    second axial mode (22.2 Hz) gets 4.2 %;
//  - seabed springs per metre of line: the shipped values per point at n = 100's spacing (1.7 m),
//    scaled by d / 1.7 m, so n = 100 is the shipped scene plus damping and the axial mode stays at
//    10.4-10.9 Hz for n = 40..300.
Case jlayDamped(Case c, const std::string& jlay) {
  constexpr double kAxialDamping = 2.21e6;  // [N s]
  c.name = "jlay_elastic_damped";
  c.title = "170 m J-lay, elastic, 2 % axial damping, seabed springs per metre (middle point at 27 s)";
  c.note = "line.axial_damping = 2.21e6 N s (zeta = 2 % at 10.5 Hz), seabed springs x 100 / n";
  c.scene = [jlay](int n) {
    Scene s = fromFile(jlay, n, true);
    s.line.axial_damping = kAxialDamping;
    s.seabed.stiffness_normal *= 100.0 / n;
    s.seabed.stiffness_tangential *= 100.0 / n;
    return s;
  };
  return c;
}

// The elastic Table 1 line with a reference that converges in n: undamped, its force histories at n = 100
// and 200 differ by 7 % RMS (the end mass's axial ringing, excited by the release, never decays). The
// variant adds c_EA = 2 zeta EA / omega_1 = 1.84e5 N s: zeta = 2 % at the axial end-mass mode,
// omega_1 = 42.75 rad/s (6.80 Hz, riser_sim_cli --modes about the displaced state at n = 100; the
// hanging line's (omega L / c) tan(omega L / c) = m_line / m_end gives 6.62 Hz), EA = 1.963e8 N.
// References: midpoint (rk4's limit shrinks ~10x with the damping), the end position from them too.
Case table1Damped(Case c) {
  constexpr double kAxialDamping = 1.84e5;  // [N s]
  c.name = "table1_elastic_damped";
  c.title = "Table 1 line, elastic, 2 % axial damping (end x_s, y_s at 20 s)";
  c.note = "line.axial_damping = 1.84e5 N s (zeta = 2 % at 6.8 Hz)";
  c.scene = [](int n) {
    Scene s = table1(n, true);
    s.line.axial_damping = kAxialDamping;
    return s;
  };
  c.fixed_probe = false;
  c.ref_runs = {{200, "midpoint", 1e-3}, {400, "midpoint", 1e-3}, {400, "midpoint", 5e-4}};
  return c;
}

}  // namespace

std::vector<Case> allCases(const std::string& root) {
  const std::vector<int> ns = {10, 20, 40, 100, 200, 1000};
  std::vector<Case> cases;
  for (bool axial : {true, false}) {
    Case c;
    c.name = axial ? "table1_elastic" : "table1_inextensible";
    c.title = axial ? "Table 1 line, elastic (end x_s, y_s at 20 s)" : "Table 1 line, inextensible (end at 20 s)";
    c.scene = [axial](int n) { return table1(n, axial); };
    c.duration = 20.0;
    c.probe_s = 100.0;
    c.probe_relative = true;
    c.ns = ns;
    // Elastic: rk4 at half its limit, recursive, n = 320 (-49.917961, -86.604043); n = 240 differs by
    // 0.09 mm, n = 160 by 1.1 mm (the undamped axial end-mass mode's phase converges non-monotonically in
    // n; docs/benchmarks.md "Speed against accuracy"). Inextensible: docs/validation.md, Richardson from n = 80/160.
    c.fixed_probe = true;
    c.probe_ref = axial ? Vec2(-49.917961, -86.604043) : Vec2(-49.91890, -86.59851);
    c.probe_spread = axial ? 9e-5 : 1e-5;
    c.probe_source = axial ? "rk4, n = 320, h = 0.5x limit (n = 240: 0.09 mm; n = 160: 1.1 mm)"
                           : "docs/validation.md: Richardson from n = 80/160";
    // Force histories: rk4 at n = 200, well inside its limit (elastic) / at 2.5 ms (no axial mode);
    // n = 100 and the step doubled show its convergence.
    if (axial)
      c.ref_runs = {{100, "rk4", -0.5}, {200, "rk4", -0.5}, {200, "rk4", -0.25}};
    else
      c.ref_runs = {{100, "rk4", 5e-3}, {200, "rk4", 5e-3}, {200, "rk4", 2.5e-3}};
    cases.push_back(c);
    if (axial) cases.push_back(table1Damped(c));
  }
  const std::string jlay = root + "/config/scenes/paper_jlay_170m.yaml";
  for (bool axial : {true, false}) {
    Case c;
    c.name = axial ? "jlay_elastic" : "jlay_inextensible";
    c.title = std::string("170 m J-lay (Table 3), ") + (axial ? "elastic" : "inextensible") + " (middle point at 27 s)";
    c.scene = [jlay, axial](int n) { return fromFile(jlay, n, axial); };
    c.duration = 27.0;  // one period of the surge x_0 = 10 cos(2 pi t / 27)
    c.probe_s = 85.0;   // middle of the line (its end lies on the seabed)
    // n <= 300: the statics of the initial state (seabed contact) do not converge at n = 256, 320, 400,
    // 500 (and take minutes at n = 1000), so n = 1000 is left out here.
    c.ns = {10, 20, 40, 100, 200};
    c.ref_runs = {{160, "midpoint", 1e-3}, {300, "midpoint", 1e-3}, {300, "midpoint", 5e-4}};
    cases.push_back(c);
    if (axial) cases.push_back(jlayDamped(c, jlay));
  }
  {
    const std::string riser = root + "/config/scenes/paper_riser_500m.yaml";
    Case c;
    c.name = "riser500";
    c.title = "500 m riser (Table 2), lower end A at 60 s";
    c.scene = [riser](int n) { return fromFile(riser, n, true); };
    c.duration = 60.0;  // the vessel's transit (velocity profile) ends at 60 s
    c.probe_s = 500.0;
    c.ns = ns;
    c.ref_runs = {{200, "midpoint", 5e-3}, {400, "midpoint", 5e-3}, {400, "midpoint", 2.5e-3}};
    cases.push_back(c);
  }
  return cases;
}

double Measures::peak() const {
  double p = 0.0;
  for (double T : top_tension) p = std::max(p, T);
  return p;
}

double Measures::rms() const {
  double s2 = 0.0;
  for (double T : top_tension) s2 += T * T;
  return top_tension.empty() ? 0.0 : std::sqrt(s2 / double(top_tension.size()));
}

Vec2 probeAt(const LineOutputs& o, double length, int n, double s) {
  const double d = length / n;
  auto arc = [&](int k) { return k == 0 ? 0.0 : (k == n + 1 ? length : (k - 0.5) * d); };
  for (int k = 0; k <= n; ++k) {
    if (s <= arc(k + 1)) {
      const double w = (s - arc(k)) / (arc(k + 1) - arc(k));
      return (1.0 - w) * o.points[k] + w * o.points[k + 1];
    }
  }
  return o.points.back();
}

}  // namespace tradeoff
