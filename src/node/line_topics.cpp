#include "riser_sim_ros/line_topics.h"

#include <cmath>

#include <visualization_msgs/MarkerArray.h>

namespace riser_sim_ros {

const std::vector<TopicRate>& dataTopicRates() {
  static const std::vector<TopicRate> rates = {
      {"tension", 20.0}, {"state", 10.0}, {"wrench", 20.0, "tension"}, {"tf", 20.0}, {"markers", 10.0}};
  return rates;
}

LineTopics::LineTopics(ros::NodeHandle& pnh, const NodeParams& params) : params_(params) {
  auto tension = pnh.advertise<riser_sim::Tension>("tension", 5);
  add("tension", [this, tension](const riser_sim::LineOutputs& out, const ros::Time& t) {
    msgs_->fillTension(out, t);
    tension.publish(msgs_->tension);
  });
  auto state = pnh.advertise<riser_sim::LineState>("state", 5);
  add("state", [this, state](const riser_sim::LineOutputs& out, const ros::Time& t) {
    msgs_->fillState(out, t);
    state.publish(msgs_->state);
  });
  auto wrench = pnh.advertise<geometry_msgs::WrenchStamped>("top_wrench", 5);
  add("wrench", [this, wrench](const riser_sim::LineOutputs& out, const ros::Time& t) {
    msgs_->fillWrench(out, t);
    wrench.publish(msgs_->wrench);
  });
  add("tf", [this](const riser_sim::LineOutputs& out, const ros::Time& t) {
    msgs_->fillTransforms(out, t);
    tf_pub_.sendTransform(msgs_->transforms);
  });
  auto markers = pnh.advertise<visualization_msgs::MarkerArray>("markers", 2);
  add("markers", [this, markers](const riser_sim::LineOutputs& out, const ros::Time& t) {
    if (markers.getNumSubscribers() == 0) return;  // large: built only for a listener
    markers_->fill(out, t);
    markers.publish(markers_->msg);
  });
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

void LineTopics::start(const riser_sim::Model& model, const riser_sim::Scene& scene, const ros::Time& origin) {
  msgs_ = std::make_unique<LineMessages>(model, params_.fixed_frame, params_.tf_prefix);
  markers_ = std::make_unique<LineMarkers>(model, params_.fixed_frame, params_.markers, surfacesOf(scene));
  for (Topic& t : topics_) t.schedule.restart(origin);
}

bool LineTopics::due(const ros::Time& now) {
  bool any = false;
  for (Topic& t : topics_) any |= (t.due = t.schedule.due(now));
  return any;
}

bool LineTopics::publishDue(const riser_sim::LineOutputs& out, const ros::Time& stamp) {
  for (Topic& t : topics_)
    if (t.due) t.send(out, stamp);
  const bool reference = reference_ >= 0 && topics_[reference_].due;
  for (Topic& t : topics_) t.due = false;
  return reference;
}

double LineTopics::referencePeriod() const { return reference_ >= 0 ? topics_[reference_].schedule.period : NAN; }

}  // namespace riser_sim_ros
