// The arbiter on LCM. The LCM handlers only queue events; the loop, which
// owns the core and its marking, drains the queue and lets time advance.
// It never sleeps: it waits for a message until the core's next deadline (a
// re-send, a timeout) is due.
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <memory>
#include <string>

#include <beft/fire_t.hpp>
#include <beft/marking_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>

#include "services/arbiter/arbiter_core.hpp"
#include "services/arbiter/arbiter_inbox.hpp"
#include "services/arbiter/firing_log.hpp"
#include "lib/service/service.hpp"
#include "lib/transport/transport.hpp"

namespace beft::arbiter {

class SteadyClock : public Clock {
 public:
  double now() const override;
};

// What the arbiter writes, declared once as ports.
struct ArbiterOutlets : service::PortSet {
  service::WritePort<beft::fire_t> fire{*this, channels::kFire, "re-sent until DONE"};
  service::WritePort<beft::marking_t> marking{*this, channels::kMarking, "after every step"};
  service::WritePort<beft::run_status_t> run_status{*this, channels::kRunStatus,
                                                    "at start, every tick, and at the end"};
  service::WritePort<beft::frontier_t> frontier{*this, channels::kFrontier,
                                                "before a firing, when DONEs told of new messages"};
  service::WritePort<beft::run_control_t> control_state{
      *this, channels::kRunControlState, "held or running, the tick, the request last applied: on a change and every 0.2 s"};
};

// Publishes the core's messages on their ports and writes the firing log.
class LcmArbiterOutput : public ArbiterOutput {
 public:
  LcmArbiterOutput(lcm::LCM& lcm, const ArbiterOutlets& outlets, FiringLog* firing_log);
  void sendFire(const beft::fire_t& fire) override;
  FrontierMark sendFrontier(const beft::frontier_t& frontier) override;
  void sendMarking(const beft::marking_t& marking) override;
  void sendRunStatus(const beft::run_status_t& status) override;
  void sendRunControlState(const beft::run_control_t& state) override;
  void firingEnded(const FiringRecord& record) override;

 private:
  lcm::LCM& lcm_;
  const ArbiterOutlets& outlets_;
  FiringLog* firing_log_;
};

// Receives what the inbox's ports take (transport.hpp: on udpm a socket of
// its own, read in the loop's thread) and queues it there.
class ArbiterEventQueue {
 public:
  // Throws std::runtime_error if it cannot receive on `url`.
  ArbiterEventQueue(lcm::LCM& lcm, const std::string& url, ArbiterInbox& inbox);
  ~ArbiterEventQueue();
  ArbiterEventQueue(const ArbiterEventQueue&) = delete;
  ArbiterEventQueue& operator=(const ArbiterEventQueue&) = delete;

  // Sends this run's beacon on BEFT_RUNS when half a second has passed.
  void announce(int64_t tick) { inbox_.announce(lcm_, tick); }

  // Waits up to `timeout_ms` for messages and queues every one there; polls
  // for the first `spin_us` microseconds of it instead of sleeping. Returns
  // false if receiving failed.
  bool receive(int timeout_ms, int spin_us = 0);
  // Hands every queued event to the core, in arrival order.
  void deliverTo(ArbiterCore& core) { inbox_.deliverTo(core); }
  bool empty() const { return inbox_.empty(); }
  std::string description() const;

 private:
  lcm::LCM& lcm_;
  ArbiterInbox& inbox_;
  std::unique_ptr<transport::Receiver> source_;
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
