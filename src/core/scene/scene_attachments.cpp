// The scene's attachments: a list of point bodies on the line (attachment.h), each a map of keys.
#include <cmath>

#include "riser_sim/planar/force_term.h"
#include "riser_sim/planar/statics.h"
#include "scene_section.h"

namespace riser_sim {
namespace scene_detail {

namespace {

// The line's weight in water with the attachments' masses [N] (> 0: down): the Gravity and Buoyancy terms' net
// vertical force on the line hanging straight down, wholly submerged (whatever its sections).
double wetWeight(const Scene& s) {
  const std::shared_ptr<Model> model = buildModel(s);
  const Kinematics kin = straightLine(*model, Vec2(0.0, s.water.surface - 2.0 * s.length - 1.0), -M_PI / 2);
  VecX Q = VecX::Zero(model->dofs());
  for (const auto& term : model->terms())
    if (term->name() == "gravity" || term->name() == "buoyancy") term->addForces(*model, nullptr, kin, 0.0, Q);
  double up = 0.0;
  for (int i = 0; i < model->bodies(); ++i) up += Q[4 * i + 1];
  return -up;
}

}  // namespace

void parseAttachments(const Section& root, Scene& s) {
  s.attachments.clear();
  if (!root.has("attachments")) return;
  const YAML::Node list = root.at("attachments");
  const std::string path = root.key("attachments");
  if (!list.IsSequence()) throw SceneError(path, "expected a list of attachments (maps), got " + describe(list));
  for (size_t k = 0; k < list.size(); ++k) {
    const std::string key = path + "[" + std::to_string(k) + "]";
    const Section a(list[k], key,
                    {"name", "arc_length", "mass", "volume", "drag_area", "cd", "added_mass", "ca", "seabed_contact"});
    if (!list[k].IsMap()) throw SceneError(key, "expected a map of keys, got " + describe(list[k]));
    AttachmentSpec spec;
    spec.name = a.text("name", "attachment " + std::to_string(k));
    for (const AttachmentSpec& other : s.attachments)
      if (other.name == spec.name) throw SceneError(a.key("name"), "'" + spec.name + "' is used twice");
    spec.arc_length = a.number("arc_length");
    if (!(spec.arc_length >= 0.0 && spec.arc_length <= s.length))
      throw SceneError(a.key("arc_length"), formatNumber(spec.arc_length) + " m is off the line (0 to line.length = " +
                                                formatNumber(s.length) + " m)");
    spec.mass = a.number("mass", 0.0);
    spec.volume = a.number("volume", 0.0);
    spec.drag_area = a.number("drag_area", 0.0);
    for (const char* k2 : {"mass", "volume", "drag_area", "cd", "added_mass", "ca"})
      requireNonNegative(a.key(k2), a.number(k2, 0.0));
    if (spec.drag_area > 0.0 && !a.has("cd"))
      throw SceneError(a.key("cd"), "is needed with drag_area (the drag is ½ ρ_w cd drag_area |u| u)");
    spec.cd = a.number("cd", 0.0);
    if (a.has("added_mass") && a.has("ca"))
      throw SceneError(a.key("ca"), "give added_mass [kg] or ca (added_mass = ca ρ_w volume), not both");
    spec.added_mass = a.number("added_mass", 0.0);
    if (a.has("ca")) {
      if (!(spec.volume > 0.0)) throw SceneError(a.key("ca"), "needs volume > 0 (added_mass = ca ρ_w volume)");
      spec.added_mass = a.number("ca") * s.water.density * spec.volume;
    }
    spec.seabed_contact = a.boolean("seabed_contact", false);
    if (!(spec.mass > 0.0 || spec.volume > 0.0 || spec.drag_area > 0.0))
      throw SceneError(key, "has no mass, volume or drag_area: it would do nothing");
    for (const char* k2 : {"volume", "drag_area", "added_mass", "ca"})
      if (a.has(k2) && a.number(k2) > 0.0 && !s.water.enabled)
        throw SceneError(a.key(k2), "needs environment.water (the attachment must be in water)");
    if (spec.seabed_contact && !s.seabed.enabled) throw SceneError(a.key("seabed_contact"), "needs a seabed section");
    s.attachments.push_back(spec);
  }
}

void checkAttachmentsFloat(const Scene& s) {
  // A free end: the buoys must not lift the whole line (statics would have nothing to hang it from).
  if (s.attachments.empty() || s.bottom == BottomBoundary::kPinned || !s.water.enabled || !(s.gravity > 0.0)) return;
  double lift = 0.0, largest = -INFINITY;
  size_t largest_k = 0;
  for (size_t k = 0; k < s.attachments.size(); ++k) {
    const AttachmentSpec& a = s.attachments[k];
    lift += s.water.density * a.volume * s.gravity;  // their weights: wetWeight
    const double net = (s.water.density * a.volume - a.mass) * s.gravity;
    if (net > largest) largest = net, largest_k = k;
  }
  if (!(lift > 0.0)) return;
  double wet = 0.0;
  try {
    wet = wetWeight(s);
  } catch (const std::invalid_argument&) {
    return;  // a line the later checks refuse, naming its key
  }
  if (lift >= wet)
    throw SceneError("attachments[" + std::to_string(largest_k) + "].volume",
                     "the attachments' buoyancy " + formatNumber(lift) +
                         " N is at least the weight in water of the line with them " + formatNumber(wet) +
                         " N (its buoyant sections' lift included): the buoys ('" + s.attachments[largest_k].name +
                         "' lifts most, net " + formatNumber(largest) +
                         " N) would float the whole line to the surface with the top held; the statics find no "
                         "hanging shape");
}

}  // namespace scene_detail
}  // namespace riser_sim
