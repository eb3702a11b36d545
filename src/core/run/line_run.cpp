// The two engines behind LineRun: the planar Simulator (its plane is 3D's x-z) and spatial::Run3.
#include "riser_sim/run/line_run.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/planar/forces/attachments.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/in_plane.h"
#include "riser_sim/spatial/external_motion.h"
#include "riser_sim/spatial/forces/attachments.h"
#include "riser_sim/spatial/forces/bending_spring.h"
#include "riser_sim/spatial/joint_bending.h"
#include "riser_sim/spatial/rfe_frames.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {

bool allFinite(const RunOutputs& o) {
  const auto finite = [](const std::vector<double>& v) {
    for (double x : v)
      if (!std::isfinite(x)) return false;
    return true;
  };
  const auto finite3 = [](const AlignedVector<Vec3>& v) {
    for (const Vec3& x : v)
      if (!x.allFinite()) return false;
    return true;
  };
  for (const Eigen::Quaterniond& q : o.frames)
    if (!q.coeffs().allFinite()) return false;
  for (const Vec3* v :
       {&o.top_point, &o.end_point, &o.top_force, &o.bottom_force, &o.top_moment, &o.bottom_moment, &o.bottom_point})
    if (!v->allFinite()) return false;
  for (double x : {o.t, o.top_twist, o.top_tension, o.max_tension, o.bottom_tension, o.energy, o.work, o.energy_drift,
                   o.constraint_error})
    if (!std::isfinite(x)) return false;
  return finite3(o.springs) && finite3(o.points) && finite3(o.bending_moment_vector) && finite(o.axial_force) &&
         finite(o.elongations) && finite(o.arc_length) && finite(o.angles) && finite(o.bending_moment) &&
         finite(o.curvature) && finite3(o.attachment_points) && finite3(o.attachment_forces);
}

namespace {

// initial.velocity with holders driven from outside: their feeds start at rest, so a translation (live top) or any
// rigid motion (live bottom) would contradict them (initial_velocity.h).
void checkLiveHolders(const Scene& scene, const LineRunInputs& inputs) {
  const InitialSpec& v = scene.initial;
  if (!v.has_velocity) return;
  if (inputs.top && !v.translation.isZero())
    throw std::invalid_argument(
        "initial.velocity.translation: the top is driven from outside (its feed starts at rest at t = 0); a "
        "translation would pull the line off the hang-off");
  if (inputs.bottom && (!v.translation.isZero() || v.rotation != 0.0))
    throw std::invalid_argument(
        "initial.velocity: the pinned bottom is driven from outside (its feed starts at rest at t = 0); a rigid "
        "motion of the line would pull it off the anchor");
}

// Every per-rfe and per-joint output sized for nb rfes.
void sizeOutputs(RunOutputs& o, int nb, bool planar) {
  o.springs.assign(nb, Vec3::Zero());
  o.axial_force.assign(nb, 0.0);
  o.points.assign(nb + 1, Vec3::Zero());
  o.frames.assign(nb, Eigen::Quaterniond::Identity());
  o.elongations.assign(nb, 0.0);
  o.arc_length.assign(nb, 0.0);
  o.angles.assign(planar ? nb : 0, 0.0);
  o.bending_moment_vector.assign(nb - 1, Vec3::Zero());
  o.bending_moment.assign(nb - 1, 0.0);
  o.curvature.assign(nb - 1, 0.0);
}

class PlanarLineRun : public LineRun {
 public:
  PlanarLineRun(const Scene& scene, const LineRunInputs& inputs) : run_(build(scene, inputs)), sim_(*run_.sim) {
    const InitialState& init = run_.initial;
    start_.about = init.about;
    start_.equilibrium = init.equilibrium;
    start_.statics_iterations = init.statics.iterations;
    start_.statics_residual = init.statics.residual;
    start_.statics_message = init.statics.message;
    start_.end_force = inSpace(init.statics.end_force);
    if (inputs.top) motion_ = static_cast<ExternalMotion*>(&sim_.topMotion());
    sizeOutputs(out_, sim_.model().bodies(), true);
    attachments_ = dynamic_cast<const Attachments*>(sim_.model().findTerm("attachments"));
    if (attachments_) {
      out_.attachment_points.assign(attachments_->count(), Vec3::Zero());
      out_.attachment_forces.assign(attachments_->count(), Vec3::Zero());
      kin_.resize(sim_.model().bodies());
    }
  }
  bool spatial() const override { return false; }
  bool step() override { return sim_.step(); }
  double time() const override { return sim_.time(); }
  long steps() const override { return sim_.steps(); }
  double dt() const override { return sim_.dt(); }
  const std::string& divergenceReason() const override { return sim_.divergenceReason(); }
  const RunOutputs& outputs() override {
    const LineOutputs& o = sim_.outputs();
    const Model& model = sim_.model();
    out_.t = o.t;
    out_.top_point = inSpace(o.points.front());
    out_.end_point = inSpace(o.points.back());
    out_.top_force = inSpace(o.top_force);
    out_.bottom_force = inSpace(o.bottom_force);
    out_.top_tension = o.top_tension;
    out_.bottom_tension = o.bottom_tension;
    out_.max_tension = o.max_tension;
    out_.energy = o.kinetic_energy + o.potential_energy;
    out_.work = o.work_in;
    out_.constraint_error = o.constraint_error;
    for (size_t k = 0; k < o.points.size(); ++k) out_.points[k] = inSpace(o.points[k]);
    for (size_t k = 0; k < out_.springs.size(); ++k) {  // A_k + l1_k (cos φ_k, sin φ_k)
      const double l1 = model.rfe(static_cast<int>(k)).length1, phi = o.angles[k];
      out_.springs[k] = inSpace(o.points[k] + l1 * Vec2(std::cos(phi), std::sin(phi)));
      out_.axial_force[k] = o.axial_force[k];
      out_.elongations[k] = o.elongations[k];
      out_.arc_length[k] = o.arc_length[k];
      out_.angles[k] = phi;
      // x towards z in the x-z plane: a turn by -φ about y.
      out_.frames[k] = Eigen::Quaterniond(Eigen::AngleAxisd(-phi, Vec3::UnitY()));
    }
    for (size_t j = 0; j < out_.bending_moment.size(); ++j) {  // a turn from +x towards +z is about -y
      out_.bending_moment[j] = o.bending_moment[j];
      out_.bending_moment_vector[j] = Vec3(0.0, -o.bending_moment[j], 0.0);
      // joint j (between rfes j and j+1) bends segment j
      out_.curvature[j] = std::abs(o.angles[j + 1] - o.angles[j]) / model.segmentLength(static_cast<int>(j));
    }
    if (attachments_) {
      sim_.kinematics(kin_);
      for (int k = 0; k < attachments_->count(); ++k) {
        out_.attachment_points[k] = inSpace(attachments_->position(kin_, k));
        out_.attachment_forces[k] = inSpace(attachments_->force(model, kin_, o.t, k));
      }
    }
    out_.energy_drift = sim_.energyDrift();
    return out_;
  }
  double maxConstraintError() const override { return sim_.maxConstraintError(); }
  double energyDrift() override { return sim_.energyDrift(); }
  double energyScale() const override { return sim_.energyScale(); }
  const ForceNoiseMonitor& forceNoise() const override { return sim_.forceNoise(); }
  std::string forceWarning(const ForceNoise& e) const override { return sim_.forceWarning(e); }
  double stableStepEstimate() const override { return sim_.stableStepEstimate(); }
  std::string stepAboveLimit() const override { return sim_.stepAboveLimit(); }
  double highestFrequency() const override { return sim_.highestFrequency(); }
  bool explicitFixedStep() const override { return sim_.integrator().explicitFixedStep(); }
  Integrator::Stats integratorStats() const override { return sim_.integrator().stats(); }

  bool addSample(Holder h, double t_sample, const Vec3& p, const Eigen::Quaterniond&) override {
    return h == Holder::kTop && motion_ && motion_->addSample(t_sample, inPlane(p), sim_.time());
  }
  void restartHolder(Holder h, double t, const Vec3& p, const Eigen::Quaterniond&) override {
    if (h == Holder::kTop && motion_) motion_->reset(t, inPlane(p));
  }
  void shiftSampleTimes(double dt) override {
    if (motion_) motion_->shiftSampleTimes(dt);
  }
  bool live(Holder h) const override { return h == Holder::kTop && motion_; }
  MotionGaps gaps(Holder h) const override { return live(h) ? motion_->gaps() : MotionGaps(); }

 private:
  // The run of the scene; a live top: an ExternalMotion from its start, the scene's top fixed there.
  Run build(const Scene& scene, const LineRunInputs& inputs) {
    if (inputs.bottom) throw std::invalid_argument("bottom.motion: a bottom driven from outside needs space: spatial");
    checkLiveHolders(scene, inputs);
    held_ = scene;
    RunInputs in;
    in.statics_progress = inputs.statics_progress;
    if (!inputs.top) return buildRun(held_, std::move(in));
    const Vec2 top = inPlane(inputs.top->point);
    held_.top.type = MotionKind::kFixed;
    held_.top.position = inSpace(top);
    in.top = top;
    in.motion = std::make_unique<ExternalMotion>(top, inputs.top->t, inputs.motion);
    return buildRun(held_, std::move(in));
  }

  Run run_;
  Simulator& sim_;
  ExternalMotion* motion_ = nullptr;  // a live top, owned by sim_
  RunOutputs out_;
  const Attachments* attachments_ = nullptr;  // the scene's attachments' term (or none)
  Kinematics kin_;                            // the state's, for the attachments' outputs
};

class SpatialLineRun : public LineRun {
 public:
  SpatialLineRun(const Scene& scene, const LineRunInputs& inputs) : run_(build(scene, inputs)) {
    const spatial::InitialState3& init = run_.initial();
    start_.about = init.about;
    start_.equilibrium = init.equilibrium;
    start_.statics_iterations = init.statics.iterations;
    start_.statics_residual = init.statics.residual;
    start_.statics_message = init.statics.message;
    start_.end_force = init.end_force;
    start_.has_rest_acceleration = true;
    start_.initial_acceleration = init.max_acceleration;
    start_.initial_acceleration_bound = init.acceleration_bound;
    start_.has_twist_moment = scene.torsion.enabled;
    start_.initial_twist_moment = init.max_twist_moment;
    start_.initial_twist_moment_bound = init.twist_moment_bound;
    if (bottom_) {  // the modes hold a driven bottom where it started
      held_.bottom_motion.type = MotionKind::kFixed;
      held_.bottom_point = held_.bottom_motion.position = init.kin.back().end();
    }
    const spatial::Model3& model = run_.model();
    const int nb = model.bodies();
    sizeOutputs(out_, nb, false);
    for (int i = 0; i < nb; ++i) out_.arc_length[i] = model.rfe(i).s_begin + 0.5 * model.rfe(i).length;
    kin_.resize(nb);
    for (const auto& term : model.terms())
      if (const auto* a = dynamic_cast<const spatial::Attachments*>(term.get())) attachments_ = a;
    if (attachments_) {
      out_.attachment_points.assign(attachments_->count(), Vec3::Zero());
      out_.attachment_forces.assign(attachments_->count(), Vec3::Zero());
    }
  }
  bool spatial() const override { return true; }
  bool step() override { return run_.step(); }
  double time() const override { return run_.time(); }
  long steps() const override { return run_.steps(); }
  double dt() const override { return run_.dt(); }
  const std::string& divergenceReason() const override { return run_.divergenceReason(); }
  const RunOutputs& outputs() override {
    const spatial::LineOutputs3& o = run_.outputs();
    const spatial::Simulator3& sim = run_.simulator();
    sim.kinematics(kin_);  // of the same state, velocities included (the dampers' moments)
    const spatial::Kinematics3& kin = kin_;
    out_.t = o.t;
    out_.top_point = o.points.front();
    out_.end_point = o.points.back();
    out_.top_force = o.top_force;
    out_.bottom_force = o.bottom_force;
    out_.top_moment = o.top_moment;
    out_.bottom_moment = o.bottom_moment;
    out_.bottom_point = o.bottom_point;
    out_.top_twist = o.top_twist;
    out_.top_tension = o.top_tension;
    out_.bottom_tension = o.axial_force.back();
    out_.max_tension = o.max_tension;
    out_.energy = o.kinetic_energy + o.potential_energy;
    out_.work = o.work_in;
    out_.constraint_error = o.constraint_error;
    for (size_t k = 0; k < o.points.size(); ++k) out_.points[k] = o.points[k];
    for (size_t k = 0; k < o.springs.size(); ++k) {
      out_.springs[k] = o.springs[k];
      out_.axial_force[k] = o.axial_force[k];
      out_.elongations[k] = kin[k].delta;
    }
    for (size_t j = 0; j < out_.curvature.size(); ++j) {
      const int i = static_cast<int>(j) + 1;  // spring i, between rfes j and j+1, bends segment j
      const spatial::Model3& model = run_.model();
      const spatial::BendingJoint b = spatial::bendingJoint(kin[j], kin[j + 1], model.bendingStiffness(i),
                                                            model.bendingDamping(i), model.line().segmentLength(i - 1));
      out_.curvature[j] = b.curvature;
      out_.bending_moment_vector[j] = b.moment;
      out_.bending_moment[j] = b.moment.norm();
    }
    if (run_.model().hasBendingAxes()) addAxesMoments(sim, kin);
    fillFrames(sim, kin);
    if (attachments_)
      for (int k = 0; k < attachments_->count(); ++k) {
        out_.attachment_points[k] = attachments_->position(kin, k);
        out_.attachment_forces[k] = attachments_->force(run_.model(), kin, o.t, k);
      }
    out_.energy_drift = run_.energyDrift();
    return out_;
  }
  double maxConstraintError() const override { return run_.maxConstraintError(); }
  double energyDrift() override { return run_.energyDrift(); }
  double energyScale() const override { return run_.energyScale(); }
  const ForceNoiseMonitor& forceNoise() const override { return run_.forceNoise(); }
  std::string forceWarning(const ForceNoise& e) const override { return run_.forceWarning(e); }
  double stableStepEstimate() const override { return run_.stableStepEstimate(); }
  std::string stepAboveLimit() const override { return run_.stepAboveLimit(); }
  double highestFrequency() const override { return run_.highestFrequency(); }
  bool explicitFixedStep() const override { return run_.explicitFixedStep(); }
  Integrator::Stats integratorStats() const override { return run_.simulator().integrator().stats(); }
  bool bottomMoves() const override { return run_.bottomMoves(); }
  bool hasTorsion() const override { return run_.hasTorsion(); }
  bool hasTopFlexJoint() const override { return run_.topFlexJoint() != nullptr; }
  bool hasBottomFlexJoint() const override { return run_.bottomFlexJoint() != nullptr; }
  double maxTopMoment() const override { return run_.maxTopMoment(); }
  double maxBottomMoment() const override { return run_.maxBottomMoment(); }

  bool addSample(Holder h, double t_sample, const Vec3& p, const Eigen::Quaterniond& q) override {
    spatial::ExternalMotion3* m = motion(h);
    return m && m->addSample(t_sample, p, q, run_.time());
  }
  void restartHolder(Holder h, double t, const Vec3& p, const Eigen::Quaterniond& q) override {
    if (spatial::ExternalMotion3* m = motion(h)) m->reset(t, p, q);
  }
  void shiftSampleTimes(double dt) override {
    if (top_) top_->shiftSampleTimes(dt);
    if (bottom_) bottom_->shiftSampleTimes(dt);
  }
  bool live(Holder h) const override { return (h == Holder::kTop ? top_ : bottom_.get()) != nullptr; }
  MotionGaps gaps(Holder h) const override {
    const spatial::ExternalMotion3* m = h == Holder::kTop ? top_ : bottom_.get();
    return m ? m->gaps() : MotionGaps();
  }

 private:
  // The run of the scene; live holders: ExternalMotion3s from their starts (with the attitude: flex joints
  // turn with the vessel and the ROV), the scene's top fixed at its start.
  spatial::Run3 build(const Scene& scene, const LineRunInputs& inputs) {
    checkLiveHolders(scene, inputs);
    held_ = scene;
    spatial::RunInputs3 in;
    in.statics_progress = inputs.statics_progress;
    if (inputs.top) {
      const HolderStart& s = *inputs.top;
      held_.top.type = MotionKind::kFixed;
      held_.top.position = s.point;
      in.top = s.point;
      auto m = std::make_unique<spatial::ExternalMotion3>(s.point, s.attitude, s.t, inputs.motion);
      top_ = m.get();
      in.motion = std::move(m);
    }
    if (inputs.bottom) {
      const HolderStart& s = *inputs.bottom;
      bottom_ = std::make_shared<spatial::ExternalMotion3>(s.point, s.attitude, s.t, inputs.motion);
      in.bottom_motion = bottom_;
    }
    return spatial::Run3(held_, std::move(in));
  }
  spatial::ExternalMotion3* motion(Holder h) { return h == Holder::kTop ? top_ : bottom_.get(); }

  // Bending axes (EI_1 != EI_2, bending_axes.h): joint k's moment gains ∂/∂κ of the axes' energy
  // (σ/4) Σ_{j=a,b} κᵀ P_j κ, that is (σ/2)(P_a + P_b) κ with κ = (θ / sin θ) n_a × n_b and P_j κ =
  // m1 (m1·κ) - m2 (m2·κ) on rfe j's material axes (bendingJoint has the isotropic (Ē/d) κ).
  void addAxesMoments(const spatial::Simulator3& sim, const spatial::Kinematics3& kin) {
    const double sigma = run_.model().bendingSplit();
    const double* theta = sim.state().data() + run_.model().dofs();
    const spatial::TwistFrames& f = sim.lastEvaluation().twist.frames;
    for (size_t j = 0; j < out_.curvature.size(); ++j) {
      const int a = static_cast<int>(j), b = a + 1;
      const Vec3 na = kin[a].e.normalized(), nb = kin[b].e.normalized(), x = na.cross(nb);
      const double s = x.norm(), turn = std::atan2(s, na.dot(nb));
      if (s == 0.0 || turn >= M_PI - spatial::BendingSpring::kFoldedTol) continue;  // κ = 0, or folded (as the spring)
      const Vec3 kappa = (turn / s) * x;
      const auto split = [&](const Vec3& n, const Vec3& m1) {
        const Vec3 m2 = n.cross(m1);
        return Vec3(m1.dot(kappa) * m1 - m2.dot(kappa) * m2);
      };
      out_.bending_moment_vector[j] += 0.5 * sigma *
                                       (split(na, spatial::materialDirector(f, a, na, theta[a])) +
                                        split(nb, spatial::materialDirector(f, b, nb, theta[b])));
      out_.bending_moment[j] = out_.bending_moment_vector[j].norm();
    }
  }

  // Torsion on: the material frames (the spins follow q in the state, simulator.h); a chart at its singularity
  // (the top rfe turned 180 deg from the hang-off's axis) or no torsion: the minimal-rotation frames.
  void fillFrames(const spatial::Simulator3& sim, const spatial::Kinematics3& kin) {
    const int nb = static_cast<int>(out_.frames.size());
    bool finite = false;
    if (run_.hasTorsion()) {
      const double* theta = sim.state().data() + run_.model().dofs();
      const spatial::TwistFrames& f = sim.lastEvaluation().twist.frames;
      finite = true;
      for (int i = 0; i < nb; ++i) {
        out_.frames[i] = spatial::materialFrame(kin[i].e, f.centre[i], f.ref[i], i == 0 ? 0.0 : theta[i]);
        finite = finite && out_.frames[i].coeffs().allFinite();
      }
    }
    if (!finite) line_frames_.update(out_.points, nb, out_.frames);
  }

  spatial::ExternalMotion3* top_ = nullptr;           // a live top, owned by run_'s simulator
  std::shared_ptr<spatial::ExternalMotion3> bottom_;  // a live bottom, shared with run_'s model
  mutable spatial::Run3 run_;                         // simulator() is non-const
  RunOutputs out_;
  spatial::LineFrames line_frames_;
  spatial::Kinematics3 kin_;                           // of the last outputs()
  const spatial::Attachments* attachments_ = nullptr;  // the scene's attachments' term (or none)
};

}  // namespace

std::unique_ptr<LineRun> buildLineRun(const Scene& scene, const LineRunInputs& inputs) {
  if (scene.space == SpaceKind::kSpatial) return std::make_unique<SpatialLineRun>(scene, inputs);
  return std::make_unique<PlanarLineRun>(scene, inputs);
}

}  // namespace riser_sim
