// A run's data messages from its log, as two runs are compared: this run's
// channels, what the guard takes, keyed by (channel, utime, order).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace beft::bench {

using DataKey = std::tuple<std::string, int64_t, int>;
// run_id 0: the run of the log's first FIRE.
std::map<DataKey, std::vector<uint8_t>> dataMessages(const std::string& log_path, int64_t run_id = 0);

// "yes", or the first difference ("VISION at t = 12.3 s differs", "... missing").
std::string compareRuns(const std::map<DataKey, std::vector<uint8_t>>& expected,
                        const std::map<DataKey, std::vector<uint8_t>>& actual);

}  // namespace beft::bench
