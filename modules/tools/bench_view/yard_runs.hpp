// The yard runs of beft-bench-view: the lockstep loop at full speed (--fast)
// without a viewer, and with the bridge running and the page open. Every run
// is paused (beft-control) as soon as its processes are up and held alike,
// for hold_s: a viewed run also until the page is connected and has settled
// (2 s after it was first read), so that every tick measured ran with the
// page open, past its start; a run without a viewer just as long, so that
// what a pause does to the ticks after it (processes and CPUs idle for
// seconds) is in both.
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
  double hold_s = 6;       // the run is held at least this long after its processes are up
};

struct YardRun {
  bool completed = false;     // beft-run exited 0
  std::string problem;        // why the run or its page failed, or ""
  TickTimes times;            // from the run's log
  int64_t resumed_at_tick = -1;  // the first tick after the hold (viewed: with the page connected and settled)
  double held_s = 0;             // how long the run was held
  PageReadings page;          // viewed: what the page said
  long bridge_rss_kb = -1;    // viewed: beft-bridge's VmRSS last read before the run ended
  double bridge_cpu_s = -1;   // viewed: its CPU time then
};

YardRun runYard(const YardRunRequest& request);

}  // namespace beft::bench
