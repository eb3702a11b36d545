// Second spatial formulation, the cross-check of NaturalFormulation: independent (joint) coordinates, the
// 3D analogue of the planar IndependentFormulation. A_0 follows the prescribed top, A_{i+1} = A_i +
// (l_i + Δ_i) e_i, so the unknowns per rfe are Δ_i (axial flexibility only) and the director e_i on the
// unit sphere in a moving chart (gnomonic, centred on a reference d_i):
//   e_i = w / |w|,  w = d_i + u_1 t_1 + u_2 t_2,  (t_1, t_2, d_i) orthonormal,  u ∈ R².
// The chart covers the open hemisphere around d_i; SphereCharts::recentre moves d_i to the current e_i
// (u = 0, u' = Tᵀ e', exact in position and velocity) when |u| grows beyond a threshold, between steps.
// So no direction is singular. Coordinates per rfe: θ_i = [Δ_i, u_i] (3) or [u_i] (2, inextensible).
// Equations: q'_i = B_i θ' + (top velocity) for the natural velocities q'_i = [A'_i, Δ'_i, e'_i], then
//   M_θ θ'' = Σ_i B_iᵀ (Q_i - h_i - M7_i b_i),   M_θ = Σ_i B_iᵀ M7_i B_i,
// with the natural per-rfe mass M7_i and velocity terms h_i (the same parts: m_p, J_p, s0, κ), b_i the
// velocity-product and top accelerations, Q_i the spatial terms' forces. M_θ is assembled in O(n²) from
// suffix sums and solved by a dense LLT, O(n³) per evaluation: the cross-check, not the fast path.
// Joints hold by construction. A pinned bottom adds its 3 constraints E_n = p_b with a multiplier μ (the
// anchor's force on the line; Schur complement of the dense KKT system) and Baumgarte stabilisation.
#pragma once
#include <Eigen/Cholesky>
#include <memory>

#include "riser_sim/scene/choices.h"
#include "riser_sim/integrators/integrator.h"
#include "riser_sim/spatial/model.h"
#include "riser_sim/spatial/natural_formulation.h"
#include "riser_sim/spatial/top_motion.h"

namespace riser_sim {
namespace spatial {

// One gnomonic chart per rfe: frame columns (t_1, t_2, d).
struct SphereCharts {
  AlignedVector<Mat3> frame;
  long switches = 0;  // chart switches so far (recentre)
  // Torsion on: the twist charts (rfe 0's is the hang-off's), moved to e_i whenever a sphere chart moves;
  // kin is a workspace of those moves.
  TwistFrames twist;
  Kinematics3 kin;
};

class IndependentData3 {
 public:
  IndependentData3(const Model3& model, int coords_per_body, int spins = 0);
  double t = 0.0;
  PointMotion3 top;
  Kinematics3 kin;
  Reactions3 reactions;           // top and bottom (pinned) only; joint forces are not computed
  double constraint_error = 0.0;  // pinned end gap [m] (0 free)
  double term_power = 0.0;        // [W]
  VecX Q;                         // terms' forces, natural coordinates (7 per rfe)
  // Per rfe: G = ∂e'/∂u' (3x2); C = ∂E_i'/∂(Δ', u') = [e, len G] (the Δ column unused when
  // inextensible); D = m_{>i} C + M7(A, Δe) L (the off-diagonal blocks of M_θ are C_jᵀ D_i); the e'' bias;
  // A_bias: A_i'' at θ'' = 0 (i = 0..n+1); the natural mass block M7 and f = Q - h - M7 b.
  AlignedVector<Eigen::Matrix<double, 3, 2>> G;
  AlignedVector<Mat3> C, D;
  AlignedVector<Vec3> e_bias, A_bias;
  AlignedVector<Mat7> M7;
  AlignedVector<Vec7> f;
  MatX M;  // M_θ (full)
  VecX rhs, theta_dd;
  Eigen::LLT<MatX> llt;
  MatX Phi, X;                    // pinned: ∂E_n'/∂θ' (3 x p) and M_θ⁻¹ Φᵀ
  std::vector<AddedMass3> added;  // terms with inertia: per rfe (empty without)
  // Torsion on: the twist (m, m', τ, kb, moments per rfe), the spin angle, rate ω and connection a per rfe.
  TwistData twist;
  std::vector<double> phi, omega;
  AlignedVector<Vec3> conn;
};

class IndependentFormulation3 {
 public:
  // stabilization: Baumgarte ω [rad/s] of the pinned end (as NaturalFormulation's, default 50).
  explicit IndependentFormulation3(const Model3& model, double stabilization = 50.0);
  const Model3& model() const { return model_; }
  int coordinatesPerBody() const { return k_; }
  int positionSize() const { return k_ * model_.bodies() + nt_; }
  // Torsion on: spin coordinates (rfes firstSpin()..n) and the index of rfe i's φ in θ.
  int spinDofs() const { return nt_; }
  int firstSpin() const { return s0_; }
  int spinIndex(int i) const { return k_ * model_.bodies() + i - s0_; }
  std::unique_ptr<IndependentData3> makeData() const { return std::make_unique<IndependentData3>(model_, k_, nt_); }

  // Charts centred on kin's directors (normalised), and y = [θ; θ'] (first 2 positionSize() entries);
  // the joints of kin are assumed closed (positions follow from the top and the directors).
  // Torsion on: hang_off_ref as in Simulator3::reset.
  void packState(const Kinematics3& kin, SphereCharts& charts, VecX& y, const HangOff& hang_off = HangOff()) const;
  // Rfe kinematics of y with A_0 moving as top.
  void kinematics(const VecX& y, const SphereCharts& charts, const PointMotion3& top, Kinematics3& kin) const;
  // dθ/dt, dθ'/dt on the first 2 positionSize() entries; data holds the evaluation (top reaction).
  void derivative(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top, VecX& dy,
                  IndependentData3& data) const;
  // The generalised forces only: data.rhs (M_θ θ'' = rhs before the pinned end's force) and data.Phi, O(n);
  // the mass matrix and its solve (O(n²), O(n³)) are skipped (the statics' finite differences need no more).
  void forces(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top,
              IndependentData3& data) const;
  // Re-centres the chart of every rfe with |u| > threshold on its current director (u = 0, exact in
  // position and velocity). Returns how many charts moved.
  // Torsion on: the twist charts move too (to every e_i, the spins' rates φ' follow).
  int recentre(VecX& y, SphereCharts& charts, double threshold) const;
  // Between steps: the twist's unwrapping branches at y (refreshTwistBranches; charts and state unchanged).
  void refreshTwist(const VecX& y, SphereCharts& charts) const;
  // Torsion on, right after packState (charts centred on e_i): spin angles and rates per rfe (entries below
  // firstSpin() ignored) [rad, rad/s].
  void setSpins(const VecX& theta, const VecX& omega, VecX& y) const;
  // Spin rate ω_i of rfe i [rad/s] and its material director (torsion.h) in state y.
  double spinRate(const VecX& y, const SphereCharts& charts, const Kinematics3& kin, int i) const;
  Vec3 materialDirector(const VecX& y, const SphereCharts& charts, const Kinematics3& kin, int i) const;
  double kineticEnergy(const Kinematics3& kin) const;  // [J] (without the spins)
  // Torsion on: Σ ½ J_i ω_i² and the twist's Σ ½ (GJ/d) m_k² [J] (0 off).
  double spinKineticEnergy(const VecX& y, const SphereCharts& charts, const Kinematics3& kin) const;
  double twistEnergy(const VecX& y, const SphereCharts& charts, const Kinematics3& kin, IndependentData3& d) const;
  double spinInertia(int i) const;                       // J_i [kg m²]
  double constraintError(const Kinematics3& kin) const;  // pinned end gap [m] (0 free)

 private:
  const Model3& model_;
  const double omega_;
  const int k_;   // coordinates per rfe
  const int ku_;  // offset of u inside θ_i (1 with Δ, 0 without)
  const int s0_;  // first spinning rfe
  const int nt_;  // spin coordinates (0 without torsion)
  void spinPhase(const VecX& y, const SphereCharts& charts, IndependentData3& d) const;  // φ, ω, a per rfe
  void addTwistForces(const VecX& y, const SphereCharts& charts, IndependentData3& d) const;
  // derivative() in two parts: the forces (and with `mass` M_θ), then M_θ's solve and the reactions.
  void assemble(double t, const VecX& y, const SphereCharts& charts, const PointMotion3& top, IndependentData3& d,
                bool mass) const;
  void solve(const VecX& y, VecX& dy, IndependentData3& d) const;
  void addSpinInertia(const VecX& y, const SphereCharts& charts, IndependentData3& d) const;
  void recentreTwist(VecX& y, SphereCharts& charts) const;
};

// Runs IndependentFormulation3 with the existing integrators on y = [θ; θ'; W] (W [J]: the work of the top
// motion and of the non-conservative terms), re-centring the charts between steps (and then telling the
// integrator the state moved). The same observers as Simulator3.
class IndependentSimulator3 : private OdeSystem {
 public:
  IndependentSimulator3(std::shared_ptr<const Model3> model, std::shared_ptr<const TopMotion3> top, IntegratorKind kind,
                        const IntegratorOptions& options = {}, double stabilization = 50.0);
  void reset(const Kinematics3& kin, double t0);        // W = 0; charts centred on kin's directors
  bool step(double h);                                  // one step, then the chart switches
  void setChartThreshold(double u) { threshold_ = u; }  // |u| beyond which a chart moves (default 0.5)

  double time() const { return t_; }
  const VecX& state() const { return y_; }
  const Model3& model() const { return *model_; }
  const IndependentFormulation3& formulation() const { return formulation_; }
  const SphereCharts& charts() const { return charts_; }
  long chartSwitches() const { return charts_.switches; }
  Integrator& integrator() { return *integrator_; }
  OdeSystem& system() { return *this; }

  void kinematics(Kinematics3& kin) const { formulation_.kinematics(y_, charts_, top_->at(t_), kin); }
  // Torsion on, after reset(): spin angles and rates per rfe (as Simulator3::setTwist; entry 0 held).
  void setTwist(const VecX& theta, const VecX& omega);
  void positions(AlignedVector<Vec3>& p) const;  // A_0..A_n and the end E_n [m] (n + 2)
  double kineticEnergy() const;
  double potentialEnergy() const;
  double energy() const { return kineticEnergy() + potentialEnergy(); }
  double work() const { return y_[y_.size() - 1]; }
  double constraintError() const;      // pinned end gap [m]
  const IndependentData3& evaluate();  // one evaluation at the current state (reactions.top, .bottom)

 private:
  void rhs(double t, const VecX& y, VecX& dy) override;

  std::shared_ptr<const Model3> model_;
  std::shared_ptr<const TopMotion3> top_;
  IndependentFormulation3 formulation_;
  std::unique_ptr<IndependentData3> data_;
  std::unique_ptr<Integrator> integrator_;
  SphereCharts charts_;
  VecX y_, dy_;
  mutable Kinematics3 kin_;
  double t_ = 0.0, threshold_ = 0.5;
};

}  // namespace spatial
}  // namespace riser_sim
