// Live traffic per channel for beft-spy: message type, count, rate, size and
// the latest message's utime, formatted as a plain-text table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace beft::spy {

struct TrafficRow {
  std::string channel;
  std::string type;                 // "beft.robot_state_t", or "unknown ..."
  uint64_t count = 0;               // messages since the spy started
  double rate_hz = 0;               // over the rate window
  double bytes_per_second = 0;      // over the rate window
  std::size_t last_bytes = 0;       // size of the latest message
  std::optional<int64_t> last_utime;  // utime of the latest message [us]
  double idle_s = 0;                // since the latest message
};

class TrafficTable {
 public:
  // Times are seconds on any steady clock; the rate of a channel is the number
  // of its messages in the last window_s seconds over the window (or over the
  // time since start while the spy is younger than the window).
  explicit TrafficTable(double start_s, double window_s = 2.0);

  void record(const std::string& channel, const std::string& type, std::size_t bytes, double now_s,
              std::optional<int64_t> utime);

  std::vector<TrafficRow> rows(double now_s) const;  // sorted by channel
  uint64_t totalCount() const { return total_count_; }

  // Header, one line per channel, a total line.
  std::string format(double now_s) const;

 private:
  struct Channel {
    std::string type;
    uint64_t count = 0;
    std::size_t last_bytes = 0;
    std::optional<int64_t> last_utime;
    double last_time = 0;
    std::deque<std::pair<double, std::size_t>> recent;  // (time, bytes) within the window
  };

  void forgetOld(Channel& channel, double now_s) const;

  double start_s_;
  double window_s_;
  uint64_t total_count_ = 0;
  std::map<std::string, Channel> channels_;
};

// "312 B", "45.1 kB", "2.3 MB".
std::string formatBytes(double bytes);

}  // namespace beft::spy
