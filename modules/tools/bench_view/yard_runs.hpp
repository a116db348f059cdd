// The yard runs of beft-bench-view: the lockstep loop at full speed (--fast)
// without a viewer, and with the bridge running and the page open. A viewed
// run is paused (beft-control) until the page is connected and has settled
// (2 s after it was first read), so that every tick measured ran with the
// page open, past its start.
#pragma once

#include <cstdint>
#include <string>

#include "tools/bench_view/page_probe.hpp"
#include "tools/bench_view/tick_times.hpp"

namespace beft::bench {

struct YardRunRequest {
  std::string source_dir;  // the repository: scenarios/yard.xml
  std::string dir;         // the run's folder (made anew)
  int ticks = 300;
  long long seed = 1;
  int view_port = 0;       // 0: no viewer
};

struct YardRun {
  bool completed = false;     // beft-run exited 0
  std::string problem;        // why the run or its page failed, or ""
  TickTimes times;            // from the run's log
  int64_t viewed_from_tick = -1;  // viewed: the first tick that started with the page connected and settled
  PageReadings page;          // viewed: what the page said
  long bridge_rss_kb = -1;    // viewed: beft-bridge's VmRSS last read before the run ended
  double bridge_cpu_s = -1;   // viewed: its CPU time then
};

YardRun runYard(const YardRunRequest& request);

}  // namespace beft::bench
