// Reads an LCM log (the format of lcm-logger and lcm_eventlog) event by
// event, to its end, whatever is in it.
//
// LCM 1.3.1's reader stops at the first damaged record and allocates
// whatever length a record claims. This one checks every header against
// the bytes the file holds, skips a damaged stretch to the next sync word,
// counts what it skipped, and tells a log cut mid-event from a whole one.
// Messages of an earlier layout of a type come out in today's
// (earlier_layouts.hpp). The payloads it returns are still untrusted: decode
// them with guarded_decode.hpp.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace beft::wire {

struct LogEvent {
  int64_t event_number = 0;
  int64_t timestamp = 0;  // receive time [us since the epoch]
  std::string channel;
  std::vector<uint8_t> data;
};

struct LogDamage {
  uint64_t damaged_stretches = 0;  // runs of bytes that were no valid record, skipped
  uint64_t bytes_skipped = 0;
  bool cut_at_end = false;  // the last record stops before its end (a log still written, or cut)

  bool any() const { return damaged_stretches > 0 || cut_at_end; }
  std::string summary() const;  // "" when undamaged
};

class LogReader {
 public:
  // Throws std::runtime_error when the file cannot be opened. start_offset:
  // a position() from an earlier reader of the same file (to follow a log
  // that is still being written).
  explicit LogReader(const std::string& path, uint64_t start_offset = 0);
  ~LogReader();
  LogReader(const LogReader&) = delete;
  LogReader& operator=(const LogReader&) = delete;

  // The next whole event; false at the end of the file.
  bool next(LogEvent& event);
  // The next event of one run (run_identity.hpp), under its plain channel
  // name; another run's are skipped and counted.
  bool nextOfRun(LogEvent& event, int64_t run_id);
  uint64_t otherRunEvents() const { return other_run_events_; }

  const LogDamage& damage() const { return damage_; }
  // Offset just after the last whole event returned.
  uint64_t position() const { return end_of_last_event_; }
  const std::string& path() const { return path_; }

  static constexpr int kMaxChannelLength = 255;
  static constexpr int64_t kMaxEventBytes = int64_t{1} << 30;

 private:
  bool readHeader(int64_t& event_number, int64_t& timestamp, int32_t& channel_length, int32_t& data_length);
  bool findSync(bool after_damage);
  uint64_t fileSize();

  std::string path_;
  std::FILE* file_ = nullptr;
  uint64_t offset_ = 0;  // where the next read starts
  uint64_t end_of_last_event_ = 0;
  uint64_t known_size_ = 0;
  uint64_t other_run_events_ = 0;
  LogDamage damage_;
};

// The run a log is of: that of its first FIRE or MARKING carrying a run id
// (the arbiter's), else of its first channel carrying one; 0 for a log in
// which no channel carries one (recorded before runs had ids). Channels
// without an id in a log with ids are foreign (a forged FIRE sent first does
// not make the log an old one); a log without ids is read to its end.
int64_t runOfLog(const std::string& path);

// Waits until a log still being written holds an event received at or after
// since_us (then everything received before it is in the file: the recorder
// writes in receive order). False after timeout_s.
bool waitForLogPast(const std::string& path, int64_t since_us, double timeout_s);

}  // namespace beft::wire
