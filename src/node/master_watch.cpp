#include "riser_sim_ros/master_watch.h"

#include <chrono>
#include <vector>

#include <ros/connection_manager.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <ros/service_manager.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace riser_sim_ros {

namespace {

using XmlRpc::XmlRpcValue;

// Calls this process's own slave API (the XML-RPC server roscpp runs); payload = third element.
bool callSelf(const std::string& method, XmlRpcValue& args, XmlRpcValue& payload) {
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(ros::XMLRPCManager::instance()->getServerURI(), host, port)) return false;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpcValue result;
  if (!client.execute(method.c_str(), args, result) || result.getType() != XmlRpcValue::TypeArray ||
      result.size() != 3 || static_cast<int>(result[0]) != 1)
    return false;
  payload = result[2];
  return true;
}

bool callMaster(const std::string& method, const XmlRpcValue& args, XmlRpcValue& payload) {
  XmlRpcValue result;
  return ros::master::execute(method, args, result, payload, false);
}

// [[name, type], ...] from getPublications / getSubscriptions of the own slave API.
std::vector<std::pair<std::string, std::string>> ownTopics(const char* method) {
  std::vector<std::pair<std::string, std::string>> out;
  XmlRpcValue args, payload;
  args[0] = ros::this_node::getName();
  if (!callSelf(method, args, payload) || payload.getType() != XmlRpcValue::TypeArray) return out;
  for (int i = 0; i < payload.size(); ++i)
    if (payload[i].getType() == XmlRpcValue::TypeArray && payload[i].size() == 2)
      out.emplace_back(static_cast<std::string>(payload[i][0]), static_cast<std::string>(payload[i][1]));
  return out;
}

}  // namespace

MasterWatch::MasterWatch(double period) : period_(period) {
  thread_ = std::thread([this] { run(); });
}

MasterWatch::~MasterWatch() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void MasterWatch::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    lock.unlock();
    if (ros::ok()) poll();
    lock.lock();
    cv_.wait_for(lock, std::chrono::duration<double>(period_), [this] { return stop_; });
  }
}

bool MasterWatch::masterKnowsUs() const {
  XmlRpcValue args, payload;
  args[0] = ros::this_node::getName();
  args[1] = ros::this_node::getName();
  return callMaster("lookupNode", args, payload);
}

void MasterWatch::poll() {
  if (!ros::master::check()) {
    if (!down_) {
      ROS_WARN(
          "riser_sim: ROS master %s unreachable: connections already made keep working; will register again "
          "when it is back",
          ros::master::getURI().c_str());
      down_ = true;
    }
    return;
  }
  if (masterKnowsUs()) {
    if (down_)
      ROS_INFO("riser_sim: ROS master %s reachable again, and it knows this node", ros::master::getURI().c_str());
    down_ = false;
    known_ = true;
    if (polls_++ % 5 == 0) rememberServices();
    return;
  }
  down_ = false;
  if (!known_) return;  // not registered yet (start-up): roscpp does that itself
  reregister();
}

void MasterWatch::rememberServices() {
  XmlRpcValue args, payload;
  args[0] = ros::this_node::getName();
  if (!callMaster("getSystemState", args, payload) || payload.getType() != XmlRpcValue::TypeArray ||
      payload.size() != 3)
    return;
  XmlRpcValue& services = payload[2];
  std::set<std::string> mine;
  for (int i = 0; i < services.size(); ++i) {
    XmlRpcValue& providers = services[i][1];
    for (int j = 0; j < providers.size(); ++j)
      if (static_cast<std::string>(providers[j]) == ros::this_node::getName())
        mine.insert(static_cast<std::string>(services[i][0]));
  }
  services_ = std::move(mine);
}

void MasterWatch::reregister() {
  const std::string me = ros::this_node::getName();
  const std::string api = ros::XMLRPCManager::instance()->getServerURI();
  int pubs = 0, subs = 0, srvs = 0, failed = 0;
  for (const auto& [topic, type] : ownTopics("getPublications")) {
    XmlRpcValue args, payload;
    args[0] = me, args[1] = topic, args[2] = type, args[3] = api;
    callMaster("registerPublisher", args, payload) ? ++pubs : ++failed;
  }
  for (const auto& [topic, type] : ownTopics("getSubscriptions")) {
    XmlRpcValue args, payload;
    args[0] = me, args[1] = topic, args[2] = type, args[3] = api;
    if (!callMaster("registerSubscriber", args, payload)) {
      ++failed;
      continue;
    }
    ++subs;
    // The publishers the master knows already: connect to them as roscpp does after subscribe().
    XmlRpcValue update, ignored;
    update[0] = std::string("/master");
    update[1] = topic;
    update[2] = payload;
    if (payload.getType() == XmlRpcValue::TypeArray && payload.size() > 0) callSelf("publisherUpdate", update, ignored);
  }
  const std::string service_api =
      "rosrpc://" + ros::network::getHost() + ":" + std::to_string(ros::ConnectionManager::instance()->getTCPPort());
  for (const std::string& name : services_) {
    if (!ros::ServiceManager::instance()->lookupServicePublication(name)) continue;  // shut down since
    XmlRpcValue args, payload;
    args[0] = me, args[1] = name, args[2] = service_api, args[3] = api;
    callMaster("registerService", args, payload) ? ++srvs : ++failed;
  }
  ++reregistrations_;
  const std::string failures = failed ? ", " + std::to_string(failed) + " failed" : "";
  ROS_WARN(
      "riser_sim: the ROS master %s was restarted (it did not know this node): registered again %d "
      "publications, %d subscriptions, %d services%s; parameters set before the restart are gone from the "
      "parameter server (this node keeps the values it read at start-up)",
      ros::master::getURI().c_str(), pubs, subs, srvs, failures.c_str());
}

std::shared_ptr<MasterWatch> sharedMasterWatch() {
  static std::mutex mutex;
  static std::weak_ptr<MasterWatch> shared;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<MasterWatch> watch = shared.lock();
  if (!watch) {
    watch = std::make_shared<MasterWatch>();
    shared = watch;
  }
  return watch;
}

}  // namespace riser_sim_ros
