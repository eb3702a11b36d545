// ~modes: the natural modes of the node's static state (riser_sim::sceneModesReport, either engine) as a
// riser_sim/Modes response.
#pragma once
#include <memory>
#include <mutex>
#include <string>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "riser_sim/Modes.h"
#include "riser_sim/scene/scene.h"

namespace riser_sim_ros {

// The modes of `scene` as riser_sim_cli --modes computes them (its statics with the top where scene.top has
// it at t = 0, their end force a dead load): periods and frequencies (0 for a mode that does not
// oscillate), characters, axial shares, the points and the shapes in fixed_frame (planar: world y = 0).
// Builds its own model: never shares the running simulator's. count is checked (1..dofs); errors come
// back as success = false with the reason, e.g. "count: must be >= 1, got 0". Allocates; meant for a
// service thread.
void computeModesResponse(const riser_sim::Scene& scene, int count, riser_sim::Modes::Response& res);

// The node's ~modes service on its own callback queue and thread (an eigen-solve never holds up the
// vessel input or ~reset). It works on a copy of the scene the integration loop hands over at each
// start, never on the running simulator.
class ModesServer {
 public:
  // `waiting_for`: what the node waits for before the first start (for the reply), e.g. the input topic.
  ModesServer(ros::NodeHandle pnh, std::string name, std::string frame, std::string waiting_for);
  ~ModesServer();
  // The running scene with its top fixed at the hang-off (and a driven bottom where it started), from the
  // integration loop at each start: ~modes solves its statics as riser_sim_cli --modes does.
  void setState(const riser_sim::Scene& scene, const ros::Time& stamp);
  // Why there is no static state (kept only until the first setState).
  void setFailure(const std::string& why);

 private:
  struct StaticState {
    riser_sim::Scene scene;
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
