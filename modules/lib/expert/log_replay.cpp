#include "lib/expert/log_replay.hpp"

#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::expert {

namespace {

using Messages = std::vector<std::vector<uint8_t>>;
// Outputs of each firing, by firing id, then channel.
using OutputsByFiring = std::map<int64_t, std::map<std::string, Messages>>;

class CapturingOutput : public Output {
 public:
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    captured[firing_id][channel].push_back(bytes);
  }
  int64_t firing_id = -1;
  OutputsByFiring captured;
};

// Compared firing by firing, so a message the logger lost shifts nothing.
void compareFirings(OutputsByFiring& recorded, OutputsByFiring& replayed, ReplayResult& result) {
  std::set<int64_t> firing_ids;
  for (const auto& [id, _] : recorded) firing_ids.insert(id);
  for (const auto& [id, _] : replayed) firing_ids.insert(id);
  for (int64_t id : firing_ids) {
    std::set<std::string> channels_of_firing;
    for (const auto& [channel, _] : recorded[id]) channels_of_firing.insert(channel);
    for (const auto& [channel, _] : replayed[id]) channels_of_firing.insert(channel);
    for (const auto& channel : channels_of_firing) {
      const Messages& was = recorded[id][channel];
      const Messages& now = replayed[id][channel];
      const std::size_t common = std::min(was.size(), now.size());
      for (std::size_t i = 0; i < common; ++i) {
        ++result.outputs_compared;
        if (was[i] == now[i]) {
          ++result.outputs_matching;
        } else if (result.first_mismatches.size() < 3) {
          result.first_mismatches.push_back({channel, id, was[i], now[i]});
        }
      }
      if (was.size() > common) result.recorded_only += static_cast<int64_t>(was.size() - common);
      if (now.size() > common) result.replayed_only += static_cast<int64_t>(now.size() - common);
    }
  }
}

// Feeds one expert the log's events as it heard them live: its inputs in
// log order, its FIREs fired once their inputs are ready (or when a newer
// FIRE for it comes, as live after the time-out). may_fire decides which
// FIREs run at all (a resumed expert leaves the one its DONE is missing
// for to the arbiter, which sends it again).
class LogFeeder {
 public:
  LogFeeder(Expert& expert, std::string process_name, Output& output, std::function<bool(int64_t)> may_fire)
      : expert_(expert), process_name_(std::move(process_name)), output_(output), may_fire_(std::move(may_fire)) {
    for (const auto& spec : expert.reads()) reads_.insert(spec.channel);
  }

  // Returns true if the event was an input delivered to the expert.
  bool feed(const wire::LogEvent& event) {
    const std::string& channel = event.channel;
    if (channel == channels::kFire) {
      beft::fire_t fire{};
      if (!wire::decodeFrom(channel, event.data.data(), event.data.size(), fire)) return false;
      if (fire.expert != process_name_ || fire.firing_id <= last_firing_id_) return false;
      firePending();  // a newer token: the previous one runs now
      last_firing_id_ = fire.firing_id;
      pending_ = Firing{fire.expert, fire.transition, fire.tick, fire.utime, fire.firing_id};
      if (!may_fire_(fire.firing_id)) {
        in_flight_ = pending_;
        pending_.reset();
        return false;
      }
      if (expert_.inputsReady(*pending_)) firePending();
      return false;
    }
    if (!reads_.count(channel)) return false;
    expert_.onMessage(channel, event.data.data(), static_cast<int>(event.data.size()));
    if (pending_ && expert_.inputsReady(*pending_)) firePending();
    return true;
  }

  void firePending() {
    if (!pending_) return;
    if (!expert_.inputsReady(*pending_)) {
      ++firings_lacking_inputs_;
      for (const std::string& channel : expert_.inputsLacking(*pending_)) ++lacking_inputs_[channel];
    }
    before_fire_(*pending_);
    try {
      expert_.fire(*pending_, output_);
    } catch (const std::exception& e) {
      log::warn("replayed firing ", pending_->firing_id, " raised: ", e.what());
    }
    ++firings_;
    last_fired_ = pending_;
    pending_.reset();
  }

  int64_t lastFiringId() const { return last_firing_id_; }
  int64_t firings() const { return firings_; }
  int64_t firingsLackingInputs() const { return firings_lacking_inputs_; }
  const std::map<std::string, int64_t>& lackingInputs() const { return lacking_inputs_; }
  const std::optional<Firing>& lastFired() const { return last_fired_; }
  const std::optional<Firing>& inFlight() const { return in_flight_; }
  void onBeforeFire(std::function<void(const Firing&)> callback) { before_fire_ = std::move(callback); }

 private:
  Expert& expert_;
  std::string process_name_;
  Output& output_;
  std::function<bool(int64_t)> may_fire_;
  std::function<void(const Firing&)> before_fire_ = [](const Firing&) {};
  std::set<std::string> reads_;
  std::optional<Firing> pending_, last_fired_, in_flight_;
  int64_t last_firing_id_ = -1;
  int64_t firings_ = 0;
  int64_t firings_lacking_inputs_ = 0;
  std::map<std::string, int64_t> lacking_inputs_;
};

class DiscardingOutput : public Output {
 public:
  void publishEncoded(const std::string&, const std::vector<uint8_t>&) override {}
};

// The DONEs this process sent, by firing id, as the log holds them.
std::map<int64_t, beft::done_t> donesOf(const std::string& process_name, const std::string& log_path) {
  std::map<int64_t, beft::done_t> dones;
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, wire::runId())) {
    if (event.channel != channels::kDone) continue;
    beft::done_t done{};
    if (wire::decodeFrom(event.channel, event.data.data(), event.data.size(), done) && done.expert == process_name)
      dones[done.firing_id] = done;
  }
  return dones;
}

uint64_t fingerprintOf(const std::string& channel, const uint8_t* bytes, std::size_t size) {
  uint64_t hash = 1469598103934665603ull;  // FNV-1a over channel and bytes
  for (char c : channel) hash = (hash ^ static_cast<uint8_t>(c)) * 1099511628211ull;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

}  // namespace

uint64_t messageFingerprint(const std::string& channel, const void* data, std::size_t size) {
  return fingerprintOf(channel, static_cast<const uint8_t*>(data), size);
}

ReplayResult replayLog(Expert& expert, const std::string& process_name, const std::string& log_path) {
  std::set<std::string> writes;
  for (const auto& spec : expert.writes()) writes.insert(spec.channel);

  ReplayResult result;
  CapturingOutput output;
  output.restrictTo(expert.writes());
  OutputsByFiring recorded;
  // Recorded outputs are the messages on its channels between this expert's
  // FIRE and its DONE: others (or a user) may publish on the same channels.
  bool in_recorded_firing = false;
  LogFeeder feeder(expert, process_name, output, [](int64_t) { return true; });
  feeder.onBeforeFire([&](const Firing& firing) { output.firing_id = firing.firing_id; });

  // Offline the expert is of the run it replays (the arbiter's in the log).
  const int64_t run = wire::runId() != 0 ? wire::runId() : wire::runOfLog(log_path);
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) {
    const std::string& channel = event.channel;
    const int64_t firing_before = feeder.lastFiringId();
    feeder.feed(event);
    if (feeder.lastFiringId() != firing_before) {
      in_recorded_firing = true;
      continue;
    }
    if (channel == channels::kDone) {
      beft::done_t done{};
      if (wire::decodeFrom(channel, event.data.data(), event.data.size(), done) && done.expert == process_name &&
          done.firing_id == feeder.lastFiringId())
        in_recorded_firing = false;
      continue;
    }
    if (writes.count(channel) && in_recorded_firing) recorded[feeder.lastFiringId()][channel].push_back(event.data);
  }
  feeder.firePending();
  result.firings = feeder.firings();
  result.firings_lacking_inputs = feeder.firingsLackingInputs();
  result.lacking_inputs = feeder.lackingInputs();
  result.log_damage = log.damage().summary();

  compareFirings(recorded, output.captured, result);
  return result;
}

// What the log holds on `writes` after each firing's FIRE, while no newer
// FIRE has come: the outputs of a firing that may be in flight.
class OutputsAfterFire {
 public:
  OutputsAfterFire(const Expert& expert, const LogFeeder& feeder) : feeder_(feeder) {
    for (const auto& spec : expert.writes()) writes_.insert(spec.channel);
  }
  void see(const wire::LogEvent& event) {
    const auto& in_flight = feeder_.inFlight();
    if (!writes_.count(event.channel) || !in_flight || in_flight->firing_id != feeder_.lastFiringId()) return;
    by_firing_[in_flight->firing_id].insert(fingerprintOf(event.channel, event.data.data(), event.data.size()));
  }
  std::multiset<uint64_t> of(int64_t firing_id) const {
    const auto found = by_firing_.find(firing_id);
    return found == by_firing_.end() ? std::multiset<uint64_t>() : found->second;
  }

 private:
  const LogFeeder& feeder_;
  std::set<std::string> writes_;
  std::map<int64_t, std::multiset<uint64_t>> by_firing_;
};

ResumeState resumeFromLog(Expert& expert, const std::string& process_name, const std::string& log_path,
                          int64_t live_since_us) {
  if (!wire::waitForLogPast(log_path, live_since_us, 5.0))
    log::warn("the run's log ", log_path, " has nothing newer than this process's start after 5 s: "
              "resuming from what it holds");
  const std::map<int64_t, beft::done_t> dones = donesOf(process_name, log_path);
  DiscardingOutput output;
  LogFeeder feeder(expert, process_name, output, [&](int64_t firing_id) { return dones.count(firing_id) > 0; });
  ResumeState state;
  OutputsAfterFire outputs(expert, feeder);
  wire::LogReader log(log_path);
  wire::LogEvent event;
  // Inputs logged after this instant may also be waiting on the live sockets.
  const int64_t overlap_from_us = live_since_us - 1000000;
  while (log.nextOfRun(event, wire::runId())) {
    outputs.see(event);
    if (feeder.feed(event)) {
      ++state.inputs;
      if (event.timestamp >= overlap_from_us) state.logged_recently.insert(fingerprintOf(event.channel, event.data.data(), event.data.size()));
    }
  }
  feeder.firePending();
  state.firings = feeder.firings();
  state.firings_lacking_inputs = feeder.firingsLackingInputs();
  state.lacking_inputs = feeder.lackingInputs();
  state.last_fired = feeder.lastFired();
  if (state.last_fired) {
    auto done = dones.find(state.last_fired->firing_id);
    if (done != dones.end()) state.last_done = done->second;
  }
  state.in_flight = feeder.inFlight();
  if (state.in_flight && state.last_fired && state.in_flight->firing_id < state.last_fired->firing_id)
    state.in_flight.reset();
  if (state.in_flight) state.in_flight_outputs = outputs.of(state.in_flight->firing_id);
  state.log_damage = log.damage().summary();
  return state;
}

std::string describeLackingInputs(const std::map<std::string, int64_t>& lacking_inputs) {
  std::string text;
  for (const auto& [channel, firings] : lacking_inputs) {
    if (!text.empty()) text += ", ";
    text += channel + " (" + std::to_string(firings) + (firings == 1 ? " firing)" : " firings)");
  }
  return text;
}

void printReplayResult(const ReplayResult& result, const std::string& process_name,
                       const std::function<std::string(const std::string&, const std::vector<uint8_t>&)>& describe) {
  std::printf("replay of %s: %lld firings, %lld/%lld outputs match", process_name.c_str(),
              static_cast<long long>(result.firings), static_cast<long long>(result.outputs_matching),
              static_cast<long long>(result.outputs_compared));
  if (result.recorded_only) std::printf(", %lld recorded but not produced", static_cast<long long>(result.recorded_only));
  if (result.replayed_only)
    std::printf(", %lld produced but not in the log (lost by the logger, or new output)",
                static_cast<long long>(result.replayed_only));
  if (!result.log_damage.empty()) std::printf("\nlog: %s", result.log_damage.c_str());
  if (result.firings_lacking_inputs > 0) {
    bool camera = false;
    for (const auto& [channel, _] : result.lacking_inputs) camera = camera || channel.rfind("CAMERA_", 0) == 0;
    std::printf("\nthe log lacks inputs of %lld of the %lld firings: nothing of their tick on %s%s",
                static_cast<long long>(result.firings_lacking_inputs), static_cast<long long>(result.firings),
                describeLackingInputs(result.lacking_inputs).c_str(),
                camera ? " (a run recorded with --record-camera every:N or none keeps the camera frames of some "
                         "ticks only, or none; record with --record-camera all to replay this expert)"
                       : "");
  }
  std::printf("\n%s\n", result.exactMatch()       ? "EXACT MATCH"
                          : result.logLacksInputs() ? "INCOMPLETE LOG: the outputs cannot be compared"
                                                    : "DIFFERENCES FOUND");
  if (result.firings == 0) std::printf("(no FIRE for '%s' in the log)\n", process_name.c_str());
  if (result.logLacksInputs()) return;  // differences of firings without their inputs tell nothing
  for (const auto& mismatch : result.first_mismatches) {
    std::printf("\nfirst difference on %s, firing %lld:\n", mismatch.channel.c_str(),
                static_cast<long long>(mismatch.index));
    if (describe) {
      std::printf("--- recorded:\n%s\n--- replayed:\n%s\n", describe(mismatch.channel, mismatch.recorded).c_str(),
                  describe(mismatch.channel, mismatch.replayed).c_str());
    } else {
      std::size_t at = 0;
      while (at < mismatch.recorded.size() && at < mismatch.replayed.size() &&
             mismatch.recorded[at] == mismatch.replayed[at])
        ++at;
      std::printf("  sizes %zu vs %zu, first differing byte at offset %zu\n", mismatch.recorded.size(),
                  mismatch.replayed.size(), at);
    }
  }
}

}  // namespace beft::expert
