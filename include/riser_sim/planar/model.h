// Immutable RFEM discretisation (paper section 2): n segments of lengths d_j (sections: line_sections.h),
// n+1 rigid finite elements (rfe): rfe 0 the first half of segment 0, rfe i the second half of segment i-1 and
// the first half of segment i, rfe n the second half of segment n-1. Each rfe is split into parts (1) and (2)
// by a longitudinal spring (at the boundary of its two segments); the bending spring between rfes i-1 and i
// sits at the middle of segment i-1 and carries that segment's bending compliance.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "riser_sim/line/line_properties.h"
#include "riser_sim/line/line_sections.h"
#include "riser_sim/types.h"

namespace riser_sim {

class ForceTerm;

// One rigid part of an rfe: centre of mass at distance s0 + kappa*Δ from A_i along the rfe.
struct RigidPart {
  double mass = 0.0;     // [kg]
  double inertia = 0.0;  // about its own centre of mass [kg m^2]
  double s0 = 0.0;       // [m]
  double kappa = 0.0;    // 0: part (1) moves with A_i; 1: part (2), beyond the spring
};

struct Rfe {
  double length = 0.0;           // l_i, unstretched [m]
  double length1 = 0.0;          // l_i^(1) [m]
  double length2 = 0.0;          // l_i^(2) [m]
  double axial_stiffness = 0.0;  // c_i^l = EA / l_i [N/m]
  double axial_damping = 0.0;    // c_EA / l_i [N s/m]
  double s_begin = 0.0;          // arc length of A_i from the top, unstretched [m]
  // Parts (1), (2), then on rfe n the end mass, then point masses (Model::addPointMass; at most one per kappa).
  RigidPart part[4];
  int section[2] = {0, 0};  // the line section of parts (1) and (2)
  int num_parts = 2;
  // Sums over the parts (s_p = s0_p + kappa_p Δ): m = Σm, mk = Σ m kappa, S(Δ) = S0 + mk Δ,
  // Σ m kappa s = Sk0 + mk Δ, I_A(Δ) = Σ (m s² + J) = I0 + 2 Sk0 Δ + mk Δ².
  double mass = 0.0, mass_k = 0.0, S0 = 0.0, Sk0 = 0.0, I0 = 0.0;
  double firstMoment(double delta) const { return S0 + mass_k * delta; }
  double firstMomentK(double delta) const { return Sk0 + mass_k * delta; }
  double inertiaAboutA(double delta) const { return I0 + 2.0 * Sk0 * delta + mass_k * delta * delta; }
};

enum class BottomBoundary { kFree, kPinned };

struct ModelOptions {
  bool bending = true;            // bending springs c_j = 1 / ∫ ds/EI over segment j between neighbouring rfes
  bool axial_flexibility = true;  // false: inextensible line, Δ_i ≡ 0
};

class Model {
 public:
  // A uniform line: one section of `segments` segments.
  Model(double length, int segments, const LineProperties& props, const ModelOptions& options, double end_mass,
        double gravity);
  // Sections from the top and bend stiffeners (line_sections.h); the length is the sections' sum.
  Model(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners,
        const ModelOptions& options, double end_mass, double gravity);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  int segments() const { return n_; }    // n
  int bodies() const { return n_ + 1; }  // rfes 0..n
  int dofs() const { return kDofPerBody * (n_ + 1); }
  double length() const { return length_; }                  // L [m]
  double segmentLength() const { return d_; }                // mean segment length L/n [m] (scales, tolerances)
  double segmentLength(int j) const { return segment_[j]; }  // d_j, j = 0..n-1 [m]
  const Rfe& rfe(int i) const { return rfe_[i]; }
  // The top section's properties (the whole line's when uniform); per part: partSection.
  const LineProperties& line() const { return sections_[0].props; }
  int sectionCount() const { return int(sections_.size()); }
  const LineSection& section(int k) const { return sections_[k]; }
  const LineSection& partSection(int i, int p) const { return sections_[rfe_[i].section[p]]; }
  bool uniform() const { return uniform_; }  // one section, no stiffener
  const ModelOptions& options() const { return options_; }
  double endMass() const { return end_mass_; }  // m_s [kg]
  double gravity() const { return gravity_; }   // g [m/s^2], acting along -y
  // Spring between rfes i-1 and i, i = 1..n: c_i = 1 / ∫ ds/EI over segment i-1 (EI/d_{i-1} when EI is
  // constant there) [N m/rad]; damper c_EI / d_{i-1} [N m s/rad]. 0 without bending.
  double bendingStiffness(int i) const { return bend_k_[i]; }
  double bendingDamping(int i) const { return bend_c_[i]; }
  bool hasBending() const { return has_bending_; }  // some spring or damper is not 0
  double totalMass() const;                         // line + contents + end mass + point masses [kg]
  // A point mass [kg] fixed to rfe i at s0 [m] from A_i, on part (1) (kappa 0) or (2) (kappa 1): an attachment
  // (attachment.h). Merged into a point part of rfe i with the same kappa (exact: the rfe's mass, first and
  // second moments are sums). Throws std::invalid_argument on an rfe, place or kappa that is not there.
  void addPointMass(int i, double mass, double s0, double kappa);
  double pointMass() const { return point_mass_; }  // Σ of the point masses [kg]

  // Bottom end condition (pinned: the end of rfe n is held at a fixed point).
  BottomBoundary bottom() const { return bottom_; }
  const Vec2& bottomPoint() const { return bottom_point_; }
  void setBottom(BottomBoundary b, const Vec2& p) {
    bottom_ = b;
    bottom_point_ = p;
  }

  // Force terms the scene asked for; only these are evaluated.
  void addTerm(std::unique_ptr<ForceTerm> term);
  const std::vector<std::unique_ptr<ForceTerm>>& terms() const { return terms_; }
  const ForceTerm* findTerm(const std::string& name) const;

 private:
  int n_;
  double length_, d_;
  std::vector<LineSection> sections_;
  bool uniform_ = true;
  std::vector<double> segment_, bend_k_, bend_c_;
  bool has_bending_ = false;
  ModelOptions options_;
  double end_mass_, gravity_;
  double point_mass_ = 0.0;
  std::vector<Rfe> rfe_;
  BottomBoundary bottom_ = BottomBoundary::kFree;
  Vec2 bottom_point_ = Vec2::Zero();
  std::vector<std::unique_ptr<ForceTerm>> terms_;
};

}  // namespace riser_sim
