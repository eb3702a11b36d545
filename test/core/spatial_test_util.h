// Scenes and runners shared by the spatial (3D) core's tests: the same line built as a planar Model (2D
// absolute formulation) and as a Model3, initial states, a bare planar ODE runner.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "riser_sim/planar/absolute_formulation.h"
#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/forces/axial_spring.h"
#include "riser_sim/planar/forces/bending_spring.h"
#include "riser_sim/planar/forces/gravity.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/spatial/force_term.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/simulator.h"

namespace riser_sim {
namespace spatial_test {

using spatial::Mat3;
using spatial::Vec3;

struct LineSpec {
  double length = 10.0;  // [m]
  int segments = 10;
  LineProperties props;
  ModelOptions options;
  double end_mass = 0.0;  // [kg]
  double g = 9.81;        // [m/s^2]
};

// Flexible line: axial and bending springs with damping; ~630-900 rad/s axial modes at n = 10.
inline LineSpec flexibleLine() {
  LineSpec s;
  s.props.mass_per_length = 10.0;
  s.props.EA = 1e6;
  s.props.EI = 1e3;
  s.props.axial_damping = 1e3;
  s.props.bending_damping = 10.0;
  s.end_mass = 50.0;
  return s;
}

inline std::shared_ptr<Model> planarModel(const LineSpec& s) {
  auto m = std::make_shared<Model>(s.length, s.segments, s.props, s.options, s.end_mass, s.g);
  m->addTerm(std::make_unique<Gravity>());
  if (s.options.axial_flexibility) m->addTerm(std::make_unique<AxialSpring>());
  if (s.options.bending) m->addTerm(std::make_unique<BendingSpring>());
  return m;
}

inline std::shared_ptr<spatial::Model3> spatialModel(const LineSpec& s, const Vec3& gravity) {
  auto m = std::make_shared<spatial::Model3>(s.length, s.segments, s.props, s.options, s.end_mass, gravity);
  m->addTerm(std::make_unique<spatial::Gravity>());
  if (s.options.axial_flexibility) m->addTerm(std::make_unique<spatial::AxialSpring>());
  if (s.options.bending) m->addTerm(std::make_unique<spatial::BendingSpring>());
  return m;
}

// The twist-only shaft of the torsion tests: a 10 m line of 10 kg/m hanging straight, inextensible, no bending,
// a 50 kg end; torsion t when t.stiffness > 0 (GJ, polar inertias, top: held, free or spring-held).
inline std::shared_ptr<spatial::Model3> twistShaft(int n, const spatial::TorsionProperties& t) {
  LineSpec s;
  s.length = 10.0;
  s.segments = n;
  s.props.mass_per_length = 10.0;
  s.options.bending = false;
  s.options.axial_flexibility = false;
  s.end_mass = 50.0;
  auto m = spatialModel(s, Vec3(0, 0, -s.g));
  if (t.stiffness > 0.0) m->setTorsion(t);
  return m;
}

// The torsion of the shaft tests: GJ, ρI_p = 1 kg m, J_end = 10 kg m², the twist damper c_GJ.
inline constexpr double kShaftRhoIp = 1.0, kShaftJend = 10.0;
inline spatial::TorsionProperties shaftTorsion(double GJ, double damping) {
  spatial::TorsionProperties t;
  t.stiffness = GJ;
  t.polar_inertia = kShaftRhoIp;
  t.damping = damping;
  t.end_polar_inertia = kShaftJend;
  return t;
}

// A bent chain hanging from the origin at rest: director i leans 0.4 i along x and a random (rng, ±0.3) along y.
inline spatial::Kinematics3 randomBentChain(const Model& line, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> dirs;
  for (int i = 0; i < line.bodies(); ++i) dirs.push_back(Vec3(0.4 * i, 0.3 * u(rng), -1.0));
  return spatial::rigidChain(line, Vec3::Zero(), dirs, Vec3::Zero(), Vec3::Zero());
}

// Σ over every part of every rfe of (x_p - A_0) × m_p g [N m]: the weight's moment about the hang-off.
inline Vec3 weightMoment(const spatial::Model3& m, const spatial::Kinematics3& kin) {
  Vec3 M = Vec3::Zero();
  for (int i = 0; i < m.bodies(); ++i)
    for (int p = 0; p < m.rfe(i).num_parts; ++p) {
      const RigidPart& part = m.rfe(i).part[p];
      M += (kin[i].point(part.s0, part.kappa) - kin[0].A).cross(part.mass * m.gravity());
    }
  return M;
}

// Planar chain at rest with Δ = 0, A_0 = top, rfe i at angle phi[i] from the x axis.
inline Kinematics planarChain(const Model& m, const Vec2& top, const std::vector<double>& phi) {
  Kinematics kin(m.bodies());
  Vec2 A = top;
  for (int i = 0; i < m.bodies(); ++i) {
    BodyKinematics& b = kin[i];
    b.A = A;
    b.phi = phi[i];
    b.c = std::cos(phi[i]);
    b.s = std::sin(phi[i]);
    b.len = m.rfe(i).length;
    A = b.end();
  }
  return kin;
}

// Top sway p(t) = a (cos(2πt/T) - 1): starts at the origin at rest (consistent with a chain hung from it).
inline std::unique_ptr<TopMotion> topSway(const Vec2& amplitude, double period) {
  return std::make_unique<SinusoidMotion>(-amplitude, amplitude, period, 0.0);
}

// The planar absolute formulation as a bare ODE y = [q; v] (no work entry).
class PlanarOde : public OdeSystem {
 public:
  PlanarOde(std::shared_ptr<const Model> m, std::unique_ptr<TopMotion> top)
      : model_(std::move(m)), top_(std::move(top)), f_(*model_, 50.0), data_(f_.makeData()) {}
  void rhs(double t, const VecX& y, VecX& dy) override { f_.derivative(t, y, top_->at(t), dy, *data_); }
  const AbsoluteFormulation& formulation() const { return f_; }
  const FormulationData& data() const { return *data_; }  // the last evaluation
  const Model& model() const { return *model_; }
  VecX state(const Kinematics& kin) const {
    VecX y = VecX::Zero(2 * model_->dofs());
    f_.packState(kin, y);
    return y;
  }
  // A_0..A_n and the end point of state y.
  std::vector<Vec2> positions(const VecX& y) {
    Kinematics kin(model_->bodies());
    f_.kinematics(y, PointMotion(), kin);
    std::vector<Vec2> p;
    for (const auto& b : kin) p.push_back(b.A);
    p.push_back(kin.back().end());
    return p;
  }

 private:
  std::shared_ptr<const Model> model_;
  std::unique_ptr<TopMotion> top_;
  AbsoluteFormulation f_;
  std::unique_ptr<FormulationData> data_;
};

// R = Rz(yaw) Ry(tilt): a tilt about y, then a yaw about the vertical.
// A 3D state hanging straight down in the x-z plane as the planar kinematics (x, z) -> (x, y), φ = -π/2.
inline Kinematics planarHanging(const spatial::Kinematics3& eq) {
  Kinematics kin2(eq.size());
  for (size_t i = 0; i < eq.size(); ++i) {
    BodyKinematics& b = kin2[i];
    b.A = Vec2(eq[i].A.x(), eq[i].A.z());
    b.delta = eq[i].delta;
    b.phi = -M_PI / 2;
    b.c = std::cos(b.phi);
    b.s = std::sin(b.phi);
    b.len = eq[i].len;
  }
  return kin2;
}

inline Mat3 yawTilt(double yaw, double tilt) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(tilt, Vec3::UnitY())).toRotationMatrix();
}

// A holder at a fixed point whose attitude turns: R(t) = Rz(γ(t)) Ry(β(t)) (tilt about y, then yaw), w = γ' z +
// β' Rz(γ) y. Each angle is a function t -> (angle [rad], rate [rad/s]).
class TurningHolder : public spatial::TopMotion3 {
 public:
  using Angle = std::function<Eigen::Vector2d(double)>;
  TurningHolder(Angle beta, Angle gamma, const Vec3& p = Vec3::Zero())
      : beta_(std::move(beta)), gamma_(std::move(gamma)), p_(p) {}
  spatial::PointMotion3 at(double t) const override {
    const Eigen::Vector2d b = beta_(t), g = gamma_(t);
    const spatial::Mat3 Rz = Eigen::AngleAxisd(g[0], Vec3::UnitZ()).toRotationMatrix();
    spatial::PointMotion3 m;
    m.p = p_;
    m.R = Rz * Eigen::AngleAxisd(b[0], Vec3::UnitY()).toRotationMatrix();
    m.w = g[1] * Vec3::UnitZ() + b[1] * Rz.col(1);
    return m;
  }
  bool rotates() const override { return true; }

 private:
  Angle beta_, gamma_;
  Vec3 p_;
};
// a0 + rate t + amp sin(freq t).
inline TurningHolder::Angle wobble(double a0, double rate, double amp, double freq) {
  return [=](double t) {
    return Eigen::Vector2d(a0 + rate * t + amp * std::sin(freq * t), rate + amp * freq * std::cos(freq * t));
  };
}
// 0 until t0, a smooth (quintic) step to `to` at t1, then held.
inline TurningHolder::Angle ramp(double to, double t0, double t1) {
  return [=](double t) {
    const double s = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0), ds = (t > t0 && t < t1) ? 1.0 / (t1 - t0) : 0.0;
    return Eigen::Vector2d(to * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s),
                           to * 30.0 * s * s * (1.0 - s) * (1.0 - s) * ds);
  };
}

// The step-cost bench's line (bench/step_cost.cpp, "3D against 2D"): 100 m, 10 kg/m, EA 1e7 N, EI 1e4 N m²,
// damping 1e4 N s and 1e2 N m² s, 500 kg end mass; straight, released 20° off the vertical in the x-z plane,
// under a top swaying 1 m in x over 10 s (benchSway).
inline std::shared_ptr<spatial::Model3> benchLine(int n) {
  LineProperties p;
  p.mass_per_length = 10.0;
  p.EA = 1e7;
  p.EI = 1e4;
  p.axial_damping = 1e4;
  p.bending_damping = 100.0;
  auto m = std::make_shared<spatial::Model3>(100.0, n, p, ModelOptions(), 500.0, Vec3(0, 0, -9.81));
  m->addTerm(std::make_unique<spatial::Gravity>());
  m->addTerm(std::make_unique<spatial::AxialSpring>());
  m->addTerm(std::make_unique<spatial::BendingSpring>());
  return m;
}

inline spatial::Kinematics3 benchReleased(const spatial::Model3& m) {
  spatial::Kinematics3 kin(m.bodies());
  const double a = 20.0 * M_PI / 180.0;
  const Vec3 e(std::sin(a), 0.0, -std::cos(a));
  Vec3 A = Vec3::Zero();
  for (int i = 0; i < m.bodies(); ++i) {
    kin[i].A = A;
    kin[i].e = e;
    kin[i].len = m.line().rfe(i).length;
    A += kin[i].len * e;
  }
  return kin;
}

inline std::unique_ptr<spatial::TopMotion3> benchSway() {
  return std::make_unique<spatial::PlanarMotion3>(topSway(Vec2(1.0, 0.0), 10.0));
}

}  // namespace spatial_test
}  // namespace riser_sim
