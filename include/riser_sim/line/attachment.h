// Point bodies fixed to the line at an arc length: clump weights, buoys and floats. Each is a point mass on
// its rfe (a rigid part at its place along the rfe, on part (1) or (2) by the side of the spring it falls on:
// Model::addPointMass), so it enters the mass matrix, the gravity term and every consumer of the rfes' parts;
// its buoyancy, drag, added mass, Froude-Krylov force and seabed contact are the force terms
// forces/attachments.h (planar) and spatial/forces/attachments.h (3D).
#pragma once
#include <cmath>
#include <string>
#include <vector>

namespace riser_sim {

class Model;

struct AttachmentSpec {
  std::string name;             // attachments[k].name (outputs, markers, messages)
  double arc_length = 0.0;      // from the top, unstretched [m], 0..line.length
  double mass = 0.0;            // [kg]
  double volume = 0.0;          // displaced [m^3]: a sphere of that volume for its submergence
  double drag_area = 0.0;       // A [m^2] of the drag ½ ρ_w C_d A |u| u on the velocity u relative to the water
  double cd = 0.0;              // C_d
  double added_mass = 0.0;      // m_a [kg], isotropic (the scene's `ca` gives C_a ρ_w V)
  bool seabed_contact = false;  // the seabed's normal spring/damper and tangential damper act on its centre
};

// Where an attachment sits: rfe i, distance s0 from A_i at Δ = 0 and kappa (0 on part (1), 1 on part (2)).
struct AttachmentPoint {
  int rfe = 0;
  double s0 = 0.0, kappa = 0.0;
};

// Throws std::invalid_argument("attachments[k].arc_length: ...") when the arc length is off the line.
AttachmentPoint locateAttachment(const Model& model, double arc_length, const std::string& key = "arc_length");

// Adds every attachment's mass as a point part (Model::addPointMass). Throws as locateAttachment.
void addAttachmentMasses(Model& model, const std::vector<AttachmentSpec>& attachments);

// A sphere of volume V (radius r) with its centre at height h above the still surface: the submerged depth
// ζ = clamp(r - h, 0, 2r), the submerged volume V_s(ζ) = π ζ² (3r - ζ) / 3 and W(ζ) = ∫_0^ζ V_s, so that the
// buoyancy ρ g V_s up has the potential U = ρ g W (W = V (r - h) fully submerged: -ρ g V h, as the line's).
struct SubmergedSphere {
  double volume = 0.0;    // V_s [m^3]
  double integral = 0.0;  // W [m^4]
  double slope = 0.0;     // dV_s/dζ = π ζ (2r - ζ) [m^2] (buoyancy stiffness ρ g dV_s/dζ)
};
inline double sphereRadius(double volume) { return std::cbrt(3.0 * volume / (4.0 * M_PI)); }
inline SubmergedSphere submergedSphere(double volume, double radius, double height) {
  SubmergedSphere s;
  if (!(volume > 0.0)) return s;
  const double r = radius, z = r - height;
  if (z <= 0.0) return s;
  if (z >= 2.0 * r) {
    s.volume = volume;
    s.integral = volume * r + volume * (z - 2.0 * r);
    return s;
  }
  s.volume = M_PI * z * z * (3.0 * r - z) / 3.0;
  s.integral = M_PI * (r * z * z * z / 3.0 - z * z * z * z / 12.0);
  s.slope = M_PI * z * (2.0 * r - z);
  return s;
}

}  // namespace riser_sim
