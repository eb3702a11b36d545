// Re-registration with a restarted ROS master (one per process).
//
// roscpp (1.15) tells the master about a publisher, subscriber or service once, when it is created.
// After a master restart the node keeps talking to the peers it is already connected to, but the new
// master does not know it: no new subscriber finds its topics, it finds no new publisher, its services
// cannot be looked up (measured: scripts/test_master_restart.py). MasterWatch polls the master on its own
// thread; when the master answers but no longer knows this node, it registers again every publication and
// subscription that the node's own slave API lists (getPublications, getSubscriptions), hands each
// subscription the master's publishers (publisherUpdate on its own slave API), and registers again the
// services the old master listed for this node (remembered from getSystemState). Parameters are not
// restored: the parameter server of the new master is empty.
#pragma once
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace riser_sim_ros {

class MasterWatch {
 public:
  // Starts the polling thread; period [s] of wall time between checks.
  explicit MasterWatch(double period = 1.0);
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;
  long reregistrations() const { return reregistrations_; }

 private:
  void run();
  void poll();
  bool masterKnowsUs() const;
  void rememberServices();
  void reregister();

  double period_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;
  bool known_ = false;  // the master has known this node since the last (re-)registration
  bool down_ = false;
  int polls_ = 0;
  std::set<std::string> services_;
  std::atomic<long> reregistrations_{0};
  std::thread thread_;  // last: started once every other member exists
};

// The process's one MasterWatch for code that cannot own it (nodelets in a manager): the first caller
// creates it; it stops when the last holder lets go (the last riser nodelet unloaded).
std::shared_ptr<MasterWatch> sharedMasterWatch();

}  // namespace riser_sim_ros
