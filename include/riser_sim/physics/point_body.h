// The force law of one point body, an attachment (attachment.h), for either engine (V = Vec2 planar, Vec3 in 3D): at
// its centre p moving at v, with the height h of p above the still surface, the water's velocity u_w and acceleration
// a_w at p and the seabed's penetration δ = n·(plane - p) along its unit normal n:
// - buoyancy ρ_w g V_s(h) up, V_s of a sphere of the attachment's volume (SubmergedSphere), U = ρ_w g W;
// - drag f ½ ρ_w C_d A |u| u, u = u_w - v, f = V_s / V the wetted fraction (1 below the surface without volume);
// - Froude-Krylov and the water's acceleration on the added mass, f (ρ_w V + m_a) a_w;
// - seabed contact (per point, as the line's contact points, physics/seabed_contact.h): F_n = max(C_n δ - c_n n·v, 0)
// n, U = ½ C_n δ²,
//   and the tangential damper -c_t (v - (n·v) n).
// The weight is the Gravity term's (the mass is a part of its rfe); the added mass m_a is in the mass matrix.
#pragma once
#include <algorithm>
#include <cmath>

#include "riser_sim/line/attachment.h"
#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/physics/seabed_contact.h"

namespace riser_sim {

template <class V>
struct AttachmentLoad {
  V total, conservative;  // the force [N] and its conservative part (buoyancy, seabed spring)
  double energy = 0.0;    // potential of the conservative part [J]
  // dF/dp = -Kp along the vertical and the normal, dF/dv = -Cp: the law's slopes for the structured solves.
  double k_up = 0.0, k_normal = 0.0, c_normal = 0.0, c_tangential = 0.0;
  double drag = 0.0;  // f ½ ρ_w C_d A (C = drag (|u| I + u uᵀ / |u|))
};

struct AttachmentWater {
  bool enabled = false;
  double density = 0.0, gravity = 0.0;  // ρ_w [kg/m^3], |g| [m/s^2]
};

template <class V>
AttachmentLoad<V> attachmentLoad(const AttachmentSpec& a, double radius, const AttachmentWater& w, double height,
                                 const V& up, const V& v, const V& u_w, const V& a_w, const SeabedSpec* seabed,
                                 double penetration, const V& normal) {
  AttachmentLoad<V> L;
  L.total.setZero();
  L.conservative.setZero();
  if (w.enabled) {
    const SubmergedSphere s = submergedSphere(a.volume, radius, height);
    const double rg = w.density * w.gravity;
    L.conservative += (rg * s.volume) * up;
    L.energy += rg * s.integral;
    L.k_up = rg * s.slope;
    const double f = a.volume > 0.0 ? s.volume / a.volume : (height < 0.0 ? 1.0 : 0.0);
    if (f > 0.0) {
      const V u = u_w - v;
      const double un = u.norm();
      L.drag = f * 0.5 * w.density * a.cd * a.drag_area;
      L.total += (L.drag * un) * u + (f * (w.density * a.volume + a.added_mass)) * a_w;
    }
  }
  if (seabed && penetration > 0.0) {
    const double vn = normal.dot(v);
    const double fn = physics::contactNormalForce(seabed->stiffness_normal, penetration, seabed->damping_normal * vn);
    L.conservative += (seabed->stiffness_normal * penetration) * normal;
    L.energy += physics::contactSpringEnergy(seabed->stiffness_normal, penetration);
    L.total += fn * normal - seabed->damping_tangential * (v - vn * normal) -
               (seabed->stiffness_normal * penetration) * normal;
    if (fn > 0.0) L.k_normal = seabed->stiffness_normal, L.c_normal = seabed->damping_normal;
    L.c_tangential = seabed->damping_tangential;
  }
  L.total += L.conservative;
  return L;
}

}  // namespace riser_sim
