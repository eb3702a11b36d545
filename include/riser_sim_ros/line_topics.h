// The node's data outputs as one table: each entry is a topic (or the tf frames) with its publishing
// rate (~rates/<name>, in ROS time) and the function that sends the NodeRun's message. Adding a topic: a
// line in dataTopicRates() and one in LineTopics' constructor (line_topics.cpp), its message filled from
// riser_sim::RunOutputs by LineMessages (line_messages.h) and handed out by NodeRun (node_run.h).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "riser_sim_ros/node_run.h"
#include "riser_sim_ros/node_params.h"
#include "riser_sim_ros/ros_clock.h"

namespace riser_sim_ros {

struct TopicRate {
  const char* name;                  // ~rates/<name>
  double hz;                         // default [Hz], 0 = off
  const char* default_as = nullptr;  // set: the default is that topic's rate when it is > 0
};
// The data topics' rate parameters (~rates/<name>); ~rates/diagnostics is the diagnostics'.
const std::vector<TopicRate>& dataTopicRates();

class LineTopics {
 public:
  // Advertises the topics in pnh's namespace; rates from params.rates. bottom_wrench: ~bottom_wrench too
  // (a 3D scene with a pinned bottom), at the rate of ~top_wrench.
  LineTopics(ros::NodeHandle& pnh, const NodeParams& params, bool bottom_wrench = false);
  // A new run: every schedule restarted at origin.
  void start(const ros::Time& origin);
  // Marks the topics due at `now`; true when any is.
  bool due(const ros::Time& now);
  // Sends the marked topics: the run's messages of its last evaluate(), stamped `stamp`. True when the
  // fastest topic (the one that defines "one publish period") was among them.
  bool publishDue(NodeRun& run, const ros::Time& stamp);
  double referencePeriod() const;  // period of the fastest topic [s]; NaN when all are off

 private:
  using Send = std::function<void(NodeRun&, const ros::Time&)>;
  struct Topic {
    std::string name;
    Schedule schedule;
    Send send;
    bool due = false;
  };
  void add(const std::string& name, Send send);

  const NodeParams& params_;
  std::vector<Topic> topics_;
  int reference_ = -1;
  tf2_ros::TransformBroadcaster tf_pub_;
};

}  // namespace riser_sim_ros
