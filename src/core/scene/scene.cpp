#include "riser_sim/scene/scene.h"

#include <stdexcept>

#include "riser_sim/planar/forces/end_load.h"
#include "riser_sim/run/force_registry.h"

namespace riser_sim {

std::vector<LineSection> lineSections(const Scene& scene) {
  std::vector<LineSection> sections = scene.sections;
  if (sections.empty())
    sections.push_back(LineSection{scene.length, scene.elements, scene.line, SectionHydro(), BuoyancyModules()});
  for (LineSection& s : sections)
    s.props.content_mass_per_length = scene.internal_fluid.density * s.props.internalArea();
  return sections;
}

bool sectionsAddMass(const Scene& scene) {
  for (const LineSection& s : scene.sections)
    if ((!std::isnan(s.hydro.inertia_coefficient) && s.hydro.inertia_coefficient != 1.0) ||
        (!std::isnan(s.hydro.axial_added_mass) && s.hydro.axial_added_mass != 0.0))
      return true;
  return false;
}

std::shared_ptr<Model> buildModel(const Scene& scene, const BuildOptions& options) {
  if (options.terms.drag_on_line_at_rest || !options.terms.seabed_friction ||
      options.spins != BuildOptions::Spins::kScene || options.bottom_motion || options.mass_damping != 0.0)
    throw std::invalid_argument(
        "buildModel: the planar engine takes BuildOptions' terms.steady_sea, pinned_at and end_force only");
  const bool pinned = scene.bottom == BottomBoundary::kPinned;
  if (options.end_force.squaredNorm() > 0.0 && pinned)
    throw std::invalid_argument("buildModel: an end load on a pinned end (its anchor holds it)");
  if (options.pinned_at && !pinned)
    throw std::invalid_argument("buildModel: a pinned anchor for a free end (bottom.type: free)");
  auto model =
      std::make_shared<Model>(lineSections(scene), scene.stiffeners, scene.options, scene.end_mass, scene.gravity);
  model->setBottom(scene.bottom, inPlane(options.pinned_at ? *options.pinned_at : scene.bottom_point));
  // Only the terms the scene needs are built (a term that is off costs nothing): the registry's rows.
  addPlanarTerms(scene, *model, options.terms);
  if (options.end_force.squaredNorm() > 0.0) model->addTerm(std::make_unique<EndLoad>(inPlane(options.end_force)));
  return model;
}

// The planar motion reads the (x, z) of the spec's vectors and the phase of x (a planar scene has one phase).
std::unique_ptr<TopMotion> buildTopMotion(const TopMotionSpec& spec) {
  switch (spec.type) {
    case MotionKind::kFixed:
    case MotionKind::kExternal: return std::make_unique<FixedMotion>(inPlane(spec.position));
    case MotionKind::kSinusoid:
      if (!(spec.period > 0.0)) throw std::invalid_argument("top.motion.period: must be > 0");
      return std::make_unique<SinusoidMotion>(inPlane(spec.position), inPlane(spec.amplitude), spec.period,
                                              spec.phase.x());
    case MotionKind::kVelocityProfile: {
      std::vector<VelocityProfileMotion::Knot> knots;
      knots.reserve(spec.knots.size());
      for (const TopMotionSpec::Knot& k : spec.knots) knots.push_back({k.t, inPlane(k.v)});
      return std::make_unique<VelocityProfileMotion>(inPlane(spec.position), std::move(knots));
    }
  }
  throw std::invalid_argument("top.motion.type: unknown motion (accepted: " + choiceNames<MotionKind>() + ")");
}

StaticsProblem staticsProblem(const Scene& scene) {
  StaticsProblem p;
  p.top = buildTopMotion(scene.top)->at(0.0).p;
  p.tolerance = scene.initial.tolerance;
  if (scene.initial.type == InitialKind::kDisplaced) {
    p.kind = StaticsProblem::Kind::kEndDisplaced;
    p.end_dx = scene.initial.end_dx;
  } else if (scene.initial.type == InitialKind::kBetweenPoints) {
    p.kind = StaticsProblem::Kind::kBetweenPoints;
    p.end_point = inPlane(scene.bottom_point);
  } else {
    p.kind = StaticsProblem::Kind::kHanging;
  }
  return p;
}

}  // namespace riser_sim
