// A planar scene is the 3D scene in its vertical x-z plane: the scene holds 3D vectors [x, y, z] (z up, REP 103)
// and the planar engine reads their (x, z) as its (x, y_up).
#pragma once
#include "riser_sim/types.h"

namespace riser_sim {

// [x, y, z] -> the plane's (x, z) (world y dropped; exact: the doubles are copied).
inline Vec2 inPlane(const Eigen::Vector3d& v) { return Vec2(v.x(), v.z()); }
// The plane's (x, z) -> [x, 0, z].
inline Eigen::Vector3d inSpace(const Vec2& p) { return Eigen::Vector3d(p.x(), 0.0, p.y()); }

}  // namespace riser_sim
