// A run's messages as JSON lines, for the Python expert tests: every event
// of the log's run (plain channel names), one line each,
//   {"channel": "AUDIO", "message": {...}}
// with the message as the bridge gives it to a client (lcmToJson). Events on
// channels outside the channel table or not decodable are left out.
//   log_to_json LOG OUT.jsonl [CHANNEL...]   (only those channels when given)
#include <cstdio>
#include <exception>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "lib/common/channels.hpp"
#include "lib/foxglove/lcm_json.hpp"
#include "lib/wire/log_reader.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: log_to_json LOG OUT.jsonl [CHANNEL...]\n");
    return 2;
  }
  const std::set<std::string> wanted(argv + 3, argv + argc);
  std::FILE* out = std::fopen(argv[2], "w");
  if (out == nullptr) {
    std::fprintf(stderr, "log_to_json: cannot write %s\n", argv[2]);
    return 1;
  }
  try {
    const auto& types = beft::foxglove::beftTypeSet();
    beft::wire::LogReader log(argv[1]);
    const int64_t run = beft::wire::runOfLog(argv[1]);
    beft::wire::LogEvent event;
    while (log.nextOfRun(event, run)) {
      if (!wanted.empty() && !wanted.count(event.channel)) continue;
      const auto* type = types.find(beft::channels::typeOfChannel(event.channel));
      if (type == nullptr) continue;
      nlohmann::json line;
      line["channel"] = event.channel;
      try {
        line["message"] = beft::foxglove::lcmToJson(types, *type, event.data.data(), event.data.size());
      } catch (const std::exception&) {
        continue;  // a damaged message: not an input any expert would get
      }
      std::fprintf(out, "%s\n", line.dump().c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "log_to_json: %s\n", e.what());
    std::fclose(out);
    return 1;
  }
  return std::fclose(out) == 0 ? 0 : 1;
}
