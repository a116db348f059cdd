#include "lib/launch/run_adoption.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::launch {

AnnouncedRuns::AnnouncedRuns(int64_t description, int64_t freshness_us)
    : description_(description), freshness_us_(freshness_us) {}

AnnouncedRuns::Verdict AnnouncedRuns::heard(const beft::run_beacon_t& beacon, int64_t now_utime) {
  if (beacon.run_id <= 0 || beacon.description == 0 || beacon.description != description_) {
    ++other_launch_beacons_;
    return Verdict::kOtherLaunch;
  }
  if (std::llabs(now_utime - beacon.utime) > freshness_us_) {
    ++stale_beacons_;
    stale_runs_.insert(beacon.run_id);
    return Verdict::kStale;
  }
  // The newest beacon says where the arbiter is now (a restarted one has another pid).
  fresh_[beacon.run_id] = {beacon.run_id, beacon.host, beacon.pid, beacon.started_utime};
  return Verdict::kFresh;
}

namespace {

using Steady = std::chrono::steady_clock;

int64_t systemClock_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string seconds(int64_t us) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", static_cast<double>(us) * 1e-6);
  return text;
}

struct Listening {
  AnnouncedRuns runs;
  std::function<int64_t()> clock;
  std::function<void(const std::string&)> say;
  const transport::MessageKey* key;
};

// True when the run has no key, or the beacon carries a valid tag of it.
bool authentic(const lcm::ReceiveBuffer* buffer, const std::string& channel, const transport::MessageKey* key) {
  if (key == nullptr) return true;
  const auto* data = static_cast<const uint8_t*>(buffer->data);
  std::size_t payload_size = 0;
  wire::Envelope envelope;
  return wire::splitEnvelope(data, buffer->data_size, payload_size, envelope) && envelope.tagged &&
         transport::tagValid(*key, channel, envelope, data, payload_size);
}

// Every beacon is checked by the key and the guard; a stale run is said once.
void onBeacon(const lcm::ReceiveBuffer* buffer, const std::string& channel, Listening* listening) {
  if (!authentic(buffer, channel, listening->key)) {
    listening->runs.unauthenticated();
    if (listening->runs.unauthenticatedBeacons() == 1 && listening->say)
      listening->say("refused a beacon without a valid tag of this run's key (a host without the key)");
    return;
  }
  beft::run_beacon_t beacon{};
  if (!wire::decodeFrom(channel, buffer->data, buffer->data_size, beacon)) return;
  const int64_t now = listening->clock();
  const bool said_before = listening->runs.staleRuns().count(beacon.run_id) > 0;
  if (listening->runs.heard(beacon, now) != AnnouncedRuns::Verdict::kStale || said_before || !listening->say) return;
  listening->say("refused the beacon of " + wire::describeRun(beacon.run_id) + " (host " + beacon.host +
                 "): sent " + seconds(std::llabs(now - beacon.utime)) +
                 " away from this host's clock, so not a live run (a replayed log, or clocks out of sync)");
}

std::string noRunHeard(const AnnouncedRuns& runs, double timeout_s) {
  char waited[32];
  std::snprintf(waited, sizeof waited, "%g s", timeout_s);
  std::string text = "no run of this launch (the same launch file and arguments) announced itself on the LCM URL within " +
                     std::string(waited) + ": start the launch that runs the arbiter, or give the run's id with --run-id";
  if (runs.staleBeacons() > 0)
    text += "; " + std::to_string(runs.staleBeacons()) + " beacon(s) of it were refused as stale (sent more than " +
            seconds(kBeaconFreshness_us) + " away from this host's clock: a replayed log, or the hosts' clocks are " +
            "not in sync)";
  if (runs.otherLaunchBeacons() > 0)
    text += "; " + std::to_string(runs.otherLaunchBeacons()) +
            " beacon(s) of other launches were heard (another launch file, or other --set values than the "
            "arbiter's launch was given)";
  if (runs.unauthenticatedBeacons() > 0)
    text += "; " + std::to_string(runs.unauthenticatedBeacons()) +
            " beacon(s) without a valid tag of this run's key were refused (is the arbiter's launch given the "
            "same --key?)";
  return text;
}

AnnouncedRun chosenRun(const AnnouncedRuns& runs, double timeout_s, int64_t now_utime) {
  if (runs.fresh().empty()) throw LaunchError(noRunHeard(runs, timeout_s));
  if (runs.fresh().size() == 1) return runs.fresh().begin()->second;
  std::string list;
  for (const auto& [id, run] : runs.fresh()) list += (list.empty() ? "" : "; ") + describeAnnouncedRun(run, now_utime);
  throw LaunchError("several runs of this launch (the same launch file and arguments) are announced on the LCM URL: " +
                    list + ". Say which to join with --run-id ID");
}

}  // namespace

std::string describeAnnouncedRun(const AnnouncedRun& run, int64_t now_utime) {
  std::string text = wire::describeRun(run.run_id) + " (arbiter pid " + std::to_string(run.pid) + " on host " + run.host;
  if (run.started_utime > 0) text += ", launched " + seconds(now_utime - run.started_utime) + " ago";
  return text + ")";
}

AnnouncedRun adoptAnnouncedRun(lcm::LCM& lcm, int64_t description, const AdoptionOptions& options) {
  Listening listening{AnnouncedRuns(description), options.wall_clock_us ? options.wall_clock_us : systemClock_us,
                      options.say, options.key};
  auto* subscription = lcm.subscribeFunction(std::string(channels::kRunBeacons.name), &onBeacon, &listening);
  const auto give_up = Steady::now() + std::chrono::duration_cast<Steady::duration>(
                                           std::chrono::duration<double>(options.timeout_s));
  std::optional<Steady::time_point> settled;
  bool receiving = true;
  while (receiving) {
    const auto now = Steady::now();
    if (!settled && !listening.runs.fresh().empty())
      settled = now + std::chrono::duration_cast<Steady::duration>(std::chrono::duration<double>(options.settle_s));
    const auto until = settled ? *settled : give_up;
    if (now >= until) break;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - now).count() + 1;
    receiving = lcm.handleTimeout(static_cast<int>(left)) >= 0;
  }
  lcm.unsubscribe(subscription);
  if (!receiving) throw LaunchError("cannot receive on the LCM URL to hear the run's beacons");
  return chosenRun(listening.runs, options.timeout_s, listening.clock());
}

}  // namespace beft::launch
