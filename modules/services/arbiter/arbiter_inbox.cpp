#include "services/arbiter/arbiter_inbox.hpp"

#include <unistd.h>

#include "lib/wire/run_identity.hpp"

namespace beft::arbiter {

void ArbiterInbox::deliverTo(ArbiterCore& core) {
  for (const auto& event : events_) {
    if (const auto* done = std::get_if<beft::done_t>(&event)) core.onDone(*done);
    else if (const auto* heartbeat = std::get_if<beft::heartbeat_t>(&event)) core.onHeartbeat(*heartbeat);
    else if (const auto* stop = std::get_if<StopRequest>(&event)) core.onStopRequest(stop->why);
    else if (const auto* control = std::get_if<beft::run_control_t>(&event)) core.onRunControl(*control);
  }
  events_.clear();
}

void ArbiterInbox::onBeacon(const beft::run_beacon_t& beacon) {
  if (beacon.run_id != wire::runId()) other_runs_.heard(beacon.run_id, beacon.host, beacon.pid);
}

void ArbiterInbox::announce(lcm::LCM& lcm, int64_t tick) {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_beacon_) return;
  next_beacon_ = now + std::chrono::milliseconds(500);
  beft::run_beacon_t beacon{};
  beacon.utime = std::chrono::duration_cast<std::chrono::microseconds>(
                     std::chrono::system_clock::now().time_since_epoch())
                     .count();
  beacon.run_id = wire::runId();
  char host[256] = {0};
  beacon.host = gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
  beacon.pid = static_cast<int32_t>(getpid());
  beacon.tick = tick;
  // Which launch this run is: the other hosts of a distributed run join it by that.
  const wire::RunOrigin origin = wire::runOrigin();
  beacon.description = origin.description;
  beacon.started_utime = origin.started_utime;
  beacons_out_.publish(lcm, beacon);
}

}  // namespace beft::arbiter
