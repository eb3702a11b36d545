#include "riser_sim/spatial/model.h"

#include "riser_sim/planar/force_term.h"  // the held planar Model destroys its (empty) term list
#include "riser_sim/spatial/force_term.h"

#include <cmath>
#include <stdexcept>

namespace riser_sim {
namespace spatial {

Model3::Model3(double length, int segments, const LineProperties& props, const ModelOptions& options, double end_mass,
               const Vec3& gravity)
    : line_(length, segments, props, options, end_mass, gravity.norm()), gravity_(gravity) {}

Model3::Model3(const std::vector<LineSection>& sections, const std::vector<BendStiffener>& stiffeners,
               const ModelOptions& options, double end_mass, const Vec3& gravity)
    : line_(sections, stiffeners, options, end_mass, gravity.norm()), gravity_(gravity) {}

namespace {
bool equalSegments(const Model& m) {
  for (int j = 0; j < m.segments(); ++j)
    if (m.segmentLength(j) != m.segmentLength(0)) return false;
  return true;
}
}  // namespace

Model3::~Model3() = default;

void Model3::setTorsion(const TorsionProperties& t) {
  if (!(t.stiffness > 0.0 && t.polar_inertia > 0.0 && t.damping >= 0.0 && t.end_polar_inertia >= 0.0))
    throw std::invalid_argument(
        "spatial torsion: GJ and the polar inertia per length must be > 0, the damping and "
        "the end's polar inertia >= 0");
  if (!equalSegments(line_))
    throw std::invalid_argument(
        "line.torsion: needs segments of one length (line.sections: the same "
        "length / elements in every section)");
  torsion_ = t;
  has_torsion_ = true;
}

void Model3::setBendingAxes(double EI1, double EI2, const Vec3& axis1) {
  if (!has_torsion_) throw std::invalid_argument("bending axes: need torsion (the material axes turn with the spin)");
  if (!line_.uniform())
    throw std::invalid_argument("line.EI: a pair [EI_1, EI_2] needs a line without sections or a stiffener");
  if (!(EI1 > 0.0 && EI2 > 0.0)) throw std::invalid_argument("bending axes: EI_1 and EI_2 must be > 0");
  const double mean = 0.5 * (EI1 + EI2), EI = line_.line().EI;
  if (!(std::abs(EI - mean) <= 1e-12 * mean))
    throw std::invalid_argument("bending axes: the line's EI must be the mean of EI_1 and EI_2");
  if (!(axis1.allFinite() && axis1.norm() > 0.0))
    throw std::invalid_argument("bending axes: axis 1 must be finite, not 0");
  has_axes_ = true;
  split_ = line_.options().bending ? 0.5 * (EI1 - EI2) / line_.segmentLength() : 0.0;
  axis1_ = axis1.normalized();
}

void Model3::setBottomMotion(std::shared_ptr<const TopMotion3> motion) {
  bottom_ = BottomBoundary::kPinned;
  bottom_point_ = motion->at(0.0).p;
  bottom_motion_ = std::move(motion);
}

void Model3::addTerm(std::unique_ptr<ForceTerm3> term) { terms_.push_back(std::move(term)); }

}  // namespace spatial
}  // namespace riser_sim
