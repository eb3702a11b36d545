#include "riser_sim_ros/line_topics.h"

#include <cmath>

#include <visualization_msgs/MarkerArray.h>

namespace riser_sim_ros {

const std::vector<TopicRate>& dataTopicRates() {
  static const std::vector<TopicRate> rates = {{"tension", 20.0}, {"state", 10.0},   {"wrench", 20.0, "tension"},
                                               {"tf", 20.0},      {"markers", 10.0}, {"range_graph", 0.0}};
  return rates;
}

LineTopics::LineTopics(ros::NodeHandle& pnh, const NodeParams& params, bool bottom_wrench) : params_(params) {
  auto tension = pnh.advertise<riser_sim::Tension>("tension", 5);
  add("tension", [tension](NodeRun& run, const ros::Time& t) { tension.publish(run.tension(t)); });
  auto state = pnh.advertise<riser_sim::LineState>("state", 5);
  add("state", [state](NodeRun& run, const ros::Time& t) { state.publish(run.state(t)); });
  auto wrench = pnh.advertise<geometry_msgs::WrenchStamped>("top_wrench", 5);
  ros::Publisher bottom;
  if (bottom_wrench) bottom = pnh.advertise<geometry_msgs::WrenchStamped>("bottom_wrench", 5);
  add("wrench", [wrench, bottom](NodeRun& run, const ros::Time& t) {
    wrench.publish(run.topWrench(t));
    if (!bottom) return;
    if (const geometry_msgs::WrenchStamped* b = run.bottomWrench(t)) bottom.publish(*b);
  });
  add("tf", [this](NodeRun& run, const ros::Time& t) { tf_pub_.sendTransform(run.transforms(t)); });
  auto markers = pnh.advertise<visualization_msgs::MarkerArray>("markers", 2);
  add("markers", [markers](NodeRun& run, const ros::Time& t) {
    if (markers.getNumSubscribers() == 0) return;  // large: built only for a listener
    markers.publish(run.markers(t));
  });
  if (params.rates.at("range_graph") > 0.0) {
    auto range = pnh.advertise<riser_sim::RangeEnvelope>("range_graph", 2);
    add("range_graph", [range](NodeRun& run, const ros::Time& t) {
      if (const riser_sim::RangeEnvelope* m = run.rangeEnvelope(t)) range.publish(*m);
    });
  }
}

void LineTopics::add(const std::string& name, Send send) {
  Topic topic;
  topic.name = name;
  topic.schedule.period = periodOf(params_.rates.at(name));
  topic.send = std::move(send);
  topics_.push_back(std::move(topic));
  const double p = topics_.back().schedule.period;
  if (p > 0.0 && (reference_ < 0 || p < topics_[reference_].schedule.period))
    reference_ = static_cast<int>(topics_.size()) - 1;
}

void LineTopics::start(const ros::Time& origin) {
  for (Topic& t : topics_) t.schedule.restart(origin);
}

bool LineTopics::due(const ros::Time& now) {
  bool any = false;
  for (Topic& t : topics_) any |= (t.due = t.schedule.due(now));
  return any;
}

bool LineTopics::publishDue(NodeRun& run, const ros::Time& stamp) {
  for (Topic& t : topics_)
    if (t.due) t.send(run, stamp);
  const bool reference = reference_ >= 0 && topics_[reference_].due;
  for (Topic& t : topics_) t.due = false;
  return reference;
}

double LineTopics::referencePeriod() const { return reference_ >= 0 ? topics_[reference_].schedule.period : NAN; }

}  // namespace riser_sim_ros
