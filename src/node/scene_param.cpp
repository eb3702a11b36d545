#include "riser_sim_ros/scene_param.h"

#include <stdexcept>

#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/xmlrpc_yaml.h"

namespace riser_sim_ros {

riser_sim::Scene loadScene(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue tree;
  if (!pnh.getParam("scene", tree))
    throw ParamError("scene",
                     "missing: load a scene file into the node's private namespace, e.g. <rosparam "
                     "command=\"load\" file=\"$(find riser_sim)/config/scenes/demo_riser.yaml\" ns=\"scene\"/> "
                     "inside the <node> tag");
  YAML::Node yaml;
  try {
    yaml = toYaml(tree);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    throw ParamError(paramPath("scene", what.substr(0, colon)), what.substr(colon + 2));
  }
  try {
    return riser_sim::parseScene(yaml);
  } catch (const riser_sim::SceneError& e) {
    std::string what = e.what();
    if (!e.key().empty() && what.rfind(e.key() + ": ", 0) == 0) what = what.substr(e.key().size() + 2);
    throw ParamError(paramPath("scene", e.key()), what);
  }
}

}  // namespace riser_sim_ros
