#include "services/arbiter/lcm_arbiter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <sched.h>

#include "lib/common/clocks.hpp"
#include "lib/common/log.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::arbiter {

namespace {
constexpr int kQueueCapacity = 10000;   // LCM 1.3.1 keeps 30 per subscription by default
constexpr double kLongestWait_s = 0.1;  // so signals are noticed promptly
}  // namespace

double SteadyClock::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void LcmArbiterOutput::sendFire(const beft::fire_t& fire) { outlets_.fire.publish(lcm_, fire); }

FrontierMark LcmArbiterOutput::sendFrontier(const beft::frontier_t& frontier) {
  beft::frontier_t stamped = frontier;
  stamped.utime = std::chrono::duration_cast<std::chrono::microseconds>(
                      std::chrono::system_clock::now().time_since_epoch())
                      .count();
  outlets_.frontier.publish(lcm_, stamped);
  const std::string sent_on = wire::runChannel(channels::kFrontier.name);
  return {static_cast<int64_t>(transport::senderIdOf(lcm_)),
          static_cast<int64_t>(transport::lastPublished(lcm_, sent_on))};
}

void LcmArbiterOutput::sendMarking(const beft::marking_t& marking) { outlets_.marking.publish(lcm_, marking); }

void LcmArbiterOutput::sendRunStatus(const beft::run_status_t& status) {
  outlets_.run_status.publish(lcm_, status);
}

void LcmArbiterOutput::sendRunControlState(const beft::run_control_t& state) {
  beft::run_control_t stamped = state;
  stamped.utime = wallMicros();
  outlets_.control_state.publish(lcm_, stamped);
}

void LcmArbiterOutput::firingEnded(const FiringRecord& record) {
  if (firing_log_) firing_log_->write(record);
}

LcmArbiterOutput::LcmArbiterOutput(lcm::LCM& lcm, const ArbiterOutlets& outlets, FiringLog* firing_log)
    : lcm_(lcm), outlets_(outlets), firing_log_(firing_log) {}

ArbiterEventQueue::ArbiterEventQueue(lcm::LCM& lcm, const std::string& url, ArbiterInbox& inbox)
    : lcm_(lcm), inbox_(inbox) {
  source_ = transport::openReceiver(lcm, url, inbox_.selection(service::Delivery::kWakes), 16, kQueueCapacity);
}

ArbiterEventQueue::~ArbiterEventQueue() = default;

std::string ArbiterEventQueue::description() const { return source_->description(); }

bool ArbiterEventQueue::receive(int timeout_ms, int spin_us) {
  const transport::Handler handler = [this](const transport::Message& message) { inbox_.dispatch(message); };
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
