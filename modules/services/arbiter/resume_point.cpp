#include "services/arbiter/resume_point.hpp"

#include <algorithm>

#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::arbiter {

std::optional<ResumePoint> readResumePoint(const std::string& log_path, int64_t since_us, double timeout_s) {
  if (!wire::waitForLogPast(log_path, since_us, timeout_s))
    log::warn("the run's log ", log_path, " has nothing newer than this restart: resuming from what it holds");
  ResumePoint point;
  bool found = false;
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, wire::runId())) {
    if (event.channel == channels::kMarking) {
      beft::marking_t marking{};
      if (!wire::decodeFrom(event.channel, event.data.data(), event.data.size(), marking)) continue;
      point.marking = std::move(marking);
      found = true;
    } else if (event.channel == channels::kFire) {
      beft::fire_t fire{};
      if (!wire::decodeFrom(event.channel, event.data.data(), event.data.size(), fire)) continue;
      point.highest_firing_id = std::max(point.highest_firing_id, fire.firing_id);
      point.newest_fire[fire.expert] = fire;
    } else if (event.channel == channels::kRunControlState) {
      beft::run_control_t state{};
      if (wire::decodeFrom(event.channel, event.data.data(), event.data.size(), state)) point.control = state;
    } else if (event.channel == channels::kDone) {
      beft::done_t done{};
      if (wire::decodeFrom(event.channel, event.data.data(), event.data.size(), done))
        point.done_firing_ids.insert(done.firing_id);
    }
  }
  if (log.damage().any()) log::warn("resuming from a damaged log: ", log.damage().summary());
  if (!found) return std::nullopt;
  return point;
}

}  // namespace beft::arbiter
