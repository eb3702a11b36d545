// Seabed in 3D: a plane touched by the contact points, the joints A_0..A_n and the end of rfe n (as the planar
// Seabed). Level (slope 0): at height `level` along "up" (against gravity). Sloped: tilted by `slope` about the
// horizontal axis normal to the heading h of steepest ascent; normal n = cos(slope) up - sin(slope) h, through the
// point `level` up (on the origin's vertical). Below it, per point, with p = n·(level up - x) the penetration:
// - normal: F_n = max(C_n p - c_n v_n, 0) n (never pulls), V = ½ C_n p²;
// - tangential damping -c_t v_t (v_t the velocity along the plane);
// - Coulomb friction, smoothed: F_f = -F_n (μ_a v_a a + μ_l v_l l) / sqrt(v_a² + v_l² + v_s²), with a the line's
//   direction projected on the plane (rfe j's, the end's rfe for the end), l = n × a, v_s the sliding speed
//   below which it acts as a viscous stick (friction_velocity). Sliding along a: μ_a F_n; across: μ_l F_n.
#pragma once
#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/spatial/force_term.h"

namespace riser_sim {
namespace spatial {

class Seabed : public ForceTerm3 {
 public:
  Seabed(const SeabedSpec& spec, const Vec3& gravity);
  std::string name() const override { return "seabed"; }
  void addForces(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  double potentialEnergy(const Model3& model, const Kinematics3& kin, double t) const override;
  double power(const Model3& model, const Kinematics3& kin, double t) const override;
  double addForcesAndPower(const Model3& model, const Kinematics3& kin, double t, VecX& Q) const override;
  // The normal spring and the dampers, and the friction's exact rate dependence (its turning with e left out).
  void addStiffness(const Model3& model, const Kinematics3& kin, double t, Stiffness3& S) const override;
  // Contact points below the plane.
  int contacts(const Model3& model, const Kinematics3& kin) const;
  const Vec3& normal() const { return n_; }
  double penetration(const Vec3& p) const { return offset_ - n_.dot(p); }  // [m], > 0 below the plane

 private:
  struct Contact {
    int body;
    double s0, kappa;
    Vec3 p, v;
  };
  Contact contact(const Model3& model, const Kinematics3& kin, int j) const;
  // The contact force; conservative: the spring alone.
  Vec3 force(const Contact& c, const Vec3& e, bool conservative) const;
  double sweep(const Model3& model, const Kinematics3& kin, VecX* Q) const;
  SeabedSpec spec_;
  Vec3 n_;         // the plane's unit normal (up when level)
  double offset_;  // n·(level up): level when level
};

}  // namespace spatial
}  // namespace riser_sim
