// What the arbiter reads, declared once as ports: DONE, HEARTBEAT,
// STOP_REQUEST and RUN_CONTROL queued as events for the core, and the beacons other runs
// send on the URL (BEFT_RUNS), where it announces its own run too.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <beft/done_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/run_beacon_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>

#include "lib/service/ports.hpp"
#include "services/arbiter/arbiter_core.hpp"
#include "services/arbiter/other_run_watch.hpp"

namespace beft::arbiter {

struct StopRequest {
  std::string why;
};
using ArbiterEvent = std::variant<beft::done_t, beft::heartbeat_t, StopRequest, beft::run_control_t>;

class ArbiterInbox : public service::PortSet {
 public:
  // Hands every queued event to the core, in arrival order.
  void deliverTo(ArbiterCore& core);
  bool empty() const { return events_.empty(); }
  // Sends this run's beacon on BEFT_RUNS when half a second has passed.
  void announce(lcm::LCM& lcm, int64_t tick);

 private:
  std::vector<ArbiterEvent> events_;
  OtherRunWatch other_runs_;
  std::chrono::steady_clock::time_point next_beacon_{};

  // Queue only; what the guard refuses is counted and dropped there.
  service::ReadPort<beft::done_t> done_in_{*this, channels::kDone, "an expert finished a firing",
                                           [this](beft::done_t&& done) { events_.emplace_back(std::move(done)); }};
  service::ReadPort<beft::heartbeat_t> heartbeat_in_{
      *this, channels::kHeartbeat, "liveness of the experts named in the net",
      [this](beft::heartbeat_t&& heartbeat) { events_.emplace_back(std::move(heartbeat)); }};
  service::ReadPort<beft::run_status_t> stop_in_{
      *this, channels::kStopRequest, "message = why; the run ends at the end of the tick",
      [this](beft::run_status_t&& request) {
        events_.emplace_back(StopRequest{request.message.empty() ? "STOP_REQUEST" : request.message});
      }};
  service::ReadPort<beft::run_control_t> control_in_{
      *this, channels::kRunControl, "pause, step or run on, from viewers and beft-control; applied between ticks",
      [this](beft::run_control_t&& request) { events_.emplace_back(std::move(request)); }};
  service::ReadPort<beft::run_beacon_t> beacons_in_{*this, channels::kRunBeacons,
                                                    "another run on this URL is said once",
                                                    [this](beft::run_beacon_t&& beacon) { onBeacon(beacon); },
                                                    service::Receiving().urlWide()};
  service::WritePort<beft::run_beacon_t> beacons_out_{*this, channels::kRunBeacons, "twice a second",
                                                      service::Reach::kUrlWide};

  void onBeacon(const beft::run_beacon_t& beacon);
};

}  // namespace beft::arbiter
