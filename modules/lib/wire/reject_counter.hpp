// Messages refused by the guard, counted per channel, and logged at most
// once a second per channel so a flood of bad traffic cannot flood the log.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "lib/wire/message_check.hpp"

namespace beft::wire {

class RejectCounter {
 public:
  using Clock = std::chrono::steady_clock;

  // Counts one refused message; logs a warning for the channel when none was
  // logged in the last second (with what was refused since).
  void count(const std::string& channel, const Verdict& verdict, Clock::time_point now = Clock::now()) {
    count(channel, verdict, std::string(), now);
  }
  // The same with the refusal's reason in words, for the log line.
  void count(const std::string& channel, const Verdict& verdict, const std::string& reason,
             Clock::time_point now = Clock::now());

  std::map<std::string, uint64_t> totals() const;  // per channel, since start
  uint64_t total() const;
  uint64_t totalOf(Fault fault) const;  // refused for that reason, on any channel, since start
  std::map<Fault, uint64_t> faultTotals() const;  // per reason, since start (one consistent look)
  uint64_t linesLogged() const;

 private:
  struct ChannelCount {
    uint64_t total = 0;
    uint64_t since_logged = 0;
    bool logged = false;
    Clock::time_point last_logged;
  };
  mutable std::mutex mutex_;
  std::map<std::string, ChannelCount> channels_;
  std::map<Fault, uint64_t> faults_;
  uint64_t lines_logged_ = 0;
};

// The process's counter (the guarded decoders count here).
RejectCounter& processRejects();

}  // namespace beft::wire
