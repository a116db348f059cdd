#include "live_runner.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <map>
#include <optional>
#include <set>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "channels.hpp"
#include "heartbeat_thread.hpp"
#include "log.hpp"
#include "udpm_filter.hpp"

namespace beft::expert {

namespace {

std::atomic<bool> g_stop_requested{false};
void onSignal(int) { g_stop_requested = true; }

using Clock = std::chrono::steady_clock;

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

class LcmOutput : public Output {
 public:
  explicit LcmOutput(lcm::LCM& lcm) : lcm_(lcm) {}
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    if (lcm_.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size())) != 0)
      log::warn("could not publish on ", channel, " (", bytes.size(), " bytes)");
  }

 private:
  lcm::LCM& lcm_;
};

// Holds what the LCM handlers received; the main loop decides what to do.
class Runner {
 public:
  Runner(Expert& expert, const LiveOptions& options, lcm::LCM& lcm)
      : expert_(expert), options_(options), lcm_(lcm), output_(lcm) {}

  int run() {
    for (const auto& spec : expert_.reads()) {
      auto* sub = lcm_.subscribe(spec.channel, &Runner::onInput, this);
      sub->setQueueCapacity(1000);  // LCM 1.3.1 keeps 30 by default and drops the rest
      read_channels_.insert(spec.channel);
    }
    lcm_.subscribe(channels::kFire, &Runner::onFire, this)->setQueueCapacity(1000);
    lcm_.subscribe(channels::kRunStatus, &Runner::onRunStatus, this);
    if (options_.catch_up) subscribeToSnapshot();
    installChannelFilter();
    if (options_.catch_up) requestSnapshot();

    log::info("ready: waiting for FIRE on ", options_.lcm_url);
    heartbeat_.emplace(lcm_, options_.process_name, options_.heartbeat_period_s);
    while (!g_stop_requested && !run_ended_) {
      // Short waits while a firing waits for its inputs; else 100 ms, so a signal is seen.
      const int timeout_ms = pending_ && !pending_fired_ ? 5 : 100;
      if (lcm_.handleTimeout(timeout_ms) < 0) {
        if (g_stop_requested) break;  // the signal interrupted the wait
        log::error("LCM receive failed; stopping");
        return 1;
      }
      servePendingFiring();
    }
    heartbeat_.reset();
    log::info(run_ended_ ? "run ended: " + run_end_reason_ : std::string("stopped by signal"),
              " (", firings_run_, " firings)");
    return 0;
  }

 private:
  void onInput(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    live_channels_.insert(channel);
    deliver(channel, rbuf->data, static_cast<int>(rbuf->data_size));
  }

  void deliver(const std::string& channel, const void* data, int size) {
    try {
      if (!expert_.onMessage(channel, data, size)) reportUnhandled(channel);
    } catch (const std::exception& e) {
      log::error("message on ", channel, " raised: ", e.what());
    }
  }

  void reportUnhandled(const std::string& channel) {
    if (++unhandled_[channel] <= 3 || unhandled_[channel] % 1000 == 0)
      log::warn("message on ", channel, " not understood (", unhandled_[channel], " so far)");
  }

  void onFire(const lcm::ReceiveBuffer*, const std::string&, const beft::fire_t* fire) {
    if (fire->expert != options_.process_name) return;
    if (pending_ && pending_->firing_id >= fire->firing_id) {
      if (pending_->firing_id == fire->firing_id && pending_fired_) resendDone();
      else if (fire->firing_id < pending_->firing_id)
        log::warn("dropped stale FIRE ", fire->firing_id, " (already at ", pending_->firing_id, ")");
      return;
    }
    if (pending_ && !pending_fired_)
      log::warn("FIRE ", pending_->firing_id, " superseded by ", fire->firing_id, " before it ran");
    pending_ = Firing{fire->expert, fire->transition, fire->tick, fire->utime, fire->firing_id};
    if (heartbeat_) heartbeat_->setState(true, last_fired_id_);
    pending_fired_ = false;
    pending_since_ = Clock::now();
  }

  void onRunStatus(const lcm::ReceiveBuffer*, const std::string&, const beft::run_status_t* s) {
    // An arbiter that started after this expert's last heartbeat waits for
    // the next one: answer at once (at most every 50 ms) instead.
    if (s->state == beft::run_status_t::STATE_WAITING && heartbeat_ &&
        Clock::now() - last_waiting_answer_ > std::chrono::milliseconds(50)) {
      last_waiting_answer_ = Clock::now();
      heartbeat_->sendNow();
    }
    if (s->state == beft::run_status_t::STATE_FINISHED || s->state == beft::run_status_t::STATE_FAILED) {
      run_ended_ = true;
      run_end_reason_ = s->message;
    }
  }

  void servePendingFiring() {
    if (!pending_ || pending_fired_) return;
    bool ready = false;
    try {
      ready = expert_.inputsReady(*pending_);
    } catch (const std::exception& e) {
      log::error("inputsReady raised: ", e.what());
      ready = true;
    }
    const double waited_s =
        std::chrono::duration<double>(Clock::now() - pending_since_).count();
    if (!ready && waited_s < options_.ready_timeout_s) return;
    if (!ready)
      log::warn("firing ", pending_->firing_id, " (tick ", pending_->tick,
                "): inputs incomplete after ", options_.ready_timeout_s, " s; firing anyway");
    fireNow();
  }

  void fireNow() {
    const auto start = Clock::now();
    Outcome outcome;
    try {
      outcome = expert_.fire(*pending_, output_);
    } catch (const std::exception& e) {
      outcome = Outcome::failure(std::string("exception: ") + e.what());
    }
    ++firings_run_;
    pending_fired_ = true;
    last_fired_id_ = pending_->firing_id;
    if (heartbeat_) heartbeat_->setState(false, last_fired_id_);
    last_done_.utime = pending_->utime;
    last_done_.expert = options_.process_name;
    last_done_.tick = pending_->tick;
    last_done_.firing_id = pending_->firing_id;
    last_done_.outcome = outcome.ok ? beft::done_t::OUTCOME_OK : beft::done_t::OUTCOME_FAILED;
    last_done_.message = outcome.message;
    last_done_.duration = std::chrono::duration<double>(Clock::now() - start).count();
    if (!outcome.ok)
      log::warn("firing ", pending_->firing_id, " (tick ", pending_->tick, ") failed: ", outcome.message);
    resendDone();
  }

  void resendDone() { lcm_.publish(channels::kDone, &last_done_); }

  // Only this expert's inputs, its own FIREs, the run status and its snapshot
  // answer wake it up; everything else is dropped in the kernel.
  void installChannelFilter() {
    udpm_filter::Spec spec;
    for (const auto& channel : read_channels_) {
      if (!udpm_filter::isPlainChannel(channel)) {
        log::info("every channel reaches this process (it reads the pattern ", channel, ")");
        return;
      }
      spec.rules.push_back(udpm_filter::channelRule(channel));
    }
    spec.rules.push_back(udpm_filter::fireFor(channels::kFire, options_.process_name));
    // Only an arbiter waiting for heartbeats and the end of the run matter
    // here, not the status of every tick: run_status_t's state byte follows
    // utime and tick.
    for (int8_t state : {beft::run_status_t::STATE_WAITING, beft::run_status_t::STATE_FINISHED,
                         beft::run_status_t::STATE_FAILED}) {
      udpm_filter::Rule rule = udpm_filter::channelRule(channels::kRunStatus);
      rule.field_offset = 16;
      rule.field = std::string(1, static_cast<char>(state));
      rule.what = "waiting and end of run";
      spec.rules.push_back(rule);
    }
    if (!snapshot_channel_.empty()) spec.rules.push_back(udpm_filter::channelRule(snapshot_channel_));
    udpm_filter::installAndReport(lcm_, options_.lcm_url, spec);
  }

  void subscribeToSnapshot() {
    snapshot_channel_ = std::string(channels::kBlackboardSnapshotPrefix) + options_.process_name +
                        "_" + std::to_string(getpid());
    lcm_.subscribe(snapshot_channel_, &Runner::onSnapshot, this);
  }

  // Late joiners: ask the blackboard for the latest message of each channel
  // read; the answer only fills channels nothing has arrived on yet.
  void requestSnapshot() {
    beft::bb_query_t query;
    query.utime = wallMicros();
    query.requester = snapshot_channel_.substr(std::string(channels::kBlackboardSnapshotPrefix).size());
    query.query_id = 1;
    for (const auto& channel : read_channels_) query.channels.push_back(channel);
    query.num_channels = static_cast<int32_t>(query.channels.size());
    lcm_.publish(channels::kBlackboardQuery, &query);
  }

  void onSnapshot(const lcm::ReceiveBuffer*, const std::string&, const beft::bb_snapshot_t* snap) {
    if (snapshot_received_) return;
    snapshot_received_ = true;
    int used = 0;
    for (const auto& entry : snap->entries) {
      if (!read_channels_.count(entry.channel) || live_channels_.count(entry.channel)) continue;
      deliver(entry.channel, entry.data.data(), entry.data_size);
      ++used;
    }
    log::info("caught up from the blackboard: ", used, " channel(s)");
  }

  Expert& expert_;
  LiveOptions options_;
  lcm::LCM& lcm_;
  LcmOutput output_;
  std::set<std::string> read_channels_, live_channels_;
  std::map<std::string, int64_t> unhandled_;
  std::optional<Firing> pending_;
  bool pending_fired_ = false;
  Clock::time_point pending_since_;
  Clock::time_point last_waiting_answer_;
  int64_t last_fired_id_ = -1;
  std::optional<HeartbeatThread> heartbeat_;  // from the start of the loop to its end
  beft::done_t last_done_;
  int64_t firings_run_ = 0;
  bool run_ended_ = false;
  std::string run_end_reason_;
  std::string snapshot_channel_;
  bool snapshot_received_ = false;
};

}  // namespace

int runLive(Expert& expert, const LiveOptions& options) {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  lcm::LCM lcm(options.lcm_url);
  if (!lcm.good()) {
    log::error("cannot open LCM at ", options.lcm_url);
    return 1;
  }
  Runner runner(expert, options, lcm);
  return runner.run();
}

}  // namespace beft::expert
