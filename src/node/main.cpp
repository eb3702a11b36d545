// riser_sim_node: see docs/ros_interface.md. Exit code 2: bad parameter or scene (the message names it).
#include <ros/ros.h>

#include "riser_sim_ros/master_watch.h"
#include "riser_sim_ros/riser_sim_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "riser_sim");
  ros::NodeHandle nh, pnh("~");
  try {
    riser_sim_ros::RiserSimNode node(nh, pnh);
    riser_sim_ros::MasterWatch watch;  // registers again with a restarted master (docs/ros_interface.md)
    node.spin();
  } catch (const riser_sim_ros::ParamError& e) {
    ROS_FATAL("riser_sim: %s", e.what());
    return 2;
  } catch (const std::exception& e) {
    ROS_FATAL("riser_sim: %s", e.what());
    return 1;
  }
  return 0;
}
