#include "riser_sim/scene.h"

#include <stdexcept>

#include "riser_sim/forces/attachments.h"
#include "riser_sim/forces/axial_spring.h"
#include "riser_sim/forces/bending_spring.h"
#include "riser_sim/forces/buoyancy.h"
#include "riser_sim/forces/gravity.h"
#include "riser_sim/forces/hydro_inertia.h"
#include "riser_sim/forces/morison_drag.h"

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

namespace {
bool sectionsDrag(const Scene& scene) {
  for (const LineSection& s : scene.sections)
    if (s.hydro.drag_normal > 0.0 || s.hydro.drag_tangential > 0.0) return true;
  return false;
}
bool sectionsBend(const Scene& scene) {
  for (const LineSection& s : scene.sections)
    if (s.props.EI > 0.0 || s.props.bending_damping > 0.0) return true;
  return !scene.stiffeners.empty();
}
}  // namespace

std::shared_ptr<Model> buildModel(const Scene& scene) {
  auto model =
      std::make_shared<Model>(lineSections(scene), scene.stiffeners, scene.options, scene.end_mass, scene.gravity);
  model->setBottom(scene.bottom, scene.bottom_point);
  // Only the terms the scene needs are built (a term that is off costs nothing).
  if (scene.gravity != 0.0) model->addTerm(std::make_unique<Gravity>());
  if (scene.options.axial_flexibility) model->addTerm(std::make_unique<AxialSpring>());
  if (scene.options.bending && (scene.line.EI > 0.0 || scene.line.bending_damping > 0.0 || sectionsBend(scene)))
    model->addTerm(std::make_unique<BendingSpring>());
  if (scene.water.enabled) {
    const WaterKinematics water(scene.water, scene.gravity);
    if (scene.gravity != 0.0) model->addTerm(std::make_unique<Buoyancy>(scene.water));
    const HydroSpec& h = scene.hydro;
    if (h.enabled && (h.drag_normal > 0.0 || h.drag_tangential > 0.0 || sectionsDrag(scene)))
      model->addTerm(std::make_unique<MorisonDrag>(water, h.drag_tangential, h.drag_normal));
    const bool section_mass = sectionsAddMass(scene);
    if (h.enabled && (h.inertia_coefficient != 1.0 || h.axial_added_mass != 0.0 || water.moving() || section_mass))
      model->addTerm(std::make_unique<HydroInertia>(water, h.inertia_coefficient, h.axial_added_mass, section_mass));
  }
  if (scene.seabed.enabled) model->addTerm(std::make_unique<Seabed>(scene.seabed));
  if (!scene.attachments.empty()) {  // their masses are parts of their rfes; the rest is their term
    addAttachmentMasses(*model, scene.attachments);
    model->addTerm(std::make_unique<Attachments>(*model, scene.attachments, scene.water, scene.seabed, scene.gravity));
  }
  const InternalFlowSpec& f = scene.internal_fluid;
  if (f.density > 0.0 && (f.velocity != 0.0 || f.acceleration != 0.0))
    f.model == FlowModelKind::kPaper ? model->addTerm(std::make_unique<InternalFlow>(f, scene.line.internalArea()))
                                     : model->addTerm(std::make_unique<PipeFlow>(f, scene.line.internalArea()));
  return model;
}

std::unique_ptr<TopMotion> buildTopMotion(const TopMotionSpec& spec) {
  switch (spec.type) {
    case MotionKind::kFixed:
    case MotionKind::kExternal: return std::make_unique<FixedMotion>(spec.position);
    case MotionKind::kSinusoid:
      if (!(spec.period > 0.0)) throw std::invalid_argument("top.motion.period: must be > 0");
      return std::make_unique<SinusoidMotion>(spec.position, spec.amplitude, spec.period, spec.phase);
    case MotionKind::kVelocityProfile: return std::make_unique<VelocityProfileMotion>(spec.position, spec.knots);
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
    p.end_point = scene.bottom_point;
  } else {
    p.kind = StaticsProblem::Kind::kHanging;
  }
  return p;
}

}  // namespace riser_sim
