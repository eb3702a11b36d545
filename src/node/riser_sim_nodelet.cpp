// riser_sim/RiserSimNodelet: RiserSimNode inside a nodelet manager (docs/ros_interface.md, "Nodelets").
// Same parameters, topics and services as riser_sim_node; its name is the nodelet's name. The
// manager's worker threads serve its callbacks (multi-threaded queues); the integration loop runs on
// a thread of its own, stopped and joined on unload. Vessel poses published as shared pointers by a
// nodelet in the same manager arrive without serialisation or copy.
#include <memory>
#include <thread>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "riser_sim_ros/master_watch.h"
#include "riser_sim_ros/riser_sim_node.h"

namespace riser_sim_ros {

class RiserSimNodelet : public nodelet::Nodelet {
 public:
  ~RiserSimNodelet() override {
    if (node_) node_->stop();
    if (loop_.joinable()) loop_.join();
  }

 private:
  void onInit() override {
    try {
      node_ = std::make_unique<RiserSimNode>(getMTNodeHandle(), getMTPrivateNodeHandle());
    } catch (const std::exception& e) {
      NODELET_FATAL("%s: %s", getName().c_str(), e.what());
      throw;  // the manager reports the load as failed (the `nodelet load` process exits)
    }
    watch_ = sharedMasterWatch();  // one per manager process (master restarts)
    loop_ = std::thread([this] { node_->run(); });
  }

  std::unique_ptr<RiserSimNode> node_;
  std::shared_ptr<MasterWatch> watch_;
  std::thread loop_;
};

}  // namespace riser_sim_ros

PLUGINLIB_EXPORT_CLASS(riser_sim_ros::RiserSimNodelet, nodelet::Nodelet)
