#include "riser_sim/spatial/model.h"

#include "riser_sim/force_term.h"  // the held planar Model destroys its (empty) term list
#include "riser_sim/spatial/force_term.h"

#include <stdexcept>

namespace riser_sim {
namespace spatial {

SpatialModel::SpatialModel(double length, int segments, const LineProperties& props, const ModelOptions& options,
                           double end_mass, const Vec3& gravity)
    : line_(length, segments, props, options, end_mass, gravity.norm()), gravity_(gravity) {}

SpatialModel::~SpatialModel() = default;

void SpatialModel::setTorsion(const TorsionProperties& t) {
  if (!(t.stiffness > 0.0 && t.polar_inertia > 0.0 && t.damping >= 0.0 && t.end_polar_inertia >= 0.0))
    throw std::invalid_argument("spatial torsion: GJ and the polar inertia per length must be > 0, the damping and "
                                "the end's polar inertia >= 0");
  torsion_ = t;
  has_torsion_ = true;
}

void SpatialModel::setBottomMotion(std::shared_ptr<const TopMotion3> motion) {
  bottom_ = BottomBoundary::kPinned;
  bottom_point_ = motion->at(0.0).p;
  bottom_motion_ = std::move(motion);
}

void SpatialModel::addTerm(std::unique_ptr<SpatialForceTerm> term) { terms_.push_back(std::move(term)); }

}  // namespace spatial
}  // namespace riser_sim
