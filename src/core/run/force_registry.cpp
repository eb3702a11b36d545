#include "riser_sim/run/force_registry.h"

#include <memory>
#include <optional>

#include "riser_sim/planar/forces/attachments.h"
#include "riser_sim/planar/forces/axial_spring.h"
#include "riser_sim/planar/forces/bending_spring.h"
#include "riser_sim/planar/forces/buoyancy.h"
#include "riser_sim/planar/forces/gravity.h"
#include "riser_sim/planar/forces/hydro_inertia.h"
#include "riser_sim/planar/forces/internal_flow.h"
#include "riser_sim/planar/forces/morison_drag.h"
#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/spatial/forces/added_mass.h"
#include "riser_sim/spatial/forces/attachments.h"
#include "riser_sim/spatial/forces/axial_spring.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/forces/buoyancy.h"
#include "riser_sim/spatial/forces/froude_krylov.h"
#include "riser_sim/spatial/forces/gravity.h"
#include "riser_sim/spatial/forces/morison_drag.h"
#include "riser_sim/spatial/forces/seabed.h"
#include "riser_sim/spatial/model.h"

namespace riser_sim {

namespace {

using spatial::Model3;
using spatial::Water3;

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
bool wantsSea(const Scene& s) { return s.water.enabled; }
bool wantsHydro(const Scene& s) { return s.water.enabled && s.hydro.enabled; }
bool wantsDrag(const Scene& s) {
  const HydroSpec& h = s.hydro;
  return wantsHydro(s) && (h.drag_normal > 0.0 || h.drag_tangential > 0.0 || sectionsDrag(s));
}
// The sea and the seabed the terms see: the scene's, or their variants (TermOptions).
WaterSpec seaFor(const Scene& s, const TermOptions& o) {
  WaterSpec w = s.water;
  if (o.steady_sea) w.waves.height = w.waves.significant_height = 0.0;
  return w;
}
SeabedSpec seabedFor(const Scene& s, const TermOptions& o) {
  SeabedSpec b = s.seabed;
  if (!o.seabed_friction) b.friction_axial = b.friction_lateral = b.damping_tangential = 0.0;
  return b;
}
// Added mass other than the displaced water's (C_M != 1, C_a,t != 0, or per section).
bool addsMass(const Scene& s) {
  return s.hydro.inertia_coefficient != 1.0 || s.hydro.axial_added_mass != 0.0 || sectionsAddMass(s);
}

const std::vector<ForceTermRow> kRows = {
    {"gravity", [](const Scene& s) { return s.gravity != 0.0; },
     [](const Scene&, const WaterKinematics*, const TermOptions&, Model& m) { m.addTerm(std::make_unique<Gravity>()); },
     [](const Scene&, const Water3*, const TermOptions&, Model3& m) {
       m.addTerm(std::make_unique<spatial::Gravity>());
     }},
    {"axial_spring", [](const Scene& s) { return s.options.axial_flexibility; },
     [](const Scene&, const WaterKinematics*, const TermOptions&, Model& m) {
       m.addTerm(std::make_unique<AxialSpring>());
     },
     [](const Scene&, const Water3*, const TermOptions&, Model3& m) {
       m.addTerm(std::make_unique<spatial::AxialSpring>());
     }},
    // Each engine asks its own line whether any section bends.
    {"bending_spring", [](const Scene& s) { return s.options.bending; },
     [](const Scene& s, const WaterKinematics*, const TermOptions&, Model& m) {
       if (s.line.EI > 0.0 || s.line.bending_damping > 0.0 || sectionsBend(s))
         m.addTerm(std::make_unique<BendingSpring>());
     },
     [](const Scene&, const Water3*, const TermOptions&, Model3& m) {
       if (m.line().hasBending()) m.addTerm(std::make_unique<spatial::BendingSpring>());
     }},
    {"buoyancy", [](const Scene& s) { return wantsSea(s) && s.gravity != 0.0; },
     [](const Scene& s, const WaterKinematics*, const TermOptions& o, Model& m) {
       m.addTerm(std::make_unique<Buoyancy>(seaFor(s, o)));
     },
     [](const Scene&, const Water3* w, const TermOptions&, Model3& m) {
       m.addTerm(std::make_unique<spatial::Buoyancy>(*w));
     }},
    {"morison_drag", wantsDrag,
     [](const Scene& s, const WaterKinematics* w, const TermOptions&, Model& m) {
       m.addTerm(std::make_unique<MorisonDrag>(*w, s.hydro.drag_tangential, s.hydro.drag_normal));
     },
     [](const Scene& s, const Water3* w, const TermOptions& o, Model3& m) {
       m.addTerm(std::make_unique<spatial::MorisonDrag>(*w, s.hydro.drag_tangential, s.hydro.drag_normal,
                                                        o.drag_on_line_at_rest));
     }},
    // Planar: one term (added mass and Froude-Krylov); 3D: the Froude-Krylov force where the water moves, then
    // the added mass.
    {"hydro_inertia", wantsHydro,
     [](const Scene& s, const WaterKinematics* w, const TermOptions&, Model& m) {
       const WaterKinematics& water = *w;
       const HydroSpec& h = s.hydro;
       if (addsMass(s) || water.moving())
         m.addTerm(
             std::make_unique<HydroInertia>(water, h.inertia_coefficient, h.axial_added_mass, sectionsAddMass(s)));
     },
     [](const Scene& s, const Water3* w, const TermOptions&, Model3& m) {
       const Water3& water = *w;
       const HydroSpec& h = s.hydro;
       if (water.moving())
         m.addTerm(std::make_unique<spatial::FroudeKrylov>(water, h.inertia_coefficient, 1.0 + h.axial_added_mass));
       if (addsMass(s))
         m.addTerm(std::make_unique<spatial::AddedMass>(water, h.inertia_coefficient - 1.0, h.axial_added_mass,
                                                        sectionsAddMass(s)));
     }},
    {"seabed", [](const Scene& s) { return s.seabed.enabled; },
     [](const Scene& s, const WaterKinematics*, const TermOptions&, Model& m) {
       m.addTerm(std::make_unique<Seabed>(s.seabed));
     },
     [](const Scene& s, const Water3*, const TermOptions& o, Model3& m) {
       m.addTerm(std::make_unique<spatial::Seabed>(seabedFor(s, o), m.gravity()));
     }},
    // Their masses are parts of their rfes; the rest is their term.
    {"attachments", [](const Scene& s) { return !s.attachments.empty(); },
     [](const Scene& s, const WaterKinematics*, const TermOptions& o, Model& m) {
       addAttachmentMasses(m, s.attachments);
       m.addTerm(std::make_unique<Attachments>(m, s.attachments, seaFor(s, o), seabedFor(s, o), s.gravity));
     },
     [](const Scene& s, const Water3*, const TermOptions& o, Model3& m) {
       addAttachmentMasses(m.mutableLine(), s.attachments);
       m.addTerm(std::make_unique<spatial::Attachments>(m, s.attachments, seaFor(s, o), seabedFor(s, o)));
     }},
    // Planar only (the 3D run refuses a flow: spatial/run_builder.cpp).
    {"internal_flow",
     [](const Scene& s) {
       const InternalFlowSpec& f = s.internal_fluid;
       return f.density > 0.0 && (f.velocity != 0.0 || f.acceleration != 0.0);
     },
     [](const Scene& s, const WaterKinematics*, const TermOptions&, Model& m) {
       const InternalFlowSpec& f = s.internal_fluid;
       if (f.model == FlowModelKind::kPaper)
         m.addTerm(std::make_unique<InternalFlow>(f, s.line.internalArea()));
       else
         m.addTerm(std::make_unique<PipeFlow>(f, s.line.internalArea()));
     },
     nullptr},
};

}  // namespace

const std::vector<ForceTermRow>& forceTermRegistry() { return kRows; }

void addPlanarTerms(const Scene& scene, Model& model, const TermOptions& options) {
  std::optional<WaterKinematics> water;
  if (scene.water.enabled) water.emplace(seaFor(scene, options), scene.gravity);
  for (const ForceTermRow& row : kRows)
    if (row.planar && row.wanted(scene)) row.planar(scene, water ? &*water : nullptr, options, model);
}

void addSpatialTerms(const Scene& scene, spatial::Model3& model, const TermOptions& options) {
  std::optional<Water3> water;
  if (scene.water.enabled) water.emplace(seaFor(scene, options), model.gravity());
  for (const ForceTermRow& row : kRows)
    if (row.spatial && row.wanted(scene)) row.spatial(scene, water ? &*water : nullptr, options, model);
}

}  // namespace riser_sim
