#include "riser_sim/spatial/torsion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "riser_sim/spatial/bending_axes.h"
#include "riser_sim/spatial/model.h"

namespace riser_sim {
namespace spatial {

namespace {
Vec3 dir(const BodyKinematics3& b) { return b.e / b.e.norm(); }
// The reference of rfe i's chart at direction n.
Vec3 reference(const TwistFrames& f, int i, const Vec3& n) { return minimalRotation(f.centre[i], n, f.ref[i]); }
// Angle about axis from a to b (both ⟂ axis) [rad], in (-π, π].
double angleAbout(const Vec3& a, const Vec3& b, const Vec3& axis) { return std::atan2(axis.dot(a.cross(b)), a.dot(b)); }
Vec3 unitPerp(const Vec3& x, const Vec3& n) { return (x - x.dot(n) * n).normalized(); }
// Reference twist of joint k, unwrapped against the stored one.
double referenceTwist(const TwistFrames& f, int k, const Vec3& n0, const Vec3& n1) {
  const Vec3 u0 = minimalRotation(n0, n1, reference(f, k, n0)), u1 = reference(f, k + 1, n1);
  const double raw = angleAbout(u0, u1, n1);
  return f.mref[k] + std::remainder(raw - f.mref[k], 2.0 * M_PI);
}
}  // namespace

void TwistData::resize(int bodies) {
  const int nj = bodies - 1;
  frames.centre.assign(bodies, Vec3::Zero());
  frames.ref.assign(bodies, Vec3::Zero());
  frames.mref.assign(nj, 0.0);
  m.assign(nj, 0.0);
  mdot.assign(nj, 0.0);
  tau.assign(nj, 0.0);
  kb.assign(nj, Vec3::Zero());
  moment.assign(bodies, 0.0);
  bend.assign(bodies, 0.0);
  m1.assign(bodies, Vec3::Zero());
}

double twistStiffness(const Model3& model) { return model.torsion().stiffness / model.line().segmentLength(); }
double twistDamping(const Model3& model) { return model.torsion().damping / model.line().segmentLength(); }
int firstSpin(const Model3& model) {
  const TorsionProperties& t = model.torsion();
  return t.free_top || t.top_stiffness > 0.0 ? 0 : 1;
}
double hangOffTwist(const Model3& model, const TwistData& d) { return firstSpin(model) > 0 ? d.moment[0] : d.top_tau; }
double polarInertia(const Model3& model, int i) {
  if (i < firstSpin(model)) return 0.0;
  const TorsionProperties& t = model.torsion();
  return t.polar_inertia * model.rfe(i).length + (i == model.bodies() - 1 ? t.end_polar_inertia : 0.0);
}

void initTwistFrames(const Kinematics3& kin, TwistFrames& f, const Vec3& axis1, const HangOff& hang) {
  const int nb = int(kin.size());
  const Vec3 n0 = dir(kin[0]);
  int axis = 0;  // the world axis least aligned with e_0
  n0.cwiseAbs().minCoeff(&axis);
  f.centre[0] = n0;
  if (!hang.given() && axis1.squaredNorm() > 0.0 && !(axis1.cross(n0).norm() > 1e-6 * axis1.norm()))
    throw std::invalid_argument("the bending axis 1 lies along the top rfe: no material frame");
  f.ref[0] = unitPerp(axis1.squaredNorm() > 0.0 ? axis1 : Vec3::Unit(axis), n0);
  if (hang.given()) f.centre[0] = hang.axis.normalized(), f.ref[0] = unitPerp(hang.ref, f.centre[0]);
  for (int i = 1; i < nb; ++i) {
    const Vec3 np = dir(kin[i - 1]), n = dir(kin[i]);
    f.centre[i] = n;
    f.ref[i] = unitPerp(minimalRotation(np, n, reference(f, i - 1, np)), n);
  }
  for (double& m : f.mref) m = 0.0;
  f.top_axis = f.centre[0];
  f.top_ref = f.ref[0];
  f.top_mref = 0.0;
  holdHangOff(f, Mat3::Identity());
}

void holdHangOff(TwistFrames& f, const Mat3& R0) {
  f.hold_axis = R0.transpose() * f.top_axis;
  f.hold_ref = R0.transpose() * f.top_ref;
  f.top_w.setZero();
}

void turnHangOff(TwistFrames& f, const Mat3& R, const Vec3& w, bool held) {
  f.top_axis = R * f.hold_axis;
  f.top_ref = R * f.hold_ref;
  f.top_w = w;
  if (held) f.centre[0] = f.top_axis, f.ref[0] = f.top_ref;
}

// The holder turns (h, r_h) at w with e_0 fixed: turning everything at w spins the transported reference by w·n0,
// and e_0 turned back by -w × n0 spins it by a(h, n0)·(-w × n0): together w·(h + n0) / (1 + h·n0).
double hangOffSpin(const TwistFrames& f, const Vec3& n0) {
  return f.top_w.dot(f.top_axis + n0) / (1.0 + f.top_axis.dot(n0));
}

double topSpringTwist(const Kinematics3& kin, double theta0, const TwistFrames& f) {
  const Vec3 n0 = dir(kin[0]);
  const double raw = angleAbout(minimalRotation(f.top_axis, n0, f.top_ref), reference(f, 0, n0), n0);
  return theta0 + f.top_mref + std::remainder(raw - f.top_mref, 2.0 * M_PI);
}

void refreshTwistBranches(const Kinematics3& kin, TwistFrames& f, int first) {
  const int nb = int(kin.size());
  for (int k = 0; k + 1 < nb; ++k) f.mref[k] = referenceTwist(f, k, dir(kin[k]), dir(kin[k + 1]));
  if (first == 0) f.top_mref = topSpringTwist(kin, 0.0, f);
}

void rechartTwistFrames(const Kinematics3& kin, TwistFrames& f, int first) {
  const int nb = int(kin.size());
  refreshTwistBranches(kin, f, first);
  for (int i = first; i < nb; ++i) {
    const Vec3 n = dir(kin[i]);
    f.ref[i] = unitPerp(reference(f, i, n), n);
    f.centre[i] = n;
  }
}

Vec3 materialDirector(const TwistFrames& f, int i, const Vec3& e, double theta) {
  const Vec3 u = unitPerp(reference(f, i, e), e);
  return std::cos(theta) * u + std::sin(theta) * e.cross(u);
}

void spinsFromAxes(const Kinematics3& kin, const TwistFrames& f, const AlignedVector<Vec3>& m1, double* theta) {
  for (int i = 0; i < int(kin.size()); ++i) {
    const Vec3 n = dir(kin[i]);
    theta[i] = angleAbout(unitPerp(reference(f, i, n), n), m1[i], n);
  }
}

void twistAngles(const Kinematics3& kin, const double* theta, const TwistFrames& f, double* m, Vec3* kb) {
  const int nb = int(kin.size());
  for (int k = 0; k + 1 < nb; ++k) {
    const Vec3 n0 = dir(kin[k]), n1 = dir(kin[k + 1]);
    m[k] = theta[k + 1] - theta[k] + referenceTwist(f, k, n0, n1);  // θ_0 = 0 when the hang-off holds it
    kb[k] = n0.cross(n1) / (1.0 + n0.dot(n1));
  }
}

double topSpinRate(const Kinematics3& kin, const TwistFrames& f) {
  const Vec3 n0 = dir(kin[0]);
  return spinConnection(f.centre[0], n0).dot(kin[0].e_dot) + hangOffSpin(f, n0);
}

double addTwistForces(const Model3& model, const Kinematics3& kin, const double* theta, const double* omega,
                      TwistData& d, VecX& Q) {
  const int nb = model.bodies(), nj = nb - 1;
  const double k = twistStiffness(model), c = twistDamping(model);
  twistAngles(kin, theta, d.frames, d.m.data(), d.kb.data());
  const bool held = firstSpin(model) > 0;
  const double w0 = held ? topSpinRate(kin, d.frames) : omega[0];
  double power = 0.0;
  for (int j = 0; j < nj; ++j) {
    d.mdot[j] = omega[j + 1] - (j == 0 ? w0 : omega[j]) + d.kb[j].dot(kin[j].e_dot + kin[j + 1].e_dot);
    d.tau[j] = k * d.m[j] + c * d.mdot[j];
    power -= c * d.mdot[j] * d.mdot[j];
  }
  // A turning hang-off moves the twist next to it by -s: the holder's work -τ s (with ∂V/∂t in it).
  const double s = hangOffSpin(d.frames, dir(kin[0]));
  if (held && nj > 0) power -= d.tau[0] * s;
  const double kt = model.torsion().top_stiffness;
  if (kt > 0.0) {  // the top spring: moment -τ_t on θ_0; on e_0 +τ_t a(h, e_0) (∂m_t/∂e_0 = -a(h, e_0))
    d.top_twist = topSpringTwist(kin, theta[0], d.frames);
    const Vec3 a = spinConnection(d.frames.top_axis, dir(kin[0]));
    const double ct = model.torsion().top_damping, rate = omega[0] - a.dot(kin[0].e_dot) - s;  // m_t'
    d.top_tau = kt * d.top_twist + ct * rate;
    power -= ct * rate * rate + d.top_tau * s;
    Q.segment<3>(kE) += d.top_tau * a;
  }
  if (model.hasBendingAxes()) {  // else d.bend stays 0 (resize)
    std::fill(d.bend.begin(), d.bend.end(), 0.0);
    addBendingAxesForces(model, kin, theta, d.frames, d.m1, Q, d.bend.data());
    if (held) power -= d.bend[0] * s;  // the holder spins rfe 0's axes: ∂V/∂t
  }
  for (int i = 0; i < nb; ++i) {
    d.moment[i] = (i < nj ? d.tau[i] : 0.0) - (i > 0 ? d.tau[i - 1] : 0.0) - (i == 0 ? d.top_tau : 0.0) + d.bend[i];
    Vec3 qe = Vec3::Zero();
    if (i < nj) qe -= d.tau[i] * d.kb[i];
    if (i > 0) qe -= d.tau[i - 1] * d.kb[i - 1];
    const BodyKinematics3& b = kin[i];
    if (i == 0 && held)  // the hang-off turns rfe 0 about e_0 at a(h, e_0)·e'_0
      qe += d.moment[0] * spinConnection(d.frames.centre[0], dir(b));
    else  // gyroscopic: d/dt of the spin's angular momentum J ω e has J ω e' across e
      qe += polarInertia(model, i) * omega[i] * b.e.cross(b.e_dot);
    Q.segment<3>(kDofPerBody3 * i + kE) += qe;
  }
  return power;
}

double twistEnergy(const Model3& model, const Kinematics3& kin, const double* theta, TwistData& d) {
  twistAngles(kin, theta, d.frames, d.m.data(), d.kb.data());
  double v = 0.0;
  for (double m : d.m) v += m * m;
  const double kt = model.torsion().top_stiffness, mt = kt > 0.0 ? topSpringTwist(kin, theta[0], d.frames) : 0.0;
  return 0.5 * twistStiffness(model) * v + 0.5 * kt * mt * mt + bendingAxesEnergy(model, kin, theta, d.frames);
}

}  // namespace spatial
}  // namespace riser_sim
