// A run's log indexed once, so that playback can seek without reading the
// whole log again: where the events of every half second of log time start,
// and for each keyframed channel (GT_OBJECTS, HYPOTHESES, OBSTACLE_MAP: sent
// whole only now and then, changes in between) where each keyframe is. A
// damaged log is indexed up to where it can be read (wire::LogReader).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace beft::bridge {

struct LogPosition {
  int64_t utime = 0;    // log time of the event [us]
  uint64_t offset = 0;  // byte offset of the event in the file
};

struct LogIndex {
  std::string path;
  int64_t run_id = 0;
  int64_t start_utime = 0, end_utime = 0;  // first and last event of the run
  uint64_t events = 0;
  std::vector<LogPosition> checkpoints;                    // every interval of log time, ascending
  std::map<std::string, std::vector<LogPosition>> keyframes;  // by plain channel name, ascending
  std::map<std::string, uint64_t> channels;                // plain channel names heard, with their counts
  std::string damage;                                      // wire::LogDamage::summary(), "" when whole

  // Where to start reading so that, read up to `utime`, the keyframes in
  // force then and everything since the checkpoint before it are among what
  // was read: the earliest of the checkpoint and those keyframes.
  uint64_t offsetToRebuild(int64_t utime) const;
};

// The channels indexed by their keyframes.
const std::vector<std::string>& keyframedChannels();

// Reads the log once. Throws std::runtime_error when it cannot be opened.
LogIndex buildLogIndex(const std::string& path, int64_t checkpoint_interval_us = 500000);

}  // namespace beft::bridge
