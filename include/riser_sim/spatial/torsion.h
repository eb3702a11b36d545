// Torsion of the spatial line (on only when the scene gives line.torsion). Per rfe a spin angle θ_i and a
// spin rate ω_i (about e_i, [rad/s]) join the state. θ_i is measured from a reference u_i(e) = R(c_i -> e) r_i:
// r_i ⟂ c_i carried by the minimal rotation from a chart centre c_i, moved to e_i between steps (a moving
// chart, exact: u_i is unchanged by the move). The material frame is u_i turned by θ_i about e_i, so
//   spin rate ω_i = θ'_i + a(c_i, e_i)·e'_i,   a(c, e) = -(c × e) / (1 + c·e)  (0 at the chart centre).
// Twist between rfes k, k+1: m_k = θ_{k+1} - θ_k + m_ref,k, m_ref,k the angle about e_{k+1} from
// R(e_k -> e_{k+1}) u_k to u_{k+1} (space-parallel transport across the joint; discrete elastic rods). Under
// minimal rotations of the frames ∂m_k/∂e_k = ∂m_k/∂e_{k+1} = kb_k = (e_k × e_{k+1}) / (1 + e_k·e_{k+1}).
// Spring V = ½ (GJ/d) m_k², damper moment (c_GJ/d) m'_k. The top rfe is held in twist by the hang-off: its
// frame is the hang-off's (axis h = e_0 at the start) turned by R(h -> e_0), θ_0 = 0 (a homokinetic joint);
// its own polar inertia is left out. The bottom is free in twist (free or pinned). The hang-off's frame is
// fixed in its holder (a vessel that turns): h(t) = R(t) h_0, r_h(t) = R(t) r_h0; turning at w it spins the
// transported reference at e_0 by s = w·(h + e_0) / (1 + h·e_0) (turnHangOff, hangOffSpin), which enters
// the twist rates, and the holder's work -τ s joins the dampers' power (V then depends on t).
#pragma once
#include <vector>

#include "riser_sim/spatial/kinematics.h"

namespace riser_sim {
namespace spatial {

struct TorsionProperties {
  double stiffness = 0.0;          // GJ [N m^2]
  double polar_inertia = 0.0;      // ρ I_p per length [kg m]
  double damping = 0.0;            // c_GJ [N m^2 s]: twisting moment per unit twist rate per length
  double end_polar_inertia = 0.0;  // end body about the line's axis [kg m^2]
  // The top's connection leaves the spin free (top.torsion: free): rfe 0 spins as the others (its own chart,
  // polar inertia, gyroscopic force) and the hang-off holds no twisting moment. False: held (homokinetic).
  bool free_top = false;
  // > 0: the top's spin is held by a torsion spring k_t [N m/rad] to the hang-off (a flex joint's torsional
  // stiffness), θ_0 free as with free_top; the spring's twist is m_t = θ_0 + angle from R(h -> e_0) r_h.
  double top_stiffness = 0.0;
  double top_damping = 0.0;  // c_t [N m s/rad] beside k_t: the moment k_t m_t + c_t m_t'
};

// R(a -> b) x: the minimal rotation taking unit a to unit b (about a × b), applied to x. Singular at b = -a.
inline Vec3 minimalRotation(const Vec3& a, const Vec3& b, const Vec3& x) {
  const Vec3 v = a.cross(b);
  return x + v.cross(x) + v.cross(v.cross(x)) / (1.0 + a.dot(b));
}
// a(c, e): spin rate about e of the chart reference R(c -> e) r is a·e'.
inline Vec3 spinConnection(const Vec3& c, const Vec3& e) { return -c.cross(e) / (1.0 + c.dot(e)); }

// Chart data: centre c_i and reference r_i per rfe (rfe 0: the hang-off's axis and reference, fixed), and
// the last reference twist per joint (the next one is unwrapped against it).
struct TwistFrames {
  AlignedVector<Vec3> centre, ref;
  std::vector<double> mref;
  // The hang-off's frame (axis h, reference r_h; world, at the last turnHangOff) and the top spring's last
  // reference twist (top spin); the same frame in the holder's frame (fixed) and the holder's angular velocity.
  Vec3 top_axis = Vec3::Zero(), top_ref = Vec3::Zero();
  double top_mref = 0.0;
  Vec3 hold_axis = Vec3::Zero(), hold_ref = Vec3::Zero(), top_w = Vec3::Zero();
};

// One evaluation's twist results and workspaces (sized once).
struct TwistData {
  TwistFrames frames;
  std::vector<double> m, mdot, tau;       // per joint k (rfes k, k+1): twist [rad], its rate, moment k m + c m' [N m]
  AlignedVector<Vec3> kb;                 // per joint
  std::vector<double> moment;             // per rfe: moment about e_i of the springs and dampers [N m]
  std::vector<double> bend;               // per rfe: its part from the bending axes (bending_axes.h) [N m]
  AlignedVector<Vec3> m1;                 // per rfe: material axis 1 (a workspace of the bending axes)
  double top_twist = 0.0, top_tau = 0.0;  // top spring: its twist m_t [rad], moment k_t m_t + c_t m_t' [N m]
  void resize(int bodies);
};

class Model3;

// The first rfe whose spin is a degree of freedom: 0 with a free or spring-held top, else 1.
int firstSpin(const Model3& model);
// The twisting moment the hang-off holds about the line's axis [N m]: τ_0 held, k_t m_t spring-held, 0 free.
double hangOffTwist(const Model3& model, const TwistData& d);
// The top spring's twist m_t at (kin, θ_0), unwrapped against f.top_mref [rad].
double topSpringTwist(const Kinematics3& kin, double theta0, const TwistFrames& f);
// Spring and damper constants per joint [N m/rad], [N m s/rad] and polar inertia of rfe i [kg m^2] (0 for
// i = 0 unless the top is free).
double twistStiffness(const Model3& model);
double twistDamping(const Model3& model);
double polarInertia(const Model3& model, int i);

// The hang-off's twist frame given rather than made at the top rfe: its axis h (unit) and reference r_h (unit,
// ⟂ h). A zero axis: made at the top rfe (initTwistFrames). The axis is the homokinetic joint's: rfe 0's frame is
// R(h -> e_0) r_h, and h enters its law beyond e_0 (minimal rotations do not compose), so it is part of the model.
struct HangOff {
  Vec3 axis = Vec3::Zero(), ref = Vec3::Zero();
  bool given() const { return axis.squaredNorm() > 0.0; }
};

// Frames at the start: centres at e_i, the hang-off's axis e_0 with a reference ⟂ e_0 (axis1's part normal to
// e_0 when given, the material axis 1 of bending_axes.h; else the world axis least aligned with e_0), the
// references transported down the line across the joints (so m_ref = 0 at the start).
// The hang-off's frame then is fixed in a holder at attitude I (holdHangOff for another).
// Throws std::invalid_argument when axis1 is within 1e-6 rad of e_0.
// hang: the hang-off's frame when given (then axis1 is not used for it).
void initTwistFrames(const Kinematics3& kin, TwistFrames& f, const Vec3& axis1 = Vec3::Zero(),
                     const HangOff& hang = HangOff());
// The hang-off's frame as it is now, fixed in a holder whose attitude is now R0 (holder frame -> world).
void holdHangOff(TwistFrames& f, const Mat3& R0);
// The hang-off's frame at the holder's attitude R turning at w [rad/s] (world); `held`: rfe 0's chart is the
// hang-off's (firstSpin = 1). Exact no-op for R = I, w = 0 with the frame held at I.
void turnHangOff(TwistFrames& f, const Mat3& R, const Vec3& w, bool held);
// s = w·(h + n0) / (1 + h·n0): spin rate about n0 (unit e_0) of the hang-off's reference transported to n0 [rad/s].
double hangOffSpin(const TwistFrames& f, const Vec3& n0);
// Between steps: every chart (i >= first; rfe 0's is the hang-off's unless first = 0) centred at e_i; the
// references follow (the frames do not move) and the reference twists are stored for unwrapping.
void rechartTwistFrames(const Kinematics3& kin, TwistFrames& f, int first = 1);
// The reference twists stored for unwrapping, at kin (rechartTwistFrames' first part; the charts stay): between
// steps, so no reference twist moves by π unseen (a turning hang-off twists the line with e fixed).
void refreshTwistBranches(const Kinematics3& kin, TwistFrames& f, int first = 1);
// Material director of rfe i: its reference at unit e turned by θ about e (frame-independent; for comparing
// formulations with different charts).
Vec3 materialDirector(const TwistFrames& f, int i, const Vec3& e, double theta);
// Spin angles θ_i [rad] turning each rfe's reference at kin (frames f) onto the material axis m1[i] (unit, ⟂ e_i):
// materialDirector's inverse.
void spinsFromAxes(const Kinematics3& kin, const TwistFrames& f, const AlignedVector<Vec3>& m1, double* theta);
// m_k and kb_k per joint at (kin, θ), unwrapped against f.mref.
void twistAngles(const Kinematics3& kin, const double* theta, const TwistFrames& f, double* m, Vec3* kb);
// Spin rate of rfe 0 held by the hang-off: a(h, e_0)·e'_0 + hangOffSpin.
double topSpinRate(const Kinematics3& kin, const TwistFrames& f);
// Twist forces at (kin, θ, ω): adds the e part (twist, hang-off, gyroscopic J ω e × e', the bending axes') to Q,
// (a free top: θ_0, ω_0 are rfe 0's own, no hang-off part)
// fills d.m, d.mdot, d.tau, d.kb, d.moment; returns the dampers' power [W] (<= 0).
double addTwistForces(const Model3& model, const Kinematics3& kin, const double* theta, const double* omega,
                      TwistData& d, VecX& Q);
// Σ ½ (GJ/d) m_k² (+ the top spring's, + the bending axes' part) [J].
double twistEnergy(const Model3& model, const Kinematics3& kin, const double* theta, TwistData& d);

}  // namespace spatial
}  // namespace riser_sim
