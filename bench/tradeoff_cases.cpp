#include "tradeoff_cases.h"

#include "riser_sim/scene_yaml.h"
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
    // Tensions: rk4 at n = 100, well inside its limit (elastic) / at 5 ms (no axial mode).
    c.ref_runs = {{100, "rk4", axial ? -0.5 : 5e-3}};
    cases.push_back(c);
  }
  const std::string jlay = root + "/config/scenes/paper_jlay_170m.yaml";
  for (bool axial : {true, false}) {
    Case c;
    c.name = axial ? "jlay_elastic" : "jlay_inextensible";
    c.title = std::string("170 m J-lay (Table 3), ") + (axial ? "elastic" : "inextensible") +
              " (middle point at 27 s)";
    c.scene = [jlay, axial](int n) { return fromFile(jlay, n, axial); };
    c.duration = 27.0;  // one period of the surge x_0 = 10 cos(2 pi t / 27)
    c.probe_s = 85.0;   // middle of the line (its end lies on the seabed)
    // n <= 300: the statics of the initial state (seabed contact) do not converge at n = 256, 320, 400,
    // 500 (and take minutes at n = 1000), so n = 1000 is left out here.
    c.ns = {10, 20, 40, 100, 200};
    c.ref_runs = {{160, "midpoint", 1e-3}, {300, "midpoint", 1e-3}, {300, "midpoint", 5e-4}};
    cases.push_back(c);
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
