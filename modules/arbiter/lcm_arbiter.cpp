#include "lcm_arbiter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "channels.hpp"
#include "log.hpp"

namespace beft::arbiter {

namespace {
constexpr int kQueueCapacity = 10000;   // LCM 1.3.1 keeps 30 per subscription by default
constexpr double kLongestWait_s = 0.1;  // so signals are noticed promptly
constexpr int kMostMessagesPerBatch = 1000;
}  // namespace

double SteadyClock::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void LcmArbiterOutput::sendFire(const beft::fire_t& fire) { lcm_.publish(channels::kFire, &fire); }

void LcmArbiterOutput::sendMarking(const beft::marking_t& marking) {
  lcm_.publish(channels::kMarking, &marking);
}

void LcmArbiterOutput::sendRunStatus(const beft::run_status_t& status) {
  lcm_.publish(channels::kRunStatus, &status);
}

void LcmArbiterOutput::firingEnded(const FiringRecord& record) {
  if (firing_log_) firing_log_->write(record);
}

std::vector<std::string> ArbiterEventQueue::channelsRead() {
  return {channels::kDone, channels::kHeartbeat, channels::kStopRequest};
}

ArbiterEventQueue::ArbiterEventQueue(lcm::LCM& lcm) : lcm_(lcm) {
  subscriptions_.push_back(lcm_.subscribe(channels::kDone, &ArbiterEventQueue::onDone, this));
  subscriptions_.push_back(lcm_.subscribe(channels::kHeartbeat, &ArbiterEventQueue::onHeartbeat, this));
  subscriptions_.push_back(
      lcm_.subscribe(channels::kStopRequest, &ArbiterEventQueue::onStopRequest, this));
  for (auto* subscription : subscriptions_) subscription->setQueueCapacity(kQueueCapacity);
}

ArbiterEventQueue::~ArbiterEventQueue() {
  for (auto* subscription : subscriptions_) lcm_.unsubscribe(subscription);
}

// Handlers: queue only, never let an exception reach LCM.
void ArbiterEventQueue::onDone(const lcm::ReceiveBuffer*, const std::string&, const beft::done_t* done) {
  try {
    events_.emplace_back(*done);
  } catch (const std::exception& e) {
    log::error("DONE dropped: ", e.what());
  }
}

void ArbiterEventQueue::onHeartbeat(const lcm::ReceiveBuffer*, const std::string&,
                                    const beft::heartbeat_t* heartbeat) {
  try {
    events_.emplace_back(*heartbeat);
  } catch (const std::exception& e) {
    log::error("HEARTBEAT dropped: ", e.what());
  }
}

void ArbiterEventQueue::onStopRequest(const lcm::ReceiveBuffer*, const std::string&,
                                      const beft::run_status_t* request) {
  try {
    events_.emplace_back(StopRequest{request->message.empty() ? "STOP_REQUEST" : request->message});
  } catch (const std::exception& e) {
    log::error("STOP_REQUEST dropped: ", e.what());
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

bool runArbiterLoop(lcm::LCM& lcm, ArbiterCore& core, const Clock& clock, const StopSignals* signals) {
  ArbiterEventQueue queue(lcm);
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
    int handled = lcm.handleTimeout(wait_ms);
    // Take whatever else is already there, so one step sees it all.
    for (int batch = 0; handled > 0 && batch < kMostMessagesPerBatch; ++batch)
      handled = lcm.handleTimeout(0);
    if (handled < 0) {
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
  }
  return true;
}

}  // namespace beft::arbiter
