// Internals of the statics (statics.cpp, statics_guess.cpp, statics_check.cpp): the terms as the
// statics see them and the scaled equilibrium residual in the independent coordinates.
#pragma once
#include <memory>
#include <vector>

#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/statics.h"

namespace riser_sim {
namespace statics_detail {

// The model's terms in a steady sea at time t (ForceTerm::steadyTerm: no waves, current frozen), in
// model order. The seabed's normal stiffness can be scaled (continuation).
class StaticTerms {
 public:
  StaticTerms(const Model& model, double t);
  const std::vector<const ForceTerm*>& terms() const { return terms_; }
  bool isSeabed(size_t k) const { return std::isfinite(terms_[k]->seabedLevel()); }
  double seabedLevel() const;       // highest seabed level (-inf without one) [m]
  double seabedStiffness() const;   // its normal stiffness per contact point (0 without) [N/m]
  void scaleSeabed(double factor);  // normal stiffness x factor x the base (1, 1: as the scene says)
  void softenSeabed(double base);   // the base of scaleSeabed's factor (1: the scene's), applied at once
  // The current's velocity x factor (1: as the scene says), for the continuation in the current.
  void scaleCurrent(double factor);
  // The attachments' loads x factor (Attachments::scaled: their weight included), for the continuation in them.
  void scaleAttachments(double factor);
  bool hasAttachments() const { return attachments_ >= 0; }
  // The buoyancy x factor (the water's density in it), for the continuation in the lift of buoyant sections.
  void scaleBuoyancy(double factor);
  // The buoyancy's term lifts some line section more than it weighs (a lazy wave's modules).
  bool hasBuoyantSection() const;
  bool hasCurrent() const { return has_current_; }
  double currentFactor() const { return current_factor_; }  // some term sees a non-zero steady current

 private:
  void composeAttachments();
  const Model& model_;
  double t_;
  bool has_current_ = false;
  double current_factor_ = 1.0;
  double attachments_factor_ = 1.0;
  double seabed_base_ = 1.0;
  int attachments_ = -1;  // index of the attachments' term
  int buoyancy_ = -1;     // index of the buoyancy's term
  std::vector<std::unique_ptr<ForceTerm>> owned_;
  std::vector<const ForceTerm*> terms_;
  std::vector<const ForceTerm*> original_;
};

// Unknowns x: per rfe (Δ_i if axial) and φ_i, then the end-force unknowns of the problem.
// Residual: generalised forces / weight (moments / weight·L), end conditions / L.
class StaticResidual {
 public:
  StaticResidual(const Model& m, const StaticsProblem& p, const StaticTerms& terms, double t);
  int size() const { return per_ * model_.bodies() + extra_; }
  int coordinates() const { return per_ * model_.bodies(); }  // Δ, φ unknowns (the rest: end force)
  int per() const { return per_; }
  int extra() const { return extra_; }
  double weight() const { return weight_; }
  double typical(int j) const { return j < coordinates() ? 1e-3 : weight_; }  // scale of unknown j

  void toKinematics(const VecX& x, Kinematics& kin) const;
  void fromKinematics(const Kinematics& kin, VecX& x) const;
  Vec2 endForce(const VecX& x) const;
  void setEndForce(const Vec2& f, VecX& x) const;
  void operator()(const VecX& x, VecX& r);
  // Force carried through each joint A_0..A_n (the sum of the loads beyond it) at the last evaluation [N].
  const AlignedVector<Vec2>& jointForces() const { return joint_; }
  const Kinematics& kinematics() const { return kin_; }
  // Forward-difference Jacobian at x (r = residual at x), for Newton.
  void jacobian(const VecX& x, const VecX& r, MatX& J);
  // Central-difference Jacobian at x (steps 1e-6 rad, 1e-8 of the rfe length, 1e-6 of the end force
  // or weight): round-off and truncation ~1e-9 of the entries, for the stability check.
  void centralJacobian(const VecX& x, MatX& J);

 private:
  const Model& model_;
  const StaticsProblem& prob_;
  const StaticTerms& terms_;
  double t_;
  bool axial_;
  int per_, extra_;
  Kinematics kin_;
  VecX Q_;
  AlignedVector<Vec2> joint_;
  double weight_;
};

// Initial guesses (statics_guess.cpp); each fills the kinematics and the end force, false if none fits.
bool displacedGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin,
                    double& end_force);
bool betweenPointsGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin,
                        Vec2& end_force);
// Hanging line whose straight hanging shape reaches below the seabed: down to it, the rest laid on it
// (towards the side the steady loads push the line).
bool hangingOnSeabedGuess(const Model& model, const StaticsProblem& p, const StaticTerms& terms, Kinematics& kin);
// Net weight per unit length [N/m] of the line in the steady sea (gravity, buoyancy), from the terms.
double netWeightPerLength(const Model& model, const StaticTerms& terms, const Vec2& top);

// Seabed geometries without a resting state (statics_check.cpp): empty if none, else the reason.
std::string seabedGeometry(const Model& model, const StaticsProblem& p, const StaticTerms& terms);
// Stability of the equilibrium (statics_check.cpp): its linearisation with drag and damping (the modal
// analysis's) on the motions the end conditions allow has no growing mode. Empty if stable, else the reason.
std::string stabilityCheck(const Model& model, const StaticsProblem& problem, const Kinematics& kin,
                           const Vec2& end_force, double t, double current_factor = 1.0);

}  // namespace statics_detail
}  // namespace riser_sim
