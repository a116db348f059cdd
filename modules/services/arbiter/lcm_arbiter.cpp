#include "services/arbiter/lcm_arbiter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <sched.h>
#include <unistd.h>

#include "lib/common/channels.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::arbiter {

namespace {
constexpr int kQueueCapacity = 10000;   // LCM 1.3.1 keeps 30 per subscription by default
constexpr double kLongestWait_s = 0.1;  // so signals are noticed promptly
}  // namespace

double SteadyClock::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void LcmArbiterOutput::sendFire(const beft::fire_t& fire) { lcm_.publish(fire_channel_, &fire); }

void LcmArbiterOutput::sendMarking(const beft::marking_t& marking) {
  lcm_.publish(marking_channel_, &marking);
}

void LcmArbiterOutput::sendRunStatus(const beft::run_status_t& status) {
  lcm_.publish(run_status_channel_, &status);
}

void LcmArbiterOutput::firingEnded(const FiringRecord& record) {
  if (firing_log_) firing_log_->write(record);
}

std::vector<std::string> ArbiterEventQueue::channelsRead() {
  return {channels::kDone, channels::kHeartbeat, channels::kStopRequest, channels::kRunBeacons};
}

void ArbiterEventQueue::announce(int64_t tick) {
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
  lcm_.publish(channels::kRunBeacons, &beacon);
}

LcmArbiterOutput::LcmArbiterOutput(lcm::LCM& lcm, FiringLog* firing_log)
    : lcm_(lcm),
      firing_log_(firing_log),
      fire_channel_(wire::runChannel(channels::kFire)),
      marking_channel_(wire::runChannel(channels::kMarking)),
      run_status_channel_(wire::runChannel(channels::kRunStatus)) {}

ArbiterEventQueue::ArbiterEventQueue(lcm::LCM& lcm, const std::string& url) : lcm_(lcm) {
  transport::Selection spec;
  for (const auto& channel : channelsRead()) spec.rules.push_back(transport::channelRule(channel));
  source_ = transport::openReceiver(lcm, url, spec, 16, kQueueCapacity);
}

ArbiterEventQueue::~ArbiterEventQueue() = default;

std::string ArbiterEventQueue::description() const { return source_->description(); }

bool ArbiterEventQueue::receive(int timeout_ms, int spin_us) {
  const transport::Handler handler = [this](const transport::Message& message) { onMessage(message); };
  if (spin_us > 0 && timeout_ms > 0) {
    // Poll before sleeping: a short firing's DONE is then taken as it comes,
    // without this process going to sleep and being woken again (on a
    // virtual machine, waking a halted CPU takes tens of microseconds, and a
    // tick waits for one DONE after another). Yielding meanwhile, so a
    // process with work on this CPU runs first. The poll counts against the
    // time-out.
    using SteadyTime = std::chrono::steady_clock;
    const auto start = SteadyTime::now();
    const auto give_up = start + std::chrono::microseconds(std::min<int64_t>(spin_us, int64_t{timeout_ms} * 1000));
    while (!transport::waitReadable({source_->fd()}, 0)) {
      if (SteadyTime::now() >= give_up) {
        const auto spun_ms = std::chrono::duration_cast<std::chrono::milliseconds>(SteadyTime::now() - start).count();
        timeout_ms = std::max<int>(0, timeout_ms - static_cast<int>(spun_ms));
        break;
      }
      sched_yield();
    }
  }
  return source_->receive(timeout_ms, handler) >= 0;
}

// Queue only; what the guard refuses is counted and dropped there.
void ArbiterEventQueue::onMessage(const transport::Message& message) {
  const std::string channel(message.channel);
  if (channel == channels::kDone) {
    beft::done_t done{};
    if (wire::decodeFrom(channel, message.data, message.size, done)) events_.emplace_back(std::move(done));
  } else if (channel == channels::kHeartbeat) {
    beft::heartbeat_t heartbeat{};
    if (wire::decodeFrom(channel, message.data, message.size, heartbeat)) events_.emplace_back(std::move(heartbeat));
  } else if (channel == channels::kStopRequest) {
    beft::run_status_t request{};
    if (wire::decodeFrom(channel, message.data, message.size, request))
      events_.emplace_back(StopRequest{request.message.empty() ? "STOP_REQUEST" : request.message});
  } else if (channel == channels::kRunBeacons) {
    beft::run_beacon_t beacon{};
    if (wire::decodeFrom(channel, message.data, message.size, beacon) && beacon.run_id != wire::runId())
      other_runs_.heard(beacon.run_id, beacon.host, beacon.pid);
  }
}

void ArbiterEventQueue::deliverTo(ArbiterCore& core) {
  for (const auto& event : events_) {
    if (const auto* done = std::get_if<beft::done_t>(&event)) core.onDone(*done);
    else if (const auto* heartbeat = std::get_if<beft::heartbeat_t>(&event)) core.onHeartbeat(*heartbeat);
    else if (const auto* stop = std::get_if<StopRequest>(&event)) core.onStopRequest(stop->why);
  }
  events_.clear();
}

bool runArbiterLoop(ArbiterEventQueue& queue, ArbiterCore& core, const Clock& clock, const StopSignals* signals,
                    int spin_us) {
  int interrupts_seen = 0;
  core.start();
  while (!core.done()) {
    if (signals) {
      const int count = signals->interrupts.load();
      if (count >= 1 && interrupts_seen < 1) core.onStopRequest("interrupted (SIGINT)");
      if (count >= 2 && interrupts_seen < 2) core.onAbort("interrupted twice (SIGINT)");
      interrupts_seen = count;
      if (signals->terminated.load()) core.onAbort("terminated (SIGTERM)");
    }
    const double wait_s = std::clamp(core.nextDeadline() - clock.now(), 0.0, kLongestWait_s);
    const int wait_ms = static_cast<int>(std::ceil(wait_s * 1e3));
    // Everything already there is taken at once, so one step sees it all.
    if (!queue.receive(wait_ms, core.firingsInFlight() == 1 ? spin_us : 0)) {
      queue.deliverTo(core);
      core.onAbort("LCM receive failed");
      while (!core.done()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        core.onTimeAdvanced();
      }
      return false;
    }
    queue.deliverTo(core);
    core.onTimeAdvanced();
    queue.announce(core.tick());
  }
  return true;
}

}  // namespace beft::arbiter
