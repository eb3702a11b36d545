// LineRun's outputs (line_run.h) in full: a planar run's are its Simulator's outputs in the x-z plane of 3D
// (points (x, 0, y), frames turned by -φ about y, bending moment vectors (0, -M, 0), curvature |Δφ| / d), and
// the 3D rfe frames (rfe_frames.h): x along each element, never singular, continuous in time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "riser_sim/run/line_run.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/bending_axes.h"
#include "riser_sim/spatial/rfe_frames.h"
#include "riser_sim/spatial/run_builder.h"

#include <yaml-cpp/yaml.h>

namespace riser_sim {
namespace {

using spatial::LineFrames;

// A slack 20 m line between a hang-off 8 m off the anchor's vertical and an anchor 15 m down: bent (bending
// springs and dampers), planar.
Scene tether() {
  return parseScene(YAML::Load(R"(
name: tether
line: {length: 20.0, elements: 10, mass_per_length: 5.0, EI: 100.0, end_mass: 0.0, axial_flexibility: false,
       bending: true, bending_damping: 20.0}
top: {position: [8.0, 0.0], motion: {type: sinusoid, amplitude: [0.3, 0.1], period: 2.0}}
bottom: {type: pinned, position: [0.0, -15.0]}
environment: {gravity: 9.81}
initial: {type: between_points}
solver: {dt: 0.001}
)"));
}

// The same scene through buildRun (the planar Simulator) and buildLineRun, both stepped 200 steps: the same
// state bit for bit (one engine), so its outputs are mapped exactly (0 tolerance but for the frames' sin/cos
// and the curvature's division: 1e-15 relative).
TEST(LineRunOutputs, PlanarAreTheSimulatorsInTheXZPlane) {
  const Scene scene = tether();
  riser_sim::Run ref = buildRun(scene);
  std::unique_ptr<LineRun> run = buildLineRun(scene);
  for (int k = 0; k < 200; ++k) {
    ASSERT_TRUE(ref.sim->step());
    ASSERT_TRUE(run->step());
  }
  const LineOutputs& p = ref.sim->outputs();
  const RunOutputs& o = run->outputs();
  ASSERT_TRUE(allFinite(o));
  const size_t nb = p.angles.size();
  ASSERT_EQ(o.points.size(), nb + 1);
  ASSERT_EQ(o.frames.size(), nb);
  ASSERT_EQ(o.bending_moment.size(), nb - 1);
  for (size_t i = 0; i <= nb; ++i) EXPECT_EQ(o.points[i], Vec3(p.points[i].x(), 0.0, p.points[i].y())) << i;
  for (size_t i = 0; i < nb; ++i) {
    EXPECT_EQ(o.angles[i], p.angles[i]);
    EXPECT_EQ(o.elongations[i], p.elongations[i]);
    EXPECT_EQ(o.arc_length[i], p.arc_length[i]);
    EXPECT_EQ(o.axial_force[i], p.axial_force[i]);
    const Vec3 x = o.frames[i] * Vec3::UnitX(), y = o.frames[i] * Vec3::UnitY();
    EXPECT_LT((x - Vec3(std::cos(p.angles[i]), 0.0, std::sin(p.angles[i]))).norm(), 1e-15) << i;
    EXPECT_LT((y - Vec3::UnitY()).norm(), 1e-15) << i;
  }
  const double d = ref.model->segmentLength();
  for (size_t j = 0; j + 1 < nb; ++j) {
    EXPECT_EQ(o.bending_moment[j], p.bending_moment[j]);
    EXPECT_EQ(o.bending_moment_vector[j], Vec3(0.0, -p.bending_moment[j], 0.0));
    EXPECT_NEAR(o.curvature[j], std::abs(p.angles[j + 1] - p.angles[j]) / d, 1e-15 * (1.0 + o.curvature[j]));
  }
  EXPECT_EQ(o.top_force, Vec3(p.top_force.x(), 0.0, p.top_force.y()));
  EXPECT_EQ(o.top_moment, Vec3::Zero());  // the planar top is pinned
  EXPECT_EQ(o.bottom_tension, p.bottom_tension);
  RunOutputs bad = o;
  bad.bending_moment_vector[0].y() = std::nan("");
  EXPECT_FALSE(allFinite(bad));
}

// A live top (LineRunInputs): the run holds the held scene's top where it started, takes samples and reports
// their gaps; a planar run has no live bottom and refuses one naming the key.
TEST(LineRunOutputs, LiveTopFollowsItsSamples) {
  const Scene scene = tether();
  LineRunInputs in;
  in.top = HolderStart{Vec3(8.0, 5.0, 0.0), Eigen::Quaterniond::Identity(), 0.0};
  std::unique_ptr<LineRun> run = buildLineRun(scene, in);
  EXPECT_TRUE(run->live(Holder::kTop));
  EXPECT_FALSE(run->live(Holder::kBottom));
  EXPECT_EQ(run->heldScene().top.type, MotionKind::kFixed);
  EXPECT_EQ(run->heldScene().top.position, Eigen::Vector3d(8.0, 0.0, 0.0));  // world y dropped: the plane
  EXPECT_LT((run->outputs().top_point - Vec3(8.0, 0.0, 0.0)).norm(), 1e-12);
  for (int k = 1; k <= 1500; ++k) {  // 0.1 m along x over 0.2 s, then still for 1.3 s
    const double t = k * run->dt();
    ASSERT_TRUE(run->addSample(Holder::kTop, t, Vec3(8.0 + 0.1 * std::min(1.0, t / 0.2), 5.0, 0.0),
                               Eigen::Quaterniond::Identity()));
    ASSERT_TRUE(run->step()) << run->divergenceReason();
  }
  // Past the fit window (0.5 s) and the stop, the top holds the last sample (the smoothing is exact at rest).
  EXPECT_NEAR(run->outputs().top_point.x(), 8.1, 1e-9);
  EXPECT_EQ(run->outputs().top_point.y(), 0.0);
  EXPECT_EQ(run->gaps(Holder::kTop).count, 0);
  in.bottom = in.top;
  try {
    buildLineRun(scene, in);
    FAIL() << "a planar live bottom was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bottom.motion"), std::string::npos) << e.what();
  }
}

// Bending axes (EI_1 != EI_2): the moments RunOutputs reports are ∂V/∂κ of the bending energy the forces derive
// from, V_k = ½ (Ē/d) θ_k² + (σ/4) Σ_j κᵀ P_j κ (bending_axes.h), quadratic in κ = (θ / sin θ) n_a × n_b at fixed
// material axes; so Σ_k ½ κ_k·M_k is that energy (isotropic part + bendingAxesEnergy) to round-off, and the
// isotropic moment alone, Ē κ / d, misses the axes' part. A hanging line swayed across its axes, no damper.
TEST(LineRunOutputs, BendingAxesMomentsCarryTheAxesEnergy) {
  const Scene scene = parseScene(YAML::Load(R"(
name: axes
space: spatial
line: {length: 10.0, elements: 10, mass_per_length: 5.0, EI: [400.0, 100.0], bending_axis: [0.0, 1.0, 0.0],
       bending_damping: 0.0, axial_flexibility: false, torsion: {stiffness: 200.0, polar_inertia: 0.01}}
top: {position: [0.0, 0.0, 0.0], motion: {type: sinusoid, amplitude: [0.5, 0.5, 0.0], period: 2.0}}
solver: {dt: 0.001}
)"));
  spatial::Run3 ref(scene);
  std::unique_ptr<LineRun> run = buildLineRun(scene);
  for (int k = 0; k < 700; ++k) {  // the same steps: the same state
    ASSERT_TRUE(ref.step()) << ref.divergenceReason();
    ASSERT_TRUE(run->step()) << run->divergenceReason();
  }
  const RunOutputs& o = run->outputs();
  ref.outputs();  // evaluates the state: the twist charts of lastEvaluation()
  spatial::Simulator3& sim = ref.simulator();
  const spatial::Model3& model = ref.model();
  spatial::Kinematics3 kin(model.bodies());
  sim.kinematics(kin);
  const double* theta = sim.state().data() + model.dofs();
  const double c = model.bendingStiffness(1), d = model.line().segmentLength();  // uniform line
  double from_moments = 0.0, isotropic = 0.0;
  for (size_t j = 0; j < o.curvature.size(); ++j) {
    const Vec3 na = kin[j].e.normalized(), nb = kin[j + 1].e.normalized(), x = na.cross(nb);
    const double turn = std::atan2(x.norm(), na.dot(nb));
    ASSERT_NEAR(o.curvature[j], turn / d, 1e-12);
    const Vec3 kappa = x.norm() > 0.0 ? Vec3((turn / x.norm()) * x) : Vec3::Zero();
    from_moments += 0.5 * kappa.dot(o.bending_moment_vector[j]);
    isotropic += 0.5 * c * turn * turn;
    EXPECT_NEAR(o.bending_moment[j], o.bending_moment_vector[j].norm(), 1e-12 * (1.0 + o.bending_moment[j]));
  }
  const double axes = spatial::bendingAxesEnergy(model, kin, theta, sim.lastEvaluation().twist.frames);
  std::printf("bending energy %.6e J (isotropic %.6e J, axes %.6e J); 1/2 sum kappa.M %.6e J\n", isotropic + axes,
              isotropic, axes, from_moments);
  ASSERT_GT(isotropic, 1e-3);                   // bent: a real comparison [J]
  EXPECT_GT(std::abs(axes), 0.01 * isotropic);  // the axes matter here
  EXPECT_NEAR(from_moments, isotropic + axes, 1e-10 * (isotropic + std::abs(axes)));
}

// 3D rfe frames: x along each element, unit, finite for vertical and horizontal elements, the planar
// frames for a line in the x-z plane, and continuous while rfe 0 turns through vertical and horizontal.
TEST(LineFrames, AlongTheLineNeverSingularAndContinuous) {
  const auto check = [](const AlignedVector<Vec3>& pts, LineFrames& f, std::vector<Eigen::Quaterniond>& q) {
    f.update(pts, static_cast<int>(pts.size()) - 1, q);
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      ASSERT_TRUE(q[i].coeffs().allFinite());
      EXPECT_NEAR(q[i].norm(), 1.0, 1e-12);
      EXPECT_LT((q[i] * Vec3::UnitX() - (pts[i + 1] - pts[i]).normalized()).norm(), 1e-12);
    }
  };
  std::vector<Eigen::Quaterniond> q(3);
  for (const Vec3& d : {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, -1, 0)}) {
    LineFrames f;
    check({Vec3::Zero(), d, 2.0 * d, 3.0 * d}, f, q);
  }
  // In the x-z plane: y stays world y (the planar run's frames).
  LineFrames planar;
  check({Vec3::Zero(), Vec3(1, 0, -1), Vec3(1.5, 0, -2), Vec3(1.5, 0, -3)}, planar, q);
  for (const auto& r : q) EXPECT_LT((r * Vec3::UnitY() - Vec3::UnitY()).norm(), 1e-12);
  // rfe 0 turns in small steps down -> horizontal -> up -> horizontal in y -> down: every frame turns by
  // about the step, never flips.
  LineFrames f;
  std::vector<Eigen::Quaterniond> prev;
  const double step = 0.02;
  for (int k = 0; k <= 630; ++k) {
    const double a = k * step;
    const Vec3 e0 =
        k <= 315 ? Vec3(std::sin(a), 0, -std::cos(a)) : Vec3(std::sin(a), std::sin(a) * 0.3, -std::cos(a)).normalized();
    check({Vec3::Zero(), e0, e0 + Vec3(0, 0, -1), e0 + Vec3(0.2, 0.3, -2)}, f, q);
    if (!prev.empty())
      for (size_t i = 0; i < q.size(); ++i) EXPECT_LT(q[i].angularDistance(prev[i]), 3.0 * step) << k << " " << i;
    prev = q;
  }
}

}  // namespace
}  // namespace riser_sim
