#include "lib/expert/live_runner.hpp"

#include "lib/wire/blackboard_query.hpp"

#include <unistd.h>

#include <atomic>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <beft/bb_snapshot_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/expert/frontier.hpp"
#include "lib/expert/heartbeat_thread.hpp"
#include "lib/expert/log_replay.hpp"
#include "lib/common/log.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/reject_report.hpp"
#include "lib/wire/run_identity.hpp"
#include "lib/transport/transport.hpp"

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
    if (alreadySent(channel, bytes)) return;
    if (transport::publishEncoded(lcm_, run_names_.of(channel), bytes.data(), bytes.size()) != 0)
      log::warn("could not publish on ", channel, " (", bytes.size(), " bytes)");
  }
  // Outputs on the bus already (a restarted process runs its in-flight
  // firing again): identical ones are not sent twice.
  void expectAlreadySent(std::multiset<uint64_t> fingerprints) { already_sent_ = std::move(fingerprints); }
  void forgetAlreadySent() { already_sent_.clear(); }

 private:
  bool alreadySent(const std::string& channel, const std::vector<uint8_t>& bytes) {
    if (already_sent_.empty()) return false;
    const auto found = already_sent_.find(messageFingerprint(channel, bytes.data(), bytes.size()));
    if (found == already_sent_.end()) return false;
    already_sent_.erase(found);
    log::info(channel, ": published before this process was restarted, not sent again");
    return true;
  }

  lcm::LCM& lcm_;
  wire::RunChannelNames run_names_;
  std::multiset<uint64_t> already_sent_;
};

// Tells whether the blackboard's copy of a channel is the message already
// heard: FNV-1a over the size and the first 64 bytes, which hold the type's
// fingerprint, utime and tick (cheap for camera frames).
uint64_t bytesHash(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  uint64_t hash = (1469598103934665603ULL ^ size) * 1099511628211ULL;
  for (std::size_t i = 0; i < std::min<std::size_t>(size, 64); ++i) hash = (hash ^ bytes[i]) * 1099511628211ULL;
  return hash;
}

// Holds what the LCM handlers received; the main loop decides what to do.
class Runner {
 public:
  Runner(Expert& expert, const LiveOptions& options, lcm::LCM& lcm)
      : expert_(expert), options_(options), lcm_(lcm), output_(lcm) {
    output_.restrictTo(expert_.writes());
  }

  int run() {
    for (const auto& spec : expert_.reads()) read_channels_.insert(spec.channel);
    if (options_.catch_up)
      snapshot_channel_ = wire::blackboardAnswerChannel(options_.process_name);
    if (!openSources()) return 1;
    heartbeat_.emplace(lcm_, options_.process_name, options_.heartbeat_period_s);
    if (!options_.resume_log.empty()) {
      if (!resume()) return 1;
    } else if (options_.catch_up) {
      requestSnapshot();
    }

    log::info("ready: waiting for FIRE on ", options_.lcm_url);
    const transport::Handler handler = [this](const transport::Message& message) { onMessage(message); };
    while (!g_stop_requested && !run_ended_) {
      // Short waits while a firing waits for its inputs (then their socket
      // wakes it too); else 100 ms, so a signal is seen.
      const bool waiting_for_inputs = pending_ && !pending_fired_;
      transport::waitReadable({control_->fd(), inputs_ && waiting_for_inputs ? inputs_->fd() : -1},
                         waiting_for_inputs ? 5 : 100);
      // Inputs around the control messages: what was published before a FIRE
      // is stored before the FIRE is served, even what arrived while the
      // FIRE was being read (a command sent just before it).
      if (transport::drainSplit(*control_, inputs_.get(), handler) < 0) {
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
  // One handler for both sources: the control channels by name, then inputs.
  void onMessage(const transport::Message& message) {
    const std::string channel(message.channel);
    const int size = static_cast<int>(message.size);
    if (channel == channels::kFire) {
      beft::fire_t fire{};
      if (decodeMessage(channel, message.data, size, fire)) onFire(fire);
    } else if (channel == channels::kRunStatus) {
      beft::run_status_t status{};
      if (decodeMessage(channel, message.data, size, status)) onRunStatus(status);
    } else if (channel == channels::kFrontier) {
      beft::frontier_t frontier{};
      if (decodeMessage(channel, message.data, size, frontier)) frontier_.add(frontier);
    } else if (!snapshot_channel_.empty() && channel == snapshot_channel_) {
      beft::bb_snapshot_t snapshot{};
      if (decodeMessage(channel, message.data, size, snapshot)) onSnapshot(snapshot);
    } else if (read_channels_.count(channel)) {
      if (heardWhileResuming(channel, message.data, message.size)) return;
      live_channels_.insert(channel);
      last_live_bytes_[channel] = bytesHash(message.data, message.size);
      deliver(channel, message.data, size);
    }
  }

  // Crash-only restart: the state the process had, rebuilt from the run's
  // log (log_replay.hpp). Inputs queue on the live sockets meanwhile; those
  // the log also held are dropped once (heardWhileResuming).
  bool resume() {
    const int64_t live_since_us = wallMicros();
    ResumeState state;
    try {
      state = resumeFromLog(expert_, options_.process_name, options_.resume_log, live_since_us);
    } catch (const std::exception& e) {
      log::error("cannot resume from ", options_.resume_log, ": ", e.what());
      return false;
    }
    if (state.last_fired && state.last_done) {
      pending_ = *state.last_fired;
      pending_fired_ = true;
      last_fired_id_ = state.last_fired->firing_id;
      last_done_ = *state.last_done;
      heartbeat_->setState(false, last_fired_id_);
    }
    logged_recently_ = std::move(state.logged_recently);
    if (state.in_flight) {
      in_flight_id_ = state.in_flight->firing_id;
      output_.expectAlreadySent(std::move(state.in_flight_outputs));
    }
    if (state.firings_lacking_inputs > 0)
      log::warn("the run's log lacks inputs of ", state.firings_lacking_inputs, " of the ", state.firings,
                " firings replayed (", describeLackingInputs(state.lacking_inputs),
                "): the state rebuilt misses what they held, and this process's outputs may differ from those of "
                "a run in which it never died");
    log::info("resumed from ", options_.resume_log, ": ", state.firings, " firings and ", state.inputs,
              " inputs replayed", state.in_flight ? "; firing " + std::to_string(state.in_flight->firing_id) +
                                                        " was in flight and is awaited from the arbiter"
                                                  : std::string(),
              state.log_damage.empty() ? "" : " (log: " + state.log_damage + ")");
    return true;
  }

  bool heardWhileResuming(const std::string& channel, const void* data, std::size_t size) {
    if (logged_recently_.empty()) return false;
    auto it = logged_recently_.find(messageFingerprint(channel, data, size));
    if (it == logged_recently_.end()) return false;
    logged_recently_.erase(it);
    return true;
  }

  void deliver(const std::string& channel, const void* data, int size) {
    try {
      expert_.onMessage(channel, data, size);  // a refused message is counted and logged by the guard
    } catch (const std::exception& e) {
      log::error("message on ", channel, " raised: ", e.what());
    }
  }

  void onFire(const beft::fire_t& fire_message) {
    const beft::fire_t* fire = &fire_message;
    if (fire->expert != options_.process_name) return;
    if (pending_ && pending_->firing_id >= fire->firing_id) {
      if (pending_->firing_id == fire->firing_id && pending_fired_) resendDone();
      else if (fire->firing_id < pending_->firing_id)
        log::warn("dropped stale FIRE ", fire->firing_id, " (already at ", pending_->firing_id, ")");
      return;
    }
    if (repeatsTheFiringDone(*fire)) {
      // A restarted arbiter whose log lacked the first FIRE fires it again
      // under a new id: its DONE answers, the outputs are not sent twice.
      log::info("FIRE ", fire->firing_id, " repeats firing ", pending_->firing_id, " of tick ", fire->tick,
                ", already done: its DONE sent again");
      pending_->firing_id = fire->firing_id;
      last_fired_id_ = last_done_.firing_id = fire->firing_id;
      if (heartbeat_) heartbeat_->setState(false, last_fired_id_);
      resendDone();
      return;
    }
    if (pending_ && !pending_fired_)
      log::warn("FIRE ", pending_->firing_id, " superseded by ", fire->firing_id, " before it ran");
    pending_ = Firing{fire->expert, fire->transition, fire->tick, fire->utime, fire->firing_id};
    pending_fire_ = *fire;
    if (heartbeat_) heartbeat_->setState(true, last_fired_id_);
    pending_fired_ = false;
    pending_since_ = Clock::now();
  }

  // Whether a newer FIRE asks for the firing that ran last, successfully: the
  // same transition at the same tick.
  bool repeatsTheFiringDone(const beft::fire_t& fire) const {
    return pending_ && pending_fired_ && last_done_.outcome == beft::done_t::OUTCOME_OK &&
           last_done_.firing_id == pending_->firing_id && pending_->tick == fire.tick &&
           pending_->transition == fire.transition;
  }

  void onRunStatus(const beft::run_status_t& status) {
    const beft::run_status_t* s = &status;
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
      // Both asked every time: each asks the transport for what it misses.
      const bool after_frontier =
          frontier_.reached(pending_fire_, {inputs_.get(), control_.get()}, !options_.resume_log.empty());
      ready = expert_.inputsReady(*pending_) && after_frontier;
    } catch (const std::exception& e) {
      log::error("inputsReady raised: ", e.what());
      ready = true;
    }
    const double waited_s =
        std::chrono::duration<double>(Clock::now() - pending_since_).count();
    if (heartbeat_) heartbeat_->setWaiting(!ready);
    if (!ready) {
      // Loss repair brings what was lost within milliseconds while its
      // sender lives; the blackboard, which keeps the latest of each
      // channel, is asked too, again every refill_after_s, for what a dead
      // sender took with it.
      if (refilled_firing_ != pending_->firing_id) {
        refilled_firing_ = pending_->firing_id;
        next_refill_s_ = options_.refill_after_s;
      }
      if (waited_s >= next_refill_s_ && !snapshot_channel_.empty()) {
        next_refill_s_ = waited_s + options_.refill_after_s;
        log::warn("firing ", pending_->firing_id, " (tick ", pending_->tick, "): inputs incomplete after ",
                  static_cast<int>(waited_s * 1000), " ms; asking the blackboard for them again");
        requestSnapshot(/*refill=*/true);
      }
      if (waited_s >= next_wait_report_s_) {
        next_wait_report_s_ += options_.wait_report_s;
        log::warn("firing ", pending_->firing_id, " (tick ", pending_->tick, "): still waiting for its inputs after ",
                  static_cast<int>(waited_s), " s");
      }
      const bool give_up = options_.ready_timeout_s > 0 && waited_s >= options_.ready_timeout_s;
      if (!give_up) return;
      log::warn("firing ", pending_->firing_id, " (tick ", pending_->tick, "): inputs incomplete after ",
                options_.ready_timeout_s, " s; firing anyway (--ready-timeout)");
    }
    next_wait_report_s_ = options_.wait_report_s;
    fireNow();
  }

  void fireNow() {
    const auto start = Clock::now();
    // Only the firing in flight when the process died has outputs on the bus already.
    if (pending_->firing_id != in_flight_id_) output_.forgetAlreadySent();
    Outcome outcome;
    try {
      outcome = expert_.fire(*pending_, output_);
    } catch (const std::exception& e) {
      outcome = Outcome::failure(std::string("exception: ") + e.what());
    }
    output_.forgetAlreadySent();
    ++firings_run_;
    pending_fired_ = true;
    last_fired_id_ = pending_->firing_id;
    if (heartbeat_) heartbeat_->setState(false, last_fired_id_);
    listPublished(lcm_, last_done_);
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

  void resendDone() { transport::publish(lcm_, done_channel_, last_done_); }

  // What wakes the expert: its own FIREs, the run's waiting and end, and its
  // snapshot answer. Its inputs go to a socket of their own that nothing
  // waits on: the kernel queues them and they are read when a FIRE comes.
  // Everything else is dropped in the kernel. Without the direct receiver
  // (another provider, BEFT_UDPM_RECEIVER=0) one LCM subscription takes both.
  bool openSources() {
    transport::Selection control_spec, input_spec;
    for (const auto& channel : read_channels_) {
      if (!transport::isPlainChannel(channel)) {
        log::error("reads() names '", channel, "': an expert reads channels by name, not by pattern");
        return false;
      }
      input_spec.rules.push_back(transport::channelRule(channel));
    }
    // What a firing comes after (frontier.hpp), read with the inputs.
    input_spec.rules.push_back(transport::channelRule(channels::kFrontier.name));
    control_spec.rules.push_back(control::firesFor(options_.process_name));
    // Only an arbiter waiting for heartbeats and the end of the run matter
    // here, not the status of every tick.
    for (int8_t state : {beft::run_status_t::STATE_WAITING, beft::run_status_t::STATE_FINISHED,
                         beft::run_status_t::STATE_FAILED})
      control_spec.rules.push_back(control::runStatusIn(state, "waiting and end of run"));
    if (!snapshot_channel_.empty()) control_spec.rules.push_back(transport::channelRule(snapshot_channel_));
    try {
      transport::SplitReceivers sources = transport::openSplitReceivers(lcm_, options_.lcm_url, control_spec, input_spec);
      control_ = std::move(sources.wake);
      inputs_ = std::move(sources.queued);
      if (inputs_) log::info("inputs: ", inputs_->description());
      log::info(inputs_ ? "control: " : "receiving: ", control_->description());
    } catch (const std::exception& e) {
      log::error("cannot receive on ", options_.lcm_url, ": ", e.what());
      return false;
    }
    return true;
  }

  // Late joiners: ask the blackboard for the latest message of each channel
  // read; the answer only fills channels nothing has arrived on yet.
  // Again while a firing waits for inputs (refill): the answer then fills
  // the channels the firing lacks whose latest message differs from what
  // arrived live.
  void requestSnapshot(bool refill = false) {
    if (refill) refill_pending_ = true;
    transport::publish(lcm_, wire::runChannel(channels::kBlackboardQuery),
                       wire::blackboardQuery(snapshot_channel_, ++snapshot_queries_,
                                             std::vector<std::string>(read_channels_.begin(), read_channels_.end())));
  }

  void onSnapshot(const beft::bb_snapshot_t& snapshot) {
    const beft::bb_snapshot_t* snap = &snapshot;
    if (refill_pending_) {
      refill_pending_ = false;
      // Only what the waiting firing lacks (messages kept by tick): a
      // message applied on arrival (a command) is never delivered twice.
      if (!pending_ || pending_fired_) return;
      const std::vector<std::string> lacking = expert_.inputsLacking(*pending_);
      int refilled = 0;
      for (const auto& entry : snap->entries) {
        if (std::find(lacking.begin(), lacking.end(), entry.channel) == lacking.end()) continue;
        const auto live = last_live_bytes_.find(entry.channel);
        const uint64_t hash = bytesHash(entry.data.data(), entry.data.size());
        if (live != last_live_bytes_.end() && live->second == hash) continue;  // nothing was lost there
        last_live_bytes_[entry.channel] = hash;
        deliver(entry.channel, entry.data.data(), entry.data_size);
        ++refilled;
      }
      log::info("refilled ", refilled, " channel(s) from the blackboard");
      return;
    }
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
  std::optional<Firing> pending_;
  bool pending_fired_ = false;
  Clock::time_point pending_since_;
  Clock::time_point last_waiting_answer_;
  int64_t last_fired_id_ = -1;
  std::unique_ptr<transport::Receiver> control_, inputs_;  // openSplitReceivers: inputs_ only with the direct receiver
  std::optional<HeartbeatThread> heartbeat_;  // from the start of the loop to its end
  beft::done_t last_done_{};
  int64_t firings_run_ = 0;
  bool run_ended_ = false;
  std::string run_end_reason_;
  std::string snapshot_channel_;
  bool snapshot_received_ = false;
  bool refill_pending_ = false;
  int64_t snapshot_queries_ = 0;
  int64_t refilled_firing_ = -1;          // the firing whose inputs were last asked again
  Frontier frontier_;                     // what the FIREs come after
  beft::fire_t pending_fire_{};           // the FIRE of pending_, as received
  double next_refill_s_ = 0.0;            // when to ask the blackboard again, from the firing's FIRE
  double next_wait_report_s_ = 5.0;
  std::map<std::string, uint64_t> last_live_bytes_;  // hash of the latest message heard per channel
  std::multiset<uint64_t> logged_recently_;  // inputs the resume replayed that may also arrive live
  int64_t in_flight_id_ = -1;                // the firing in flight when the process died (resume)
  const std::string done_channel_ = wire::runChannel(channels::kDone);
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
  std::unique_ptr<transport::PublisherScope> publishing;
  try {
    publishing = transport::attachPublisher(lcm, options.lcm_url, options.process_name);
  } catch (const std::exception& e) {
    log::error("cannot publish on ", options.lcm_url, ": ", e.what());
    return 1;
  }
  wire::logRunOf(options.lcm_url);
  // What this process refuses, told to the run: the report counts it (a log keeps no tags).
  wire::RejectReporter rejects(options.process_name, [&lcm](const beft::process_rejects_t& account) {
    transport::publish(lcm, wire::runChannel(channels::kProcessRejects), account);
  });
  Runner runner(expert, options, lcm);
  return runner.run();
}

}  // namespace beft::expert
