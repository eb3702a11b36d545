#include "riser_sim_ros/reset_handshake.h"

namespace riser_sim_ros {

bool ResetHandshake::request(std::string& message, std::chrono::seconds timeout) {
  std::lock_guard<std::mutex> call(call_mutex_);  // one reset at a time
  std::unique_lock<std::mutex> lock(mutex_);
  requested_ = true;
  done_ = false;
  if (!cv_.wait_for(lock, timeout, [this] { return done_; })) {
    requested_ = false;
    message = "timed out waiting for the integration loop";
    return false;
  }
  message = message_;
  return ok_;
}

bool ResetHandshake::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!requested_) return false;
  requested_ = false;
  return true;
}

void ResetHandshake::answer(bool ok, const std::string& message) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
    ok_ = ok;
    message_ = message;
  }
  cv_.notify_all();
}

}  // namespace riser_sim_ros
