#include "riser_sim/line/line_sections.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace riser_sim {

double BendStiffener::at(double xi) const {
  xi = std::min(std::max(xi, 0.0), length);
  if (conical) {
    const double D = root_diameter + (tip_diameter - root_diameter) * xi / length;
    return line_EI + modulus * M_PI / 64.0 * (std::pow(D, 4) - std::pow(bore, 4));
  }
  const auto it = std::upper_bound(x.begin(), x.end(), xi);
  if (it == x.begin()) return EI.front();
  if (it == x.end()) return EI.back();
  const size_t k = size_t(it - x.begin());
  const double w = (xi - x[k - 1]) / (x[k] - x[k - 1]);
  return EI[k - 1] + w * (EI[k] - EI[k - 1]);
}

namespace {

// 5-point Gauss-Legendre on [a, b] of 1/EI(s).
template <class F>
double gauss5(double a, double b, F&& inv) {
  static const double xg[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double wg[5] = {0.5688888888888889, 0.4786286704257771, 0.4786286704257771, 0.2369268850561891,
                               0.2369268850561891};
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0.0;
  for (int k = 0; k < 5; ++k) s += wg[k] * inv(c + h * xg[k]);
  return h * s;
}

}  // namespace

double bendingCompliance(double a, double b, double L, double EI0, const std::vector<BendStiffener>& stiffeners) {
  // Breakpoints: the ends of every stiffener and its table knots, in arc length from the top.
  std::vector<double> cuts = {a, b};
  for (const BendStiffener& st : stiffeners) {
    auto add = [&](double x) {
      const double s = st.at_top ? x : L - x;
      if (s > a && s < b) cuts.push_back(s);
    };
    add(st.length);
    for (double x : st.x) add(x);
  }
  std::sort(cuts.begin(), cuts.end());
  auto EI = [&](double s) {
    for (const BendStiffener& st : stiffeners) {
      const double x = st.at_top ? s : L - s;
      if (x >= 0.0 && x <= st.length) return st.at(x);
    }
    return EI0;
  };
  double c = 0.0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double h = (cuts[k + 1] - cuts[k]) / 4.0;  // 4 sub-pieces: a conical EI ∝ D⁴ is smooth, not polynomial
    for (int q = 0; q < 4; ++q)
      c += gauss5(cuts[k] + q * h, cuts[k] + (q + 1) * h, [&](double s) { return 1.0 / EI(s); });
  }
  return c;
}

void smearModules(LineSection& s, double cd_n, double cd_t, double cm) {
  const BuoyancyModules& b = s.modules;
  const double D = s.props.outer_diameter, A = M_PI / 4.0 * D * D;
  const double f = b.length / b.pitch, per_length = b.volume / b.pitch;
  const double A_eq = A + per_length;
  const double ca_m = std::isnan(b.added_mass) ? cm - 1.0 : b.added_mass;
  s.props.mass_per_length += b.mass / b.pitch;
  s.props.outer_diameter = std::sqrt(4.0 * A_eq / M_PI);
  s.hydro.drag_diameter = b.outer_diameter * f + D * (1.0 - f);
  s.hydro.drag_normal = (b.drag_normal * b.outer_diameter * f + cd_n * D * (1.0 - f)) / s.hydro.drag_diameter;
  s.hydro.drag_tangential = cd_t * D / s.hydro.drag_diameter;
  s.hydro.inertia_coefficient = 1.0 + ((cm - 1.0) * A + ca_m * per_length) / A_eq;
}

ResolvedLine resolveLine(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners) {
  if (sections.empty()) throw std::invalid_argument("line.sections: at least one section");
  ResolvedLine r;
  double L = 0.0;
  for (const LineSection& s : sections) L += s.length;
  double s_top = 0.0;
  for (size_t k = 0; k < sections.size(); ++k) {
    const LineSection& sec = sections[k];
    const std::string key = "line.sections[" + std::to_string(k) + "]";
    if (!(sec.length > 0.0)) throw std::invalid_argument(key + ".length: must be > 0");
    if (sec.elements < 1) throw std::invalid_argument(key + ".elements: must be >= 1");
    const double d = sec.length / sec.elements;
    for (int e = 0; e < sec.elements; ++e) {
      const double a = s_top + e * d, b = a + d;
      bool stiff = false;
      for (const BendStiffener& st : stiffeners) {
        const double lo = st.at_top ? 0.0 : L - st.length, hi = st.at_top ? st.length : L;
        stiff = stiff || (b > lo && a < hi);
      }
      r.segment.push_back(d);
      r.section.push_back(int(k));
      r.stiffened.push_back(stiff);
      const double EI = sec.props.EI;
      if (stiff)
        r.compliance.push_back(bendingCompliance(a, b, L, EI, stiffeners));
      else
        r.compliance.push_back(EI > 0.0 ? d / EI : std::numeric_limits<double>::infinity());
    }
    s_top += sec.length;
  }
  return r;
}

}  // namespace riser_sim
