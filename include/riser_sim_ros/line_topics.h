// The node's data outputs as one table: each entry is a topic (or the tf frames) with its publishing
// rate (~rates/<name>, in ROS time) and the function that fills and sends it. Adding a topic: a line
// in dataTopicRates() and one in LineTopics' constructor (line_topics.cpp), and its message filler
// (line_messages.h/.cpp).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "riser_sim/model.h"
#include "riser_sim/outputs.h"
#include "riser_sim/scene.h"
#include "riser_sim_ros/line_markers.h"
#include "riser_sim_ros/line_messages.h"
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
  // Advertises the topics in pnh's namespace; rates from params.rates.
  LineTopics(ros::NodeHandle& pnh, const NodeParams& params);
  // A new run: messages sized for its model, every schedule restarted at origin.
  void start(const riser_sim::Model& model, const riser_sim::Scene& scene, const ros::Time& origin);
  // Marks the topics due at `now`; true when any is.
  bool due(const ros::Time& now);
  // Sends the marked topics, filled from `out`, stamped `stamp`. True when the fastest topic (the one
  // that defines "one publish period") was among them.
  bool publishDue(const riser_sim::LineOutputs& out, const ros::Time& stamp);
  double referencePeriod() const;  // period of the fastest topic [s]; NaN when all are off

 private:
  using Send = std::function<void(const riser_sim::LineOutputs&, const ros::Time&)>;
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
  std::unique_ptr<LineMessages> msgs_;
  std::unique_ptr<LineMarkers> markers_;
};

}  // namespace riser_sim_ros
