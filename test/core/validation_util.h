// Reference solutions and helpers shared by the validation tests (test/core/test_*.cpp):
// analytic elastic catenary, complete elliptic integral, pendulum period, zero-crossing timing,
// convergence orders and the paper's Table 1 scene.
#pragma once
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim {
namespace validation {

// ---------------------------------------------------------------------------------------------
// Elastic catenary with a point load at the end, parametrised by the unstretched arc length s from
// the top (s = 0) to the end (s = L). External end force (Fx, Fy) plus an end weight W_end = m_s g:
// the part [s, L] is pulled by the part above with P(s) = (-Fx, V(s)), V(s) = W_end - Fy + w (L - s),
// tension T(s) = |P(s)|, and dr/ds = -(P/T)(1 + T/EA). Integrating in closed form (H = |Fx| > 0):
//   x(s) = (Fx/w) [asinh(V0/H) - asinh(V(s)/H)] + Fx s / EA
//   y(s) = -(1/w) [T(0) - T(s)] - (V0 s - w s²/2) / EA,     V0 = V(0)
// EA = +inf gives the inextensible catenary.
struct Catenary {
  double L = 0.0;         // unstretched length [m]
  double w = 0.0;         // weight per unit length [N/m]
  double EA = 0.0;        // axial stiffness [N] (inf: inextensible)
  double W_end = 0.0;     // end weight m_s g [N]
  Vec2 F = Vec2::Zero();  // external end force [N]

  double V(double s) const { return W_end - F.y() + w * (L - s); }
  double T(double s) const { return std::hypot(F.x(), V(s)); }
  // Position relative to the top at unstretched arc length s.
  Vec2 at(double s) const {
    const double H = std::abs(F.x()), V0 = V(0.0), Vs = V(s);
    const double flex = std::isinf(EA) ? 0.0 : 1.0 / EA;
    double x, y;
    if (H > 0.0) {
      x = F.x() / w * (std::asinh(V0 / H) - std::asinh(Vs / H)) + F.x() * s * flex;
      y = -(T(0.0) - T(s)) / w;
    } else {  // straight down: dr/ds = (0, -sign(V)(1 + |V|/EA))
      x = 0.0;
      y = -s;
    }
    y -= (V0 * s - 0.5 * w * s * s) * flex;
    return Vec2(x, y);
  }
  Vec2 end() const { return at(L); }
};

// Horizontal end force Fx that moves the end by dx (problem (a) of the statics), by the secant method
// on the monotone map Fx -> x_end(Fx).
inline double catenaryForceForOffset(Catenary c, double dx) {
  auto f = [&](double fx) {
    c.F.x() = fx;
    return c.end().x() - dx;
  };
  double a = dx * (c.W_end + 0.5 * c.w * c.L) / c.L, b = 1.5 * a;  // two guesses of the right sign
  double fa = f(a), fb = f(b);
  for (int k = 0; k < 100 && std::abs(fb) > 1e-14 * c.L; ++k) {
    const double next = b - fb * (b - a) / (fb - fa);
    a = b;
    fa = fb;
    b = next;
    fb = f(b);
  }
  return b;
}

// Largest distance [m] between the solver's joints A_0..A_n, end point and the analytic catenary
// at the same unstretched arc lengths.
inline double catenaryShapeError(const Model& model, const Kinematics& kin, const Catenary& c) {
  const Vec2 top = kin[0].A;
  double err = 0.0;
  for (int i = 0; i < model.bodies(); ++i) err = std::max(err, (kin[i].A - top - c.at(model.rfe(i).s_begin)).norm());
  return std::max(err, (kin.back().end() - top - c.end()).norm());
}

// ---------------------------------------------------------------------------------------------
// Catenary resting on a flat rigid seabed: the top at height h above it, the end at horizontal
// distance X from the top, lying on the seabed with no friction, so the horizontal tension H is the
// same everywhere and the suspended part (unstretched length s) meets the seabed tangentially (V = 0
// at the touchdown). Elastic (EA) or inextensible (EA = inf); weight w per unstretched length:
//   h = (H/w) (sqrt(1 + (w s/H)²) - 1) + w s² / (2 EA)
//   X = (H/w) asinh(w s/H) + H s/EA + (L - s)(1 + H/EA)
// Valid while 0 < s < L (part of the line lies on the seabed).
struct SeabedCatenary {
  double L = 0.0, w = 0.0, EA = INFINITY, h = 0.0, X = 0.0;
  double H = 0.0, s = 0.0;  // solution: horizontal tension [N], suspended unstretched length [m]

  double flex() const { return std::isinf(EA) ? 0.0 : 1.0 / EA; }
  // Suspended length for tension H (height equation, increasing in s: bisection).
  double suspended(double Hh) const {
    double lo = 0.0, hi = 2.0 * h + 10.0 * Hh / w + L;
    for (int k = 0; k < 200; ++k) {
      const double m = 0.5 * (lo + hi);
      const double y = Hh / w * (std::sqrt(1.0 + std::pow(w * m / Hh, 2)) - 1.0) + 0.5 * w * m * m * flex();
      (y < h ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
  }
  double touchdownX(double Hh, double ss) const { return Hh / w * std::asinh(w * ss / Hh) + Hh * ss * flex(); }
  double extent(double Hh) const {
    const double ss = suspended(Hh);
    return touchdownX(Hh, ss) + (L - ss) * (1.0 + Hh * flex());
  }
  // Solves for H (X increases with H) and s; returns false when no part of the line would lie on the seabed.
  bool solve() {
    double lo = 1e-9 * w * L, hi = 1e9 * w * L;
    for (int k = 0; k < 300; ++k) {  // largest H that leaves some length on the seabed
      const double m = std::sqrt(lo * hi);
      (suspended(m) < L ? lo : hi) = m;
    }
    hi = lo;
    lo = 1e-9 * w * L;
    for (int k = 0; k < 300; ++k) {
      const double m = std::sqrt(lo * hi);
      (extent(m) < X ? lo : hi) = m;
    }
    H = std::sqrt(lo * hi);
    s = suspended(H);
    return s < L;
  }
  double topTension() const { return std::hypot(H, w * s); }
  double touchdownX() const { return touchdownX(H, s); }
};

// ---------------------------------------------------------------------------------------------
// Complete elliptic integral of the first kind K(k) = π / (2 AGM(1, sqrt(1 - k²))).
inline double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 60 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return M_PI / (2.0 * a);
}

// Exact period of a pendulum of length l released from rest at theta0 [rad].
inline double pendulumPeriod(double l, double g, double theta0) {
  return 4.0 * std::sqrt(l / g) * ellipticK(std::sin(0.5 * theta0));
}

// ---------------------------------------------------------------------------------------------
// Times at which the samples (t_k, x_k) cross zero, linearly interpolated.
inline std::vector<double> zeroCrossings(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> out;
  for (size_t k = 1; k < x.size(); ++k)
    if ((x[k - 1] < 0.0) != (x[k] < 0.0)) out.push_back(t[k - 1] + (t[k] - t[k - 1]) * x[k - 1] / (x[k - 1] - x[k]));
  return out;
}

// Observed convergence order from errors at resolutions refined by `ratio`.
inline double order(double e_coarse, double e_fine, double ratio = 2.0) {
  return std::log(std::abs(e_coarse) / std::abs(e_fine)) / std::log(ratio);
}

// Richardson extrapolation of f(h) = f* + C h^p from f(h) and f(h/2).
inline double richardson(double f_coarse, double f_fine, double p) {
  const double r = std::pow(2.0, p);
  return (r * f_fine - f_coarse) / (r - 1.0);
}

// ---------------------------------------------------------------------------------------------
// The paper's section 2.3 / Table 1 case: m_s = 1000 kg on L = 100 m, E = 1e11 Pa, ρ = 2000 kg/m³,
// R = 0.025 m, no bending, end displaced by 50 m under a horizontal force, RK4, h = 1e-4 s.
inline Scene table1Scene(int n, double dt = 1e-4) {
  Scene s;
  s.name = "table1";
  s.length = 100.0;
  s.elements = n;
  s.line = LineProperties::fromGeometry(0.05, 0.0, 1e11, 2000.0);
  s.options.bending = false;
  s.end_mass = 1000.0;
  s.initial.type = InitialKind::kDisplaced;
  s.initial.end_dx = -50.0;
  s.solver.dt = dt;
  s.duration = 20.0;
  return s;
}

}  // namespace validation
}  // namespace riser_sim
