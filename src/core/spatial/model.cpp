#include "riser_sim/spatial/model.h"

#include "riser_sim/force_term.h"  // the held planar Model destroys its (empty) term list
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

SpatialModel::SpatialModel(double length, int segments, const LineProperties& props, const ModelOptions& options,
                           double end_mass, const Vec3& gravity)
    : line_(length, segments, props, options, end_mass, gravity.norm()), gravity_(gravity) {}

SpatialModel::~SpatialModel() = default;

void SpatialModel::setBottomMotion(std::shared_ptr<const TopMotion3> motion) {
  bottom_ = BottomBoundary::kPinned;
  bottom_point_ = motion->at(0.0).p;
  bottom_motion_ = std::move(motion);
}

void SpatialModel::addTerm(std::unique_ptr<SpatialForceTerm> term) { terms_.push_back(std::move(term)); }

}  // namespace spatial
}  // namespace riser_sim
