// riser_sim_node: see docs/ros_interface.md. Exit code 2: bad parameter or scene (the message names it).
#include <ros/ros.h>

#include <atomic>
#include <csignal>

#include "riser_sim_ros/master_watch.h"
#include "riser_sim_ros/riser_sim_node.h"

namespace {

// SIGINT/SIGTERM stop the loop; the node is then torn down and ros::shutdown() runs here, in the main thread
// (roscpp's own handler shuts down from its callback thread while the node's subscribers and publishers are
// being destroyed: an assertion in roscpp's TCP transport was seen to abort the node that way).
std::atomic<riser_sim_ros::RiserSimNode*> g_node{nullptr};
volatile std::sig_atomic_t g_stop = 0;

void onSignal(int) {
  g_stop = 1;
  if (riser_sim_ros::RiserSimNode* node = g_node.load()) node->stop();
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "riser_sim", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  int code = 0;
  {
    ros::NodeHandle nh, pnh("~");
    try {
      riser_sim_ros::RiserSimNode node(nh, pnh);
      g_node = &node;
      if (g_stop) node.stop();           // a signal during the start-up
      riser_sim_ros::MasterWatch watch;  // registers again with a restarted master (docs/ros_interface.md)
      node.spin();
      g_node = nullptr;
    } catch (const riser_sim_ros::ParamError& e) {
      g_node = nullptr;
      ROS_FATAL("riser_sim: %s", e.what());
      code = 2;
    } catch (const std::exception& e) {
      g_node = nullptr;
      ROS_FATAL("riser_sim: %s", e.what());
      code = 1;
    }
  }
  ros::shutdown();
  return code;
}
