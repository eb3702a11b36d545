// Small fixed-size Eigen aliases used across the core. Units are SI throughout.
#pragma once
#include <Eigen/Core>
#include <Eigen/StdVector>
#include <vector>

namespace riser_sim {

using Vec2 = Eigen::Vector2d;
using Vec4 = Eigen::Vector4d;
using Mat2 = Eigen::Matrix2d;
using Mat4 = Eigen::Matrix4d;
using Mat24 = Eigen::Matrix<double, 2, 4>;
using Mat42 = Eigen::Matrix<double, 4, 2>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

template <class T>
using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

// Generalised coordinates of one rigid finite element (paper eq. 6): q_i = [x_i, y_i, Δ_i, φ_i].
enum Dof { kX = 0, kY = 1, kDelta = 2, kPhi = 3 };
constexpr int kDofPerBody = 4;

inline Vec2 unit(double phi) { return Vec2(std::cos(phi), std::sin(phi)); }
inline Vec2 perp(const Vec2& e) { return Vec2(-e.y(), e.x()); }

}  // namespace riser_sim
