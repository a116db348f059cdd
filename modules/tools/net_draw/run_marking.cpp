#include "tools/net_draw/run_marking.hpp"

#include <beft/marking_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::net_draw {

std::optional<arbiter::ShownMarking> lastMarkingOfRun(const std::string& log_path, const std::string& run_id) {
  const int64_t run = run_id.empty() ? wire::runOfLog(log_path) : wire::parseRunId(run_id);
  wire::LogReader log(log_path);
  wire::LogEvent event;
  std::optional<beft::marking_t> newest;
  while (log.nextOfRun(event, run)) {
    if (event.channel != channels::kMarking) continue;
    beft::marking_t marking{};
    if (wire::guardedDecode(event.data.data(), event.data.size(), marking).ok()) newest = std::move(marking);
  }
  if (!newest) return std::nullopt;
  arbiter::ShownMarking shown;
  for (int32_t i = 0; i < newest->num_places; ++i) shown.tokens[newest->place_ids[i]] = newest->tokens[i];
  shown.running = newest->running;
  shown.caption = "run " + wire::runIdText(run) + ", last marking: tick " + std::to_string(newest->tick) + ", step " +
                  std::to_string(newest->step) + " (" + newest->event + ")";
  return shown;
}

}  // namespace beft::net_draw
