// ~modes: the modal analysis of a static state (riser_sim::computeModes) as a riser_sim/Modes response.
#pragma once
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "riser_sim/Modes.h"
#include "riser_sim/kinematics.h"
#include "riser_sim/scene.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim_ros {

// Modes of `scene` (top fixed at its hang-off) about the static state `kin` with `end_force` [N] kept as
// a dead load; for initial.type straight (not an equilibrium) about the hanging equilibrium instead.
// Builds its own model: the analysis sets up terms with run state (seabed anchors), so it must never
// share the running simulator's. count is checked (1..dofs); errors come back as success = false with
// the reason, e.g. "count: must be >= 1, got 0". Allocates; meant for a service thread.
void computeModesResponse(const riser_sim::Scene& scene, const riser_sim::Kinematics& kin,
                          const riser_sim::Vec2& end_force, int count, riser_sim::Modes::Response& res);

// The same for a 3D scene (space: spatial; modes_service3.cpp): spatial::computeSpatialModes about the
// equilibrium relaxed from initial.kin (spatialEquilibrium, as riser_sim_cli --modes), the statics' end force
// a dead load, flex joints as the run's; degenerate transverse pairs turned into the statics' plane and
// across it. Refuses line.torsion (no torsion in the 3D modes) and a moving bottom naming the key.
void computeModesResponse3(const riser_sim::Scene& scene, const riser_sim::spatial::InitialState3& initial, int count,
                           riser_sim::Modes::Response& res);

// The node's ~modes service on its own callback queue and thread (an eigen-solve never holds up the
// vessel input or ~reset). It works on a copy of the static state the integration loop hands over at
// each start, never on the running simulator.
class ModesServer {
 public:
  // `waiting_for`: what the node waits for before the first start (for the reply), e.g. the input topic.
  ModesServer(ros::NodeHandle pnh, std::string name, std::string frame, std::string waiting_for);
  ~ModesServer();
  // The scene with the top fixed at the hang-off and its static state (integration loop).
  void setState(const riser_sim::Scene& scene, const riser_sim::Kinematics& kin, const riser_sim::Vec2& end_force,
                const ros::Time& stamp);
  // A 3D scene (top fixed at the hang-off; a driven bottom held at its start) and its initial state.
  void setState3(const riser_sim::Scene& scene, const riser_sim::spatial::InitialState3& initial,
                 const ros::Time& stamp);
  // Why there is no static state (kept only until the first setState).
  void setFailure(const std::string& why);

 private:
  struct StaticState {
    riser_sim::Scene scene;
    riser_sim::Kinematics kin;
    riser_sim::Vec2 end_force = riser_sim::Vec2::Zero();
    std::shared_ptr<const riser_sim::spatial::InitialState3> initial3;  // set: a 3D scene
    ros::Time stamp;
  };
  bool onModes(riser_sim::Modes::Request& req, riser_sim::Modes::Response& res);

  std::string name_, frame_, waiting_for_;
  std::mutex mutex_;
  std::shared_ptr<const StaticState> state_;
  std::string failure_;
  ros::CallbackQueue queue_;
  ros::ServiceServer srv_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};

}  // namespace riser_sim_ros
