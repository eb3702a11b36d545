// The planar core behind LineRun: riser_sim::buildRun with an ExternalMotion top; the hang-off projected
// onto the riser's x-z plane (world y dropped), messages from LineMessages and LineMarkers.
#pragma once
#include <memory>

#include "riser_sim/external_motion.h"
#include "riser_sim/run_builder.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages.h"
#include "riser_sim_ros/line_run.h"

namespace riser_sim_ros {

class PlanarLineRun : public LineRun {
 public:
  // Throws as riser_sim::buildRun.
  PlanarLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t, const NodeParams& params);
  bool spatial() const override { return false; }
  void restartMotion(double t, const VesselSample& s) override { motion_->reset(t, toPaper(s.hangoff)); }
  bool addSample(double t_sample, const VesselSample& s) override {
    return motion_->addSample(t_sample, toPaper(s.hangoff), sim_->time());
  }
  void shiftSampleTimes(double dt) override { motion_->shiftSampleTimes(dt); }
  bool step() override { return sim_->step(); }
  const std::string& divergenceReason() const override { return sim_->divergenceReason(); }
  double time() const override { return sim_->time(); }
  double dt() const override { return sim_->dt(); }
  std::string stepAboveLimit() const override { return sim_->stepAboveLimit(); }
  std::string startMessage() override;
  void shareStatics(ModesServer& modes, const ros::Time& stamp) override;
  RunHealth health() override;

  bool evaluate() override;
  const riser_sim::Tension& tension(const ros::Time& stamp) override;
  const riser_sim::LineState& state(const ros::Time& stamp) override;
  const geometry_msgs::WrenchStamped& topWrench(const ros::Time& stamp) override;
  const std::vector<geometry_msgs::TransformStamped>& transforms(const ros::Time& stamp) override;
  const visualization_msgs::MarkerArray& markers(const ros::Time& stamp) override;

 private:
  riser_sim::Scene scene_;  // top fixed at the start's hang-off (~modes)
  riser_sim::Run run_;
  riser_sim::Simulator* sim_ = nullptr;       // run_.sim
  riser_sim::ExternalMotion* motion_ = nullptr;  // owned by sim_
  const riser_sim::LineOutputs* out_ = nullptr;  // of the last evaluate()
  LineMessages msgs_;
  LineMarkers markers_;
};

}  // namespace riser_sim_ros
