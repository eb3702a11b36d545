#include "riser_sim/spatial/kinematics.h"

#include <stdexcept>

namespace riser_sim {
namespace spatial {

Kinematics3 rigidChain(const Model& line, const Vec3& top, const std::vector<Vec3>& directions, const Vec3& v_top,
                       const Vec3& omega) {
  if (int(directions.size()) != line.bodies()) throw std::invalid_argument("rigidChain: one direction per rfe");
  Kinematics3 kin(line.bodies());
  Vec3 A = top;
  for (int i = 0; i < line.bodies(); ++i) {
    BodyKinematics3& b = kin[i];
    b.A = A;
    b.e = directions[i].normalized();
    b.A_dot = v_top + omega.cross(A - top);
    b.e_dot = omega.cross(b.e);
    b.len = line.rfe(i).length;
    A = b.end();
  }
  return kin;
}

Kinematics3 fromPlanar(const Kinematics& kin, const Mat3& R, const Vec3& offset) {
  Kinematics3 out(kin.size());
  for (size_t i = 0; i < kin.size(); ++i) {
    const BodyKinematics& b = kin[i];
    BodyKinematics3& o = out[i];
    o.A = planarPoint(b.A, R, offset);
    o.A_dot = planarPoint(b.A_dot, R);
    o.delta = b.delta;
    o.delta_dot = b.delta_dot;
    o.e = planarPoint(b.e(), R);
    o.e_dot = planarPoint(b.phi_dot * b.nrm(), R);
    o.len = b.len;
  }
  return out;
}

}  // namespace spatial
}  // namespace riser_sim
