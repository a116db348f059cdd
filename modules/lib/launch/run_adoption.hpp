// How a launch that does not run the arbiter (the other hosts of a
// distributed run) learns the run's id: the arbiter announces its run on the
// URL-wide channel BEFT_RUNS twice a second (run_beacon_t), with the hash of
// its launch file and arguments; this launch takes the run whose beacon names
// the same launch and is fresh.
//
// Fresh: the beacon's time is within a few seconds of this host's wall clock.
// A replayed log's beacons carry the times they were sent (lcm-logplayer
// leaves the bytes as they were), so yesterday's run, played on the URL,
// is refused rather than joined; so is an arbiter on a host whose clock is
// far off (the hosts of a distributed run keep their clocks in sync, NTP).
// In a keyed run a beacon counts only with a valid tag of the run's key, so a
// host without the key can neither lure this launch into its run nor make
// it refuse the real one as one of two.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>

#include <beft/run_beacon_t.hpp>

namespace lcm {
class LCM;
}
namespace beft::transport {
class MessageKey;
}

namespace beft::launch {

// How far a beacon's time may be from this host's wall clock.
constexpr int64_t kBeaconFreshness_us = 5'000'000;

struct AnnouncedRun {
  int64_t run_id = 0;
  std::string host;
  int32_t pid = 0;
  int64_t started_utime = 0;  // 0: not known
};

// The beacons heard, sorted: those of this launch that are fresh, by run;
// those refused as stale, counted; those of other launches, counted.
class AnnouncedRuns {
 public:
  enum class Verdict { kFresh, kStale, kOtherLaunch };

  explicit AnnouncedRuns(int64_t description, int64_t freshness_us = kBeaconFreshness_us);
  // `now_utime`: this host's wall clock when the beacon arrived [us].
  Verdict heard(const beft::run_beacon_t& beacon, int64_t now_utime);

  const std::map<int64_t, AnnouncedRun>& fresh() const { return fresh_; }
  uint64_t staleBeacons() const { return stale_beacons_; }
  const std::set<int64_t>& staleRuns() const { return stale_runs_; }
  uint64_t otherLaunchBeacons() const { return other_launch_beacons_; }
  // A beacon without a valid tag of the run's key (heard() is not called for it).
  void unauthenticated() { ++unauthenticated_beacons_; }
  uint64_t unauthenticatedBeacons() const { return unauthenticated_beacons_; }

 private:
  int64_t description_;
  int64_t freshness_us_;
  std::map<int64_t, AnnouncedRun> fresh_;
  std::set<int64_t> stale_runs_;
  uint64_t stale_beacons_ = 0;
  uint64_t other_launch_beacons_ = 0;
  uint64_t unauthenticated_beacons_ = 0;
};

struct AdoptionOptions {
  double timeout_s = 30;  // without a fresh beacon of this launch by then: LaunchError
  double settle_s = 1.5;  // after the first: three beacons' time to hear a second run of the same launch
  std::function<int64_t()> wall_clock_us;           // default: the system clock
  std::function<void(const std::string&)> say;      // progress and refusals, one line each
  const transport::MessageKey* key = nullptr;       // a keyed run's: only beacons tagged with it count
};

// Listens on `lcm` for the run of launch `description` (launchDescriptionOf)
// and returns it. Throws LaunchError when none is heard within the timeout
// (saying what was refused), or when two runs of the same launch are fresh
// on the URL (the user says which with --run-id).
AnnouncedRun adoptAnnouncedRun(lcm::LCM& lcm, int64_t description, const AdoptionOptions& options);

// "run 1f3a... (arbiter pid 12 on host sim, launched 3 s ago)", for messages.
std::string describeAnnouncedRun(const AnnouncedRun& run, int64_t now_utime);

}  // namespace beft::launch
