// Spatial line model: the RFEM discretisation of the planar Model (rfe lengths, parts, line properties,
// options, end mass: held, not copied), a gravity vector, the ends and the spatial force terms the scene
// lists (only those are built and run).
#pragma once
#include <memory>
#include <vector>

#include "riser_sim/planar/model.h"
#include "riser_sim/spatial/kinematics.h"
#include "riser_sim/spatial/top_motion.h"
#include "riser_sim/spatial/torsion.h"

namespace riser_sim {
namespace spatial {

class ForceTerm3;

class Model3 {
 public:
  // gravity: acceleration vector [m/s^2], default (0, 0, -9.81)-like; the held planar Model gets |gravity|.
  Model3(double length, int segments, const LineProperties& props, const ModelOptions& options, double end_mass,
         const Vec3& gravity);
  // Sections from the top and bend stiffeners (line_sections.h), as the planar Model.
  Model3(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners,
         const ModelOptions& options, double end_mass, const Vec3& gravity);
  ~Model3();
  Model3(const Model3&) = delete;
  Model3& operator=(const Model3&) = delete;

  const Model& line() const { return line_; }  // the discretisation (its own terms are not used)
  // A point mass on rfe i (Model::addPointMass): an attachment (attachment.h).
  void addPointMass(int i, double mass, double s0, double kappa) { line_.addPointMass(i, mass, s0, kappa); }
  Model& mutableLine() { return line_; }  // for the builders' attachments (addAttachmentMasses)
  int bodies() const { return line_.bodies(); }
  int dofs() const { return kDofPerBody3 * bodies(); }
  const Rfe& rfe(int i) const { return line_.rfe(i); }
  const ModelOptions& options() const { return line_.options(); }
  const Vec3& gravity() const { return gravity_; }
  // Spring and damper between rfes i-1 and i (Model::bendingStiffness(i)) [N m/rad], [N m s/rad].
  double bendingStiffness(int i) const { return line_.bendingStiffness(i); }
  double bendingDamping(int i) const { return line_.bendingDamping(i); }

  // Bottom end: free, or the end of rfe n pinned at a point [m]: fixed (setBottom), or moving along a
  // prescribed path (setBottomMotion: A_{n+1} = p_b(t), held as the top's A_0 = p(t)).
  BottomBoundary bottom() const { return bottom_; }
  const Vec3& bottomPoint() const { return bottom_point_; }  // at t = 0 when it moves
  void setBottom(BottomBoundary b, const Vec3& p) {
    bottom_ = b;
    bottom_point_ = p;
    bottom_motion_.reset();
  }
  // Pins the bottom to motion (its position at t = 0 becomes bottomPoint()).
  void setBottomMotion(std::shared_ptr<const TopMotion3> motion);
  bool bottomMoves() const { return bottom_motion_ != nullptr; }
  const std::shared_ptr<const TopMotion3>& bottomMotion() const { return bottom_motion_; }
  // Position, velocity, acceleration of the pinned bottom at t [s] (fixed: velocity 0). Allocates nothing.
  PointMotion3 bottomAt(double t) const {
    return bottom_motion_ ? bottom_motion_->at(t) : PointMotion3{bottom_point_, Vec3::Zero(), Vec3::Zero()};
  }

  // Torsion (torsion.h): off unless set; on adds a spin angle and rate per rfe to the state. Throws
  // std::invalid_argument unless GJ > 0, ρ I_p > 0, damping >= 0, end polar inertia >= 0 and the segments are
  // of one length (the twist springs are GJ/d).
  void setTorsion(const TorsionProperties& t);
  bool hasTorsion() const { return has_torsion_; }
  const TorsionProperties& torsion() const { return torsion_; }

  // Bending stiffness about the rfes' material axes (bending_axes.h): EI_1 about axis 1, EI_2 about axis 2
  // [N m^2]; the line's EI must be their mean (the isotropic BendingSpring carries it). axis1: axis 1 at the
  // hang-off at t = 0 (world; its part normal to the top rfe is taken). Needs setTorsion first (the axes turn
  // with the spin) and a uniform line (Model::uniform()). Throws std::invalid_argument naming what is wrong.
  void setBendingAxes(double EI1, double EI2, const Vec3& axis1);
  bool hasBendingAxes() const { return has_axes_; }
  double bendingSplit() const { return split_; }      // σ = (EI_1 - EI_2) / (2d) [N m/rad]
  const Vec3& bendingAxis() const { return axis1_; }  // zero without axes

  void addTerm(std::unique_ptr<ForceTerm3> term);
  const std::vector<std::unique_ptr<ForceTerm3>>& terms() const { return terms_; }

 private:
  Model line_;
  Vec3 gravity_;
  BottomBoundary bottom_ = BottomBoundary::kFree;
  Vec3 bottom_point_ = Vec3::Zero();
  std::shared_ptr<const TopMotion3> bottom_motion_;
  std::vector<std::unique_ptr<ForceTerm3>> terms_;
  TorsionProperties torsion_;
  bool has_torsion_ = false;
  bool has_axes_ = false;
  double split_ = 0.0;
  Vec3 axis1_ = Vec3::Zero();
};

}  // namespace spatial
}  // namespace riser_sim
