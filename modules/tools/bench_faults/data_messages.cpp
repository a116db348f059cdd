#include "tools/bench_faults/data_messages.hpp"

#include <cstdio>

#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/message_check.hpp"

namespace beft::bench {

std::map<DataKey, std::vector<uint8_t>> dataMessages(const std::string& log_path, int64_t run_id) {
  std::map<DataKey, std::vector<uint8_t>> messages;
  std::map<std::pair<std::string, int64_t>, int> count;
  const int64_t run = run_id != 0 ? run_id : wire::runOfLog(log_path);
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) {
    if (!channels::isDataPlaneChannel(event.channel) ||
        !wire::MessageRules::beftTypes().checkForChannel(event.channel, event.data.data(), event.data.size()).ok())
      continue;
    int64_t utime = 0;
    wire::encodedUtime(event.data.data(), event.data.size(), utime);
    const int order = count[{event.channel, utime}]++;
    messages[{event.channel, utime, order}] = event.data;
  }
  return messages;
}

std::string compareRuns(const std::map<DataKey, std::vector<uint8_t>>& expected,
                        const std::map<DataKey, std::vector<uint8_t>>& actual) {
  for (const auto& [key, data] : expected) {
    char where[160];
    std::snprintf(where, sizeof where, "%s at t = %.1f s", std::get<0>(key).c_str(), std::get<1>(key) * 1e-6);
    const auto it = actual.find(key);
    if (it == actual.end()) return std::string("no: ") + where + " missing";
    if (it->second != data) return std::string("no: ") + where + " differs";
  }
  if (actual.size() > expected.size()) return "no: " + std::to_string(actual.size() - expected.size()) + " extra";
  return "yes";
}

}  // namespace beft::bench
