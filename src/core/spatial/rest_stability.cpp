// stability3(): the statics' stability criterion (linear_stability.h) on the 3D line at rest.
#include <Eigen/QR>

#include "rest_line.h"
#include "riser_sim/spatial/statics.h"

namespace riser_sim {
namespace spatial {

LinearStability stability3(const Model3& model, const Kinematics3& equilibrium, bool held_end,
                           const ModalOptions3& options, const AlignedVector<Vec3>* material_axes) {
  detail::RestLine line(model, equilibrium, options.fd_step, material_axes, options.hang_off);
  const VecX theta0 = line.theta();
  const bool pinned = model.bottom() == BottomBoundary::kPinned;
  const Vec3 lambda = line.anchorForce(theta0, model);  // 0 unless pinned
  const MatX K = line.stiffness(theta0, model, lambda);
  const MatX C = line.damping(theta0, model);
  const MatX M = line.mass(theta0);
  MatX G;  // the end conditions' Jacobian
  if (pinned)
    G = line.endJacobian(theta0);
  else if (held_end)
    G = line.endJacobian(theta0).topRows(2);
  MatX N;
  if (G.rows() > 0) {
    Eigen::HouseholderQR<MatX> qr(G.transpose());
    N = MatX(qr.householderQ()).rightCols(line.size() - G.rows());
  }
  // Noise of K's central differences (steps 1e-6): ~1e-9 of its entries, as the planar one.
  return linearStability(K, C, M, N, 1e-9);
}

}  // namespace spatial
}  // namespace riser_sim
