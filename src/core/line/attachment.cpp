#include "riser_sim/line/attachment.h"

#include <sstream>
#include <stdexcept>

#include "riser_sim/planar/model.h"

namespace riser_sim {

AttachmentPoint locateAttachment(const Model& model, double arc_length, const std::string& key) {
  const double L = model.length();
  if (!(arc_length >= 0.0 && arc_length <= L)) {
    std::ostringstream o;
    o.precision(9);
    o << key << ": " << arc_length << " m is off the line (0 to line.length = " << L << " m)";
    throw std::invalid_argument(o.str());
  }
  // The rfe whose span [s_begin, s_begin + l_i) holds it (rfe n holds the end).
  int i = model.bodies() - 1;
  for (int k = 0; k < model.bodies(); ++k)
    if (arc_length < model.rfe(k).s_begin + model.rfe(k).length) {
      i = k;
      break;
    }
  const Rfe& r = model.rfe(i);
  AttachmentPoint p;
  p.rfe = i;
  p.s0 = std::min(std::max(arc_length - r.s_begin, 0.0), r.length);
  p.kappa = p.s0 < r.length1 ? 0.0 : 1.0;  // beyond the spring: moves with Δ_i
  return p;
}

void addAttachmentMasses(Model& model, const std::vector<AttachmentSpec>& attachments) {
  for (size_t k = 0; k < attachments.size(); ++k) {
    const AttachmentSpec& a = attachments[k];
    const std::string key = "attachments[" + std::to_string(k) + "]";
    if (!(a.mass >= 0.0)) throw std::invalid_argument(key + ".mass: must be >= 0");
    const AttachmentPoint p = locateAttachment(model, a.arc_length, key + ".arc_length");
    if (a.mass > 0.0) model.addPointMass(p.rfe, a.mass, p.s0, p.kappa);
  }
}

}  // namespace riser_sim
