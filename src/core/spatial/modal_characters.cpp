#include "riser_sim/spatial/modal_characters.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>

namespace riser_sim {
namespace spatial {

namespace {

// Σ_p (d_p·n)(d'_p·n): the out-of-plane form of two modes' displacements.
double outOfPlane(const Mode3& a, const Mode3& b, const Vec3& n) {
  double s = 0.0;
  for (size_t p = 0; p < a.displacement.size(); ++p) s += a.displacement[p].dot(n) * b.displacement[p].dot(n);
  return s;
}

void alignPair(Mode3& a, Mode3& b, const Vec3& n) {
  Eigen::Matrix2d P;
  P << outOfPlane(a, a, n), outOfPlane(a, b, n), outOfPlane(a, b, n), outOfPlane(b, b, n);
  const Eigen::Matrix2d R = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(P).eigenvectors();  // col 0: least out
  const Mode3 a0 = a, b0 = b;
  a.theta = R(0, 0) * a0.theta + R(1, 0) * b0.theta;
  b.theta = R(0, 1) * a0.theta + R(1, 1) * b0.theta;
  for (size_t p = 0; p < a.displacement.size(); ++p) {
    a.displacement[p] = R(0, 0) * a0.displacement[p] + R(1, 0) * b0.displacement[p];
    b.displacement[p] = R(0, 1) * a0.displacement[p] + R(1, 1) * b0.displacement[p];
  }
}

bool bending(const Mode3& m, const Vec3& n) {
  const char* c = modeCharacter(m, n);
  return std::strcmp(c, "axial") != 0 && std::strcmp(c, "torsional") != 0;
}

}  // namespace

const char* modeCharacter(const Mode3& m, const Vec3& n) {
  if (m.torsional) return "torsional";
  if (m.along_fraction > 0.5) return "axial";
  double t = 0.0;
  for (const Vec3& v : m.displacement) t += v.squaredNorm();
  return t > 0.0 && outOfPlane(m, m, n) > 0.5 * t ? "out-of-plane" : "in-plane";
}

void alignDegeneratePairs(std::vector<Mode3>& modes, const Vec3& n) {
  for (size_t k = 0; k + 1 < modes.size(); ++k)
    if (bending(modes[k], n) && bending(modes[k + 1], n) &&
        std::abs(modes[k + 1].omega2 - modes[k].omega2) <= kPairTolerance * std::abs(modes[k + 1].omega2)) {
      alignPair(modes[k], modes[k + 1], n);
      ++k;
    }
}

}  // namespace spatial
}  // namespace riser_sim
