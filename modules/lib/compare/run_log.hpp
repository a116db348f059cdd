// A run's messages as its LCM log holds them, under plain channel names.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lib/wire/log_reader.hpp"

namespace beft::compare {

struct LoggedMessage {
  std::string channel;    // without the run's suffix ("VISION", not "VISION@1f3a")
  int64_t timestamp = 0;  // logger receive time [us]
  std::vector<uint8_t> data;
};

struct RunLog {
  std::vector<LoggedMessage> messages;  // in log order
  int64_t run_id = 0;                   // the run read (0: plain channel names)
  uint64_t other_run_events = 0;        // events of other runs, left out
  wire::LogDamage damage;               // what the reader skipped
};

// The run a log is of (wire::runOfLog): its arbiter's, else that of the
// first channel carrying a run suffix, else 0.
int64_t runOfLogFile(const std::string& path);

// Every event of one run of an LCM log, in order, the run's suffix stripped
// from its channels; `run_id` unset: runOfLogFile(path). Throws
// std::runtime_error when the file cannot be opened.
RunLog readRunLog(const std::string& path, std::optional<int64_t> run_id = std::nullopt);

}  // namespace beft::compare
