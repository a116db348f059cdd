// An expert's heartbeat, sent from a thread of its own: a long firing (the
// task executor waiting for a plan, a large camera frame) does not look like
// a dead process, and an arbiter that asks (RUN_STATUS WAITING) hears one at
// once. Whether the expert is making progress is the firing timeout's job.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace lcm {
class LCM;
}

namespace beft::expert {

class HeartbeatThread {
 public:
  // Sends the first heartbeat at once, then one every `period_s`.
  HeartbeatThread(lcm::LCM& lcm, std::string process_name, double period_s);
  ~HeartbeatThread();  // stops the thread; no heartbeat after it returns
  HeartbeatThread(const HeartbeatThread&) = delete;
  HeartbeatThread& operator=(const HeartbeatThread&) = delete;

  // What the next heartbeats say: running a firing or idle, and the last firing run.
  void setState(bool firing, int64_t last_firing_id);
  // A firing that waits for its inputs (lost on the way, being repaired):
  // the heartbeat says "waiting", and the arbiter, which hears it, lets the
  // firing's timeout wait too (alive and waiting is not dead).
  void setWaiting(bool waiting) { waiting_ = waiting; }
  // One heartbeat now, besides the periodic ones.
  void sendNow();
  int64_t sent() const { return sent_.load(); }

 private:
  void loop();
  void send();

  lcm::LCM& lcm_;
  const std::string process_name_;
  const std::string host_;
  const std::chrono::microseconds period_;
  std::atomic<bool> firing_{false};
  std::atomic<bool> waiting_{false};
  std::atomic<int64_t> last_firing_id_{-1};
  std::atomic<int64_t> sent_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, send_now_ = false;
  std::thread thread_;
};

}  // namespace beft::expert
