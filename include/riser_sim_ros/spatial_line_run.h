// The 3D core behind LineRun (scene space: spatial): spatial::SpatialRun with its top driven by an
// ExternalMotion3 through the full 3D hang-off (vessel position + orientation applied to hangoff_offset;
// nothing projected); a driven bottom (bottom.motion.type external) by a second ExternalMotion3 through the
// ROV's attachment point. Messages from LineMessages3 and LineMarkers.
#pragma once
#include <memory>

#include <Eigen/Geometry>

#include "riser_sim/spatial/external_motion3.h"
#include "riser_sim/spatial/run_builder.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages3.h"
#include "riser_sim_ros/line_run.h"
#include "riser_sim_ros/sea_markers.h"

namespace riser_sim_ros {

class SpatialLineRun : public LineRun {
 public:
  // Throws as spatial::SpatialRun. bottom: the driven bottom's first sample (null: the scene's bottom).
  SpatialLineRun(const riser_sim::Scene& scene, const VesselSample& s, double t, const NodeParams& params,
                 const VesselSample* bottom = nullptr, double t_bottom = 0.0);
  bool spatial() const override { return true; }
  void restartMotion(double t, const VesselSample& s) override;
  bool addSample(double t_sample, const VesselSample& s) override;
  void shiftSampleTimes(double dt) override;
  bool drivenBottom() const override { return bottom_motion_ != nullptr; }
  void restartBottom(double t, const VesselSample& s) override;
  bool addBottomSample(double t_sample, const VesselSample& s) override;
  bool step() override { return run_->step(); }
  const std::string& divergenceReason() const override { return run_->divergenceReason(); }
  double time() const override { return run_->time(); }
  double dt() const override { return run_->dt(); }
  std::string stepAboveLimit() const override { return run_->stepAboveLimit(); }
  std::string startMessage() override;
  void shareStatics(ModesServer& modes, const ros::Time& stamp) override;
  RunHealth health() override;

  bool evaluate() override;
  const riser_sim::Tension& tension(const ros::Time& stamp) override;
  const riser_sim::LineState& state(const ros::Time& stamp) override;
  const geometry_msgs::WrenchStamped& topWrench(const ros::Time& stamp) override;
  const geometry_msgs::WrenchStamped* bottomWrench(const ros::Time& stamp) override;
  const std::vector<geometry_msgs::TransformStamped>& transforms(const ros::Time& stamp) override;
  const visualization_msgs::MarkerArray& markers(const ros::Time& stamp) override;

 private:
  riser_sim::Scene scene_;  // for ~modes
  Eigen::Vector3d top_;  // hang-off at the start [m]
  riser_sim::spatial::ExternalMotion3* motion_ = nullptr;  // owned by run_'s simulator
  std::shared_ptr<riser_sim::spatial::ExternalMotion3> bottom_motion_;  // shared with run_'s model
  std::unique_ptr<riser_sim::spatial::SpatialRun> run_;
  const riser_sim::spatial::LineOutputs3* out_ = nullptr;  // of the last evaluate()
  Eigen::Quaterniond vessel_ = Eigen::Quaterniond::Identity();  // orientation of the latest sample
  Eigen::Quaterniond rov_ = Eigen::Quaterniond::Identity();     // of the latest bottom sample
  bool pinned_;
  LineMessages3 msgs_;
  LineMarkers markers_;
  SeaMarkers3 sea_;  // its markers appended to markers_.msg
  riser_sim::spatial::Kinematics3 kin_;  // of the last evaluate()
};

}  // namespace riser_sim_ros
