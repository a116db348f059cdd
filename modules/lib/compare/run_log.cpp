#include "lib/compare/run_log.hpp"

#include "lib/wire/run_identity.hpp"

namespace beft::compare {

int64_t runOfLogFile(const std::string& path) { return wire::runOfLog(path); }

RunLog readRunLog(const std::string& path, std::optional<int64_t> run_id) {
  RunLog run;
  run.run_id = run_id ? *run_id : runOfLogFile(path);
  wire::LogReader log(path);
  wire::LogEvent event;
  while (log.nextOfRun(event, run.run_id))
    run.messages.push_back({std::move(event.channel), event.timestamp, std::move(event.data)});
  run.other_run_events = log.otherRunEvents();
  run.damage = log.damage();
  return run;
}

}  // namespace beft::compare
