// ~scene: the scene as a parameter tree (a scene file loaded with <rosparam ns="scene">).
#pragma once
#include <ros/node_handle.h>

#include "riser_sim/scene/scene.h"

namespace riser_sim_ros {

// Loads ~scene (XmlRpc tree -> YAML -> riser_sim::parseScene). Throws ParamError naming the key,
// e.g. "~scene/line/elements: must be >= 1, got 0".
riser_sim::Scene loadScene(const ros::NodeHandle& pnh);

}  // namespace riser_sim_ros
