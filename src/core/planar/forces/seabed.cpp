#include "riser_sim/planar/forces/seabed.h"

#include <algorithm>
#include <cmath>

#include "riser_sim/physics/seabed_contact.h"

namespace riser_sim {

void Seabed::point(const Model& model, const Kinematics& kin, int j, int& body, double& s0, Vec2& p, Vec2& v) const {
  const int n1 = model.bodies();
  body = j < n1 ? j : n1 - 1;
  s0 = j < n1 ? 0.0 : model.rfe(body).length;
  const double kappa = j < n1 ? 0.0 : 1.0;
  p = kin[body].point(s0, kappa);
  v = kin[body].velocity(s0, kappa);
}

const double* Seabed::anchors(const TermData* data) {
  return data ? static_cast<const SeabedData*>(data)->anchor.data() : nullptr;
}

Vec2 Seabed::force(const double* anchor, int j, const Vec2& p, const Vec2& v, bool damping) const {
  const double pen = spec_.level - p.y();
  if (pen <= 0.0) return Vec2::Zero();
  const double fy =
      physics::contactNormalForce(spec_.stiffness_normal, pen, damping ? spec_.damping_normal * v.y() : 0.0);
  double fx = damping ? -spec_.damping_tangential * v.x() : 0.0;
  if (anchor && std::isfinite(anchor[j])) fx -= spec_.stiffness_tangential * (p.x() - anchor[j]);
  return Vec2(fx, fy);
}

template <class Visit>
void Seabed::forEachContact(const Model& model, const Kinematics& kin, Visit&& visit) const {
  for (int j = 0; j <= model.bodies(); ++j) {
    int body;
    double s0;
    Vec2 p, v;
    point(model, kin, j, body, s0, p, v);
    if (p.y() < spec_.level) visit(j, body, s0, p, v);
  }
}

void Seabed::addForces(const Model& model, const TermData* data, const Kinematics& kin, double, VecX& Q) const {
  const double* anchor = anchors(data);
  forEachContact(model, kin, [&](int j, int body, double s0, const Vec2& p, const Vec2& v) {
    Q.segment<4>(4 * body) += pointForce(kin[body], s0, j < model.bodies() ? 0.0 : 1.0, force(anchor, j, p, v, true));
  });
}

double Seabed::potentialEnergy(const Model& model, const TermData* data, const Kinematics& kin) const {
  const double* anchor = anchors(data);
  double e = 0.0;
  forEachContact(model, kin, [&](int j, int, double, const Vec2& p, const Vec2&) {
    const double pen = spec_.level - p.y();
    e += physics::contactSpringEnergy(spec_.stiffness_normal, pen);
    if (anchor && std::isfinite(anchor[j])) e += 0.5 * spec_.stiffness_tangential * std::pow(p.x() - anchor[j], 2);
  });
  return e;
}

// Damping power; the normal clamp (no pull) also removes energy, counted here as the difference.
double Seabed::power(const Model& model, const TermData* data, const Kinematics& kin, double) const {
  const double* anchor = anchors(data);
  double pw = 0.0;
  forEachContact(model, kin, [&](int j, int, double, const Vec2& p, const Vec2& v) {
    pw += (force(anchor, j, p, v, true) - force(anchor, j, p, v, false)).dot(v);
  });
  return pw;
}

std::unique_ptr<TermData> Seabed::makeData(const Model& model) const {
  auto data = std::make_unique<SeabedData>();
  data->anchor.assign(model.bodies() + 1, NAN);
  return data;
}

void Seabed::startRun(const Model& model, const Kinematics& kin, TermData& data) const {
  std::vector<double>& anchor = static_cast<SeabedData&>(data).anchor;
  std::fill(anchor.begin(), anchor.end(), NAN);
  endStep(model, kin, data);
}

// Anchors are set at touch-down and cleared at lift-off; in between they stay (no change reported).
bool Seabed::endStep(const Model& model, const Kinematics& kin, TermData& data) const {
  std::vector<double>& anchor = static_cast<SeabedData&>(data).anchor;
  bool changed = false;
  for (int j = 0; j <= model.bodies(); ++j) {
    int body;
    double s0;
    Vec2 p, v;
    point(model, kin, j, body, s0, p, v);
    const bool was_anchored = std::isfinite(anchor[j]);
    if (p.y() >= spec_.level) {
      anchor[j] = NAN;
      changed = changed || was_anchored;
    } else if (!was_anchored) {
      anchor[j] = p.x();
      changed = true;
    }
  }
  return changed;
}

int Seabed::contacts(const Model& model, const Kinematics& kin) const {
  int c = 0;
  forEachContact(model, kin, [&](int, int, double, const Vec2&, const Vec2&) { ++c; });
  return c;
}

}  // namespace riser_sim

namespace riser_sim {

// Contact springs and dampers on each point below the level, as in force(); a clamped normal force
// (the damper would pull) contributes nothing.
bool Seabed::addStiffness(const Model& model, const TermData* data, const Kinematics& kin, double,
                          StiffnessBlocks& S) const {
  const double* anchor = anchors(data);
  forEachContact(model, kin, [&](int j, int body, double s0, const Vec2& p, const Vec2& v) {
    const Vec2 F = force(anchor, j, p, v, true);
    const bool anchored = anchor && std::isfinite(anchor[j]);
    const bool pressing = F.y() > 0.0;
    Mat2 Kp = Mat2::Zero(), Cp = Mat2::Zero();
    Kp(0, 0) = anchored ? spec_.stiffness_tangential : 0.0;
    Cp(0, 0) = spec_.damping_tangential;
    Kp(1, 1) = pressing ? spec_.stiffness_normal : 0.0;
    Cp(1, 1) = pressing ? spec_.damping_normal : 0.0;
    addPointStiffness(kin[body], s0, j < model.bodies() ? 0.0 : 1.0, F, Kp, Cp, S.K_diag[body], S.C_diag[body]);
  });
  return true;
}

}  // namespace riser_sim
