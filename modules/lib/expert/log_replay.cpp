#include "log_replay.hpp"

#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "channels.hpp"
#include "log.hpp"

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

}  // namespace

ReplayResult replayLog(Expert& expert, const std::string& process_name, const std::string& log_path) {
  lcm::LogFile log(log_path, "r");
  if (!log.good()) throw std::runtime_error("cannot read LCM log '" + log_path + "'");

  std::set<std::string> reads, writes;
  for (const auto& spec : expert.reads()) reads.insert(spec.channel);
  for (const auto& spec : expert.writes()) writes.insert(spec.channel);

  ReplayResult result;
  CapturingOutput output;
  output.restrictTo(expert.writes());
  OutputsByFiring recorded;
  std::optional<Firing> pending;
  int64_t last_firing_id = -1;
  // Recorded outputs are the messages on its channels between this expert's
  // FIRE and its DONE: others (or a user) may publish on the same channels.
  bool in_recorded_firing = false;

  auto firePending = [&] {
    if (!pending) return;
    output.firing_id = pending->firing_id;
    try {
      expert.fire(*pending, output);
    } catch (const std::exception& e) {
      log::warn("replayed firing ", pending->firing_id, " raised: ", e.what());
    }
    ++result.firings;
    pending.reset();
  };

  while (const lcm::LogEvent* event = log.readNextEvent()) {
    const std::string& channel = event->channel;
    if (channel == channels::kFire) {
      beft::fire_t fire;
      if (fire.decode(event->data, 0, event->datalen) != event->datalen) continue;
      if (fire.expert != process_name || fire.firing_id <= last_firing_id) continue;
      firePending();  // a newer token: the previous one runs now, as live after its timeout
      last_firing_id = fire.firing_id;
      in_recorded_firing = true;
      pending = Firing{fire.expert, fire.transition, fire.tick, fire.utime, fire.firing_id};
      if (expert.inputsReady(*pending)) firePending();
      continue;
    }
    if (channel == channels::kDone) {
      beft::done_t done;
      if (done.decode(event->data, 0, event->datalen) == event->datalen && done.expert == process_name &&
          done.firing_id == last_firing_id)
        in_recorded_firing = false;
      continue;
    }
    if (writes.count(channel) && in_recorded_firing) {
      const auto* bytes = static_cast<const uint8_t*>(event->data);
      recorded[last_firing_id][channel].emplace_back(bytes, bytes + event->datalen);
    }
    if (reads.count(channel)) {
      expert.onMessage(channel, event->data, event->datalen);
      if (pending && expert.inputsReady(*pending)) firePending();
    }
  }
  firePending();

  compareFirings(recorded, output.captured, result);
  return result;
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
  std::printf("\n%s\n", result.exactMatch() ? "EXACT MATCH" : "DIFFERENCES FOUND");
  if (result.firings == 0) std::printf("(no FIRE for '%s' in the log)\n", process_name.c_str());
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
