#include "services/arbiter/other_run_watch.hpp"

#include "lib/common/log.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::arbiter {

void OtherRunWatch::heard(int64_t run_id, const std::string& host, int pid, Clock::time_point now) {
  const bool new_run = runs_.insert(run_id).second;
  if (!new_run && now - last_report_ < std::chrono::seconds(10)) return;
  last_report_ = now;
  log::error("another run (", wire::describeRun(run_id), ", arbiter pid ", pid, " on ", host,
             ") shares this LCM URL with this run (", wire::describeRun(wire::runId()), "): each takes only its own run's channels, but they share the network and the CPUs. Give each "
             "run its own port (beft run does) or URL.");
}

}  // namespace beft::arbiter
