// ~reset's handshake: the service thread asks and waits; the integration loop, which owns the
// simulation, takes the request at its next cycle and answers.
#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>

namespace riser_sim_ros {

class ResetHandshake {
 public:
  // Service thread: asks and waits up to `timeout` for the answer; false + message when refused or late.
  bool request(std::string& message, std::chrono::seconds timeout = std::chrono::seconds(30));
  // Integration loop: true once per request; answer() must follow.
  bool take();
  // Integration loop: the answer to the request taken (or to any waiting caller, e.g. at shutdown).
  void answer(bool ok, const std::string& message);

 private:
  std::mutex call_mutex_, mutex_;
  std::condition_variable cv_;
  bool requested_ = false, done_ = false, ok_ = false;
  std::string message_;
};

}  // namespace riser_sim_ros
