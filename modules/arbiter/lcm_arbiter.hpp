// The arbiter on LCM. The LCM handlers only queue events; the loop, which
// owns the core and its marking, drains the queue and lets time advance.
// It never sleeps: it waits in lcm.handleTimeout until a message arrives or
// the core's next deadline (a re-send, a timeout) is due.
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <string>
#include <variant>
#include <vector>

#include "arbiter_core.hpp"
#include "firing_log.hpp"

namespace beft::arbiter {

class SteadyClock : public Clock {
 public:
  double now() const override;
};

// Publishes the core's messages on their channels and writes the firing log.
class LcmArbiterOutput : public ArbiterOutput {
 public:
  LcmArbiterOutput(lcm::LCM& lcm, FiringLog* firing_log) : lcm_(lcm), firing_log_(firing_log) {}
  void sendFire(const beft::fire_t& fire) override;
  void sendMarking(const beft::marking_t& marking) override;
  void sendRunStatus(const beft::run_status_t& status) override;
  void firingEnded(const FiringRecord& record) override;

 private:
  lcm::LCM& lcm_;
  FiringLog* firing_log_;
};

struct StopRequest {
  std::string why;
};
using ArbiterEvent = std::variant<beft::done_t, beft::heartbeat_t, StopRequest>;

// Subscribes to DONE, HEARTBEAT and STOP_REQUEST and queues what arrives.
class ArbiterEventQueue {
 public:
  explicit ArbiterEventQueue(lcm::LCM& lcm);
  ~ArbiterEventQueue();
  ArbiterEventQueue(const ArbiterEventQueue&) = delete;
  ArbiterEventQueue& operator=(const ArbiterEventQueue&) = delete;

  // The channels it subscribes to: DONE, HEARTBEAT, STOP_REQUEST.
  static std::vector<std::string> channelsRead();

  // Hands every queued event to the core, in arrival order.
  void deliverTo(ArbiterCore& core);
  bool empty() const { return events_.empty(); }

 private:
  void onDone(const lcm::ReceiveBuffer*, const std::string&, const beft::done_t* done);
  void onHeartbeat(const lcm::ReceiveBuffer*, const std::string&, const beft::heartbeat_t* heartbeat);
  void onStopRequest(const lcm::ReceiveBuffer*, const std::string&, const beft::run_status_t* request);

  lcm::LCM& lcm_;
  std::vector<lcm::Subscription*> subscriptions_;
  std::vector<ArbiterEvent> events_;
};

// Set by signal handlers, read by the loop.
struct StopSignals {
  std::atomic<int> interrupts{0};      // SIGINT: first ends the run after the tick, second aborts
  std::atomic<bool> terminated{false}; // SIGTERM: end now
};

// Runs the core until it is done (final status sent). Returns false if LCM
// stopped working (the run is then FAILED).
bool runArbiterLoop(lcm::LCM& lcm, ArbiterCore& core, const Clock& clock,
                    const StopSignals* signals = nullptr);

}  // namespace beft::arbiter
