// Newton's starting points for the statics: inextensible catenaries, with the part that reaches the
// seabed laid flat on it.
#include <Eigen/LU>
#include <cmath>

#include "statics_residual.h"

namespace riser_sim {
namespace statics_detail {

namespace {

// Places the rfes (lengths l_i + Δ_i, Δ_i as set in kin) from the top along a curve at(σ) (σ:
// unstretched arc length from the top): each joint at the curve's height for its arc length, towards
// the curve's side. Heights matter most: a joint 1 cm into a stiff seabed carries a force far beyond
// the line's weight.
template <class At>
void placeAlong(const Model& model, const Vec2& top, At&& at, Kinematics& kin) {
  Vec2 A = top;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    const double len = r.length + kin[i].delta;
    const Vec2 target = at(r.s_begin + r.length), chord = at(r.s_begin + r.length) - at(r.s_begin);
    const double dy = target.y() - A.y();
    const double side =
        (std::abs(target.x() - A.x()) > 1e-12 * len ? target.x() - A.x() : chord.x()) < 0.0 ? -1.0 : 1.0;
    const double phi =
        std::abs(dy) < len ? std::atan2(dy, side * std::sqrt(len * len - dy * dy)) : (dy < 0.0 ? -M_PI / 2 : M_PI / 2);
    BodyKinematics& b = kin[i];
    b.A = A;
    b.phi = phi;
    b.c = std::cos(phi);
    b.s = std::sin(phi);
    b.len = len;
    A = b.end();
  }
}

// Δ_i of an elastic line under the tension T(σ) at the middle of each rfe (0 when inextensible).
template <class Tension>
void stretch(const Model& model, Tension&& T, Kinematics& kin) {
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    kin[i].delta = model.options().axial_flexibility ? T(r.s_begin + 0.5 * r.length) / r.axial_stiffness : 0.0;
  }
}

// Seabed sink of a contact point carrying one segment's weight [m] (0 without a seabed).
double segmentSink(const Model& model, const StaticTerms& terms, double w) {
  const double k = terms.seabedStiffness();
  return k > 0.0 ? std::max(w, 0.0) * model.segmentLength() / k : 0.0;
}

}  // namespace

double netWeightPerLength(const Model& model, const StaticTerms& terms, const Vec2& top) {
  // A horizontal line just below the top, at rest; the seabed left out.
  Kinematics probe = straightLine(model, top - Vec2(0.0, 1e-6), 0.0);
  VecX Q = VecX::Zero(model.dofs());
  for (size_t k = 0; k < terms.terms().size(); ++k)
    if (!terms.isSeabed(k)) terms.terms()[k]->addForces(model, nullptr, probe, 0.0, Q);
  double W = 0.0;
  for (int i = 0; i < model.bodies(); ++i) W -= Q[4 * i + kY];
  return (W - model.endMass() * model.gravity()) / model.length();
}

// Displaced end (problem (a)): horizontal force H at the end, vertical end load Ve, weight w per
// length; on a seabed the last part lies flat. Returns false when no such shape fits.
bool displacedGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin,
                    double& end_force) {
  const double L = model.length(), X = std::abs(p.end_dx);
  const double w = netWeightPerLength(model, terms, p.top), Ve = model.endMass() * model.gravity();
  if (!(w > 0.0)) return false;
  const double level = terms.seabedLevel();
  const double h = p.top.y() - level + segmentSink(model, terms, w);  // height above the sunk seabed
  const int m = 4000;
  // Horizontal extent of the shape for H; fills 'lay' (length on the seabed).
  auto extent = [&](double H, double& lay) {
    const double a = H / w;
    lay = 0.0;
    if (std::isfinite(h) && h > 0.0) {
      const double ss = a * std::sqrt(std::pow(h / a + 1.0, 2) - 1.0);
      if (ss < L) {
        lay = L - ss;
        return a * std::asinh(ss / a) + lay;
      }
    }
    double x = 0.0;
    for (int k = 0; k < m; ++k) {
      const double s = (k + 0.5) * L / m;
      x += L / m / std::sqrt(1.0 + std::pow((Ve + w * s) / H, 2));
    }
    return x;
  };
  double lo = 1e-6 * w * L, hi = 1e6 * w * L, lay = 0.0;
  if (extent(lo, lay) > X || extent(hi, lay) < X) return false;
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (extent(mid, lay) < X ? lo : hi) = mid;
  }
  const double H = hi;
  extent(H, lay);
  // Points from the end (σ = L) up to the top, each step stretched by T/EA (the Δ_i set below), then
  // shifted so the top is at p.top, or with a laid part, so that it lies on the sunk seabed.
  const double flex = model.options().axial_flexibility ? 1.0 / model.line().EA : 0.0;
  auto tension = [&](double s) {  // s from the end
    return std::hypot(H, s < lay ? 0.0 : (lay > 0.0 ? w * (s - lay) : Ve + w * s));
  };
  std::vector<Vec2> pts(m + 1);
  pts[0] = Vec2::Zero();
  for (int k = 0; k < m; ++k) {
    const double s = (k + 0.5) * L / m;
    const double V = s < lay ? 0.0 : (lay > 0.0 ? w * (s - lay) : Ve + w * s);
    const Vec2 dir = Vec2(H, V).normalized();
    pts[k + 1] = pts[k] + L / m * (1.0 + tension(s) * flex) * Vec2(-dir.x() * (p.end_dx < 0 ? -1.0 : 1.0), dir.y());
  }
  const Vec2 shift(p.top.x() - pts[m].x(), lay > 0.0 ? p.top.y() - h : p.top.y() - pts[m].y());
  auto at = [&](double sigma) {
    const double f = (L - sigma) / L * m;
    const int k = std::min(std::max(static_cast<int>(f), 0), m - 1);
    return Vec2(pts[k] + (f - k) * (pts[k + 1] - pts[k]) + shift);
  };
  end_force = p.end_dx < 0 ? -H : H;
  kin = straightLine(model, p.top, 0.0);
  stretch(
      model, [&](double sigma) { return tension(L - sigma); }, kin);
  placeAlong(model, p.top, at, kin);
  return true;
}

// Between points (problem (b)): the inextensible catenary through both points (the end mass hangs at
// the anchor, so it only adds to the anchor's vertical reaction). When that catenary would dip into a
// seabed and the anchor lies on it, the displaced-end shape (catenary, then laid) is used instead.
bool betweenPointsGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin,
                        Vec2& end_force) {
  const Vec2 chord = p.end_point - p.top;
  const double L = model.length(), c = chord.norm();
  const double Wm = model.endMass() * model.gravity();
  if (!(c < L)) return false;
  const double w = netWeightPerLength(model, terms, p.top);
  if (!(w > 0.0)) return false;
  // End of the catenary (from the top, arc length s) for an external end force Fe without end mass.
  auto endOf = [&](const Vec2& Fe, double s) {
    const double H = std::max(std::abs(Fe.x()), 1e-9 * w * L);
    const double V0 = -Fe.y() + w * L, Vs = -Fe.y() + w * (L - s);
    return Vec2(Fe.x() / w * (std::asinh(V0 / H) - std::asinh(Vs / H)), -(std::hypot(H, V0) - std::hypot(H, Vs)) / w);
  };
  // A chord (nearly) straight down has two mirror-image U shapes and an unstable folded one between
  // them: aim 1e-3 L to the side so that Newton starts on one of the U shapes.
  Vec2 aim = chord;
  if (std::abs(aim.x()) < 1e-3 * L) aim.x() = aim.x() < 0.0 ? -1e-3 * L : 1e-3 * L;
  Vec2 Fe(w * aim.x(), 0.5 * w * L);
  for (int it = 0; it < 100; ++it) {
    const Vec2 r = endOf(Fe, L) - aim;
    if (!r.allFinite()) return false;
    if (r.norm() < 1e-12 * L) break;
    Mat2 J;
    for (int j = 0; j < 2; ++j) {
      Vec2 F1 = Fe;
      const double h = 1e-7 * std::max(std::abs(Fe[j]), w * L);
      F1[j] += h;
      J.col(j) = (endOf(F1, L) - aim - r) / h;
    }
    const Vec2 dF = -J.inverse() * r;
    if (!dF.allFinite()) return false;
    double a = 1.0;
    while (a > 1e-3 && !((endOf(Fe + a * dF, L) - aim).norm() <= r.norm())) a *= 0.5;
    Fe += a * dF;
  }
  if (!((endOf(Fe, L) - aim).norm() < 1e-6 * L)) return false;
  kin = straightLine(model, p.top, 0.0);
  placeAlong(
      model, p.top, [&](double s) { return Vec2(p.top + endOf(Fe, s)); }, kin);
  end_force = Fe + Vec2(0.0, Wm);
  // Into the seabed: lay the rest on it if the anchor is on it (within a segment).
  const double level = terms.seabedLevel();
  bool dips = false;
  for (int i = 0; i < model.bodies(); ++i) dips = dips || kin[i].A.y() < level;
  if (dips && p.end_point.y() < level + model.segmentLength()) {
    StaticsProblem d = p;
    d.kind = StaticsProblem::Kind::kEndDisplaced;
    d.end_dx = chord.x();
    double H = 0.0;
    Kinematics laid;
    if (displacedGuess(model, d, terms, laid, H)) {
      kin = laid;
      end_force = Vec2(H, 0.0);
    }
  }
  for (const BodyKinematics& b : kin)
    if (!std::isfinite(b.phi)) return false;
  return end_force.allFinite();
}

bool hangingOnSeabedGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin) {
  const double level = terms.seabedLevel();
  if (!(p.top.y() - model.length() < level)) return false;  // hangs clear of the seabed
  const double w = netWeightPerLength(model, terms, p.top);
  if (!(w > 0.0)) return false;
  // Lay towards the steady horizontal loads (current) on the straight hanging line, else towards +x.
  kin = straightLine(model, p.top, -M_PI / 2);
  VecX Q = VecX::Zero(model.dofs());
  for (size_t k = 0; k < terms.terms().size(); ++k)
    if (!terms.isSeabed(k)) terms.terms()[k]->addForces(model, nullptr, kin, 0.0, Q);
  double fx = 0.0;
  for (int i = 0; i < model.bodies(); ++i) fx += Q[4 * i + kX];
  const double side = fx < 0.0 ? -1.0 : 1.0;
  const double y_bed = level - segmentSink(model, terms, w);
  Vec2 A = p.top;
  for (int i = 0; i < model.bodies(); ++i) {
    const Rfe& r = model.rfe(i);
    double above = A.y() - y_bed;
    // Stretch under the weight hanging below the rfe's middle (the laid part and the end mass rest on the seabed).
    const double T = w * std::max(above - 0.5 * r.length, 0.0);
    BodyKinematics& b = kin[i];
    b.delta = model.options().axial_flexibility ? T / r.axial_stiffness : 0.0;
    const double l = r.length + b.delta;
    double phi;
    if (above >= l)
      phi = -M_PI / 2;  // hanging
    else if (above > 0.0)
      phi = std::atan2(-above, side * std::sqrt(l * l - above * above));  // touching down
    else
      phi = side > 0.0 ? 0.0 : M_PI;  // laid
    b.phi = phi;
    b.c = std::cos(phi);
    b.s = std::sin(phi);
    b.len = l;
    b.A = A;
    A = b.end();
  }
  return true;
}

}  // namespace statics_detail
}  // namespace riser_sim
