#include "services/bridge/log_index.hpp"

#include <algorithm>

#include "lib/common/channels.hpp"
#include "lib/wire/log_reader.hpp"

namespace beft::bridge {

namespace {

// The last position at or before `utime`, or null.
const LogPosition* lastAtOrBefore(const std::vector<LogPosition>& positions, int64_t utime) {
  const auto after = std::upper_bound(positions.begin(), positions.end(), utime,
                                      [](int64_t t, const LogPosition& p) { return t < p.utime; });
  return after == positions.begin() ? nullptr : &*(after - 1);
}

}  // namespace

const std::vector<std::string>& keyframedChannels() {
  static const std::vector<std::string> names = {channels::kGroundTruth.name, channels::kHypotheses.name,
                                                 channels::kObstacleMap.name};
  return names;
}

uint64_t LogIndex::offsetToRebuild(int64_t utime) const {
  const LogPosition* checkpoint = lastAtOrBefore(checkpoints, utime);
  uint64_t offset = checkpoint ? checkpoint->offset : 0;
  for (const auto& [channel, positions] : keyframes)
    if (const LogPosition* keyframe = lastAtOrBefore(positions, utime)) offset = std::min(offset, keyframe->offset);
  return offset;
}

LogIndex buildLogIndex(const std::string& path, int64_t checkpoint_interval_us) {
  LogIndex index;
  index.path = path;
  index.run_id = wire::runOfLog(path);
  wire::LogReader reader(path);
  wire::LogEvent event;
  uint64_t event_start = reader.position();
  int64_t next_checkpoint = 0;
  bool first = true;
  const auto& keyframed = keyframedChannels();
  while (reader.nextOfRun(event, index.run_id)) {
    // An event's start: where the previous one ended (a damaged stretch between is skipped again on reading).
    const LogPosition here{event.timestamp, event_start};
    event_start = reader.position();
    if (first) {
      index.start_utime = event.timestamp;
      next_checkpoint = event.timestamp;
      first = false;
    }
    index.end_utime = std::max(index.end_utime, event.timestamp);
    ++index.events;
    ++index.channels[event.channel];
    if (event.timestamp >= next_checkpoint) {
      index.checkpoints.push_back(here);
      next_checkpoint = event.timestamp + checkpoint_interval_us;
    }
    if (std::find(keyframed.begin(), keyframed.end(), event.channel) != keyframed.end())
      index.keyframes[event.channel].push_back(here);
  }
  index.damage = reader.damage().summary();
  return index;
}

}  // namespace beft::bridge
