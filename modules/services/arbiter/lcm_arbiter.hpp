// The arbiter on LCM. The LCM handlers only queue events; the loop, which
// owns the core and its marking, drains the queue and lets time advance.
// It never sleeps: it waits for a message until the core's next deadline (a
// re-send, a timeout) is due.
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "services/arbiter/arbiter_core.hpp"
#include "services/arbiter/firing_log.hpp"
#include "services/arbiter/other_run_watch.hpp"
#include "lib/service/service.hpp"
#include "lib/transport/transport.hpp"

namespace beft::arbiter {

class SteadyClock : public Clock {
 public:
  double now() const override;
};

// Publishes the core's messages on their channels and writes the firing log.
class LcmArbiterOutput : public ArbiterOutput {
 public:
  LcmArbiterOutput(lcm::LCM& lcm, FiringLog* firing_log);
  void sendFire(const beft::fire_t& fire) override;
  void sendMarking(const beft::marking_t& marking) override;
  void sendRunStatus(const beft::run_status_t& status) override;
  void firingEnded(const FiringRecord& record) override;

 private:
  lcm::LCM& lcm_;
  FiringLog* firing_log_;
  std::string fire_channel_, marking_channel_, run_status_channel_;  // on this run (run_identity.hpp)
};

struct StopRequest {
  std::string why;
};
using ArbiterEvent = std::variant<beft::done_t, beft::heartbeat_t, StopRequest>;

// Receives DONE, HEARTBEAT and STOP_REQUEST (transport.hpp: on udpm a
// socket of its own, read in the loop's thread) and queues what arrives.
class ArbiterEventQueue {
 public:
  // Throws std::runtime_error if it cannot receive on `url`.
  ArbiterEventQueue(lcm::LCM& lcm, const std::string& url);
  ~ArbiterEventQueue();
  ArbiterEventQueue(const ArbiterEventQueue&) = delete;
  ArbiterEventQueue& operator=(const ArbiterEventQueue&) = delete;

  // The channels it receives: DONE, HEARTBEAT, STOP_REQUEST.
  static std::vector<std::string> channelsRead();

  // Sends this run's beacon on BEFT_RUNS when half a second has passed.
  void announce(int64_t tick);

  // Waits up to `timeout_ms` for messages and queues every one there; polls
  // for the first `spin_us` microseconds of it instead of sleeping. Returns
  // false if receiving failed.
  bool receive(int timeout_ms, int spin_us = 0);
  // Hands every queued event to the core, in arrival order.
  void deliverTo(ArbiterCore& core);
  bool empty() const { return events_.empty(); }
  std::string description() const;

 private:
  void onMessage(const transport::Message& message);


  lcm::LCM& lcm_;
  std::unique_ptr<transport::Receiver> source_;
  std::vector<ArbiterEvent> events_;
  OtherRunWatch other_runs_;
  std::chrono::steady_clock::time_point next_beacon_{};
};

// Set by signal handlers, read by the loop.
// SIGINT: the first ends the run after the tick, a second aborts; SIGTERM: end now.
using StopSignals = service::StopSignals;

// Runs the core until it is done (final status sent). While exactly one
// firing is in flight, each wait polls for up to `spin_us` microseconds
// before it sleeps; with more, the firing experts have the cores.
// Returns false if LCM stopped working (the run is then FAILED).
bool runArbiterLoop(ArbiterEventQueue& queue, ArbiterCore& core, const Clock& clock,
                    const StopSignals* signals = nullptr, int spin_us = 0);

}  // namespace beft::arbiter
