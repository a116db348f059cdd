#include "fault_injection.hpp"

#include <algorithm>

#include <beft/marking_t.hpp>

#include "channels.hpp"
#include "guarded_decode.hpp"
#include "launch_file.hpp"

namespace beft::launch {

PlannedKill parsePlannedKill(const std::string& text) {
  const auto at = text.find('@');
  if (at == std::string::npos || at == 0 || at + 1 == text.size())
    throw LaunchError("--kill '" + text + "' is not NAME@TICK (e.g. fusion@150)");
  PlannedKill kill;
  kill.process = text.substr(0, at);
  try {
    std::size_t used = 0;
    kill.tick = std::stoll(text.substr(at + 1), &used);
    if (used != text.size() - at - 1 || kill.tick < 0) throw std::invalid_argument("bad tick");
  } catch (const std::exception&) {
    throw LaunchError("--kill '" + text + "': the tick must be a number >= 0");
  }
  return kill;
}

int64_t TickFollower::poll() {
  try {
    wire::LogReader log(path_, offset_);
    wire::LogEvent event;
    while (log.nextOfRun(event, run_id_)) {
      if (event.channel != channels::kMarking) continue;
      beft::marking_t marking{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), marking).ok()) tick_ = std::max(tick_, marking.tick);
    }
    offset_ = log.position();
  } catch (const std::exception&) {
    // Not written yet.
  }
  return tick_;
}

}  // namespace beft::launch
