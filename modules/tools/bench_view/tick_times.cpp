#include "tools/bench_view/tick_times.hpp"

#include <algorithm>
#include <stdexcept>

#include <beft/fire_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/log_reader.hpp"

namespace beft::bench {

int64_t TickTimes::firstTickFiredAfter(int64_t since_us) const {
  for (const auto& [tick, fired_us] : first_fire_us)
    if (fired_us >= since_us) return tick;
  return -1;
}

int64_t TickTimes::tickAt(int64_t at_us) const {
  int64_t under_way = -1;
  for (const auto& [tick, fired_us] : first_fire_us)
    if (fired_us <= at_us) under_way = std::max(under_way, tick);
  return under_way;
}

double TickTimes::ticksPerSecondFrom(int64_t from) const {
  const auto start = first_fire_us.find(from);
  if (start == first_fire_us.end() || last_done_us <= start->second) return 0;
  const double ticks = static_cast<double>(first_fire_us.rbegin()->first - from + 1);
  return ticks / ((last_done_us - start->second) * 1e-6);
}

TickTimes readTickTimes(const std::string& log_path) {
  TickTimes times;
  try {
    const int64_t run_id = wire::runOfLog(log_path);
    wire::LogReader reader(log_path);
    wire::LogEvent event;
    while (reader.nextOfRun(event, run_id)) {
      if (event.channel == channels::kDone) times.last_done_us = std::max(times.last_done_us, event.timestamp);
      if (event.channel != channels::kFire) continue;
      beft::fire_t fire;
      if (fire.decode(event.data.data(), 0, static_cast<int>(event.data.size())) != static_cast<int>(event.data.size()))
        continue;
      times.first_fire_us.emplace(fire.tick, event.timestamp);  // the tick's first FIRE stays
    }
  } catch (const std::exception&) {
    return {};
  }
  return times;
}

}  // namespace beft::bench
