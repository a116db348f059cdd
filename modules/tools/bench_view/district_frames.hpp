// The page on a big scene at the pace a person watches: district_large run
// with --view in real time (no --fast), the page read every few seconds.
#pragma once

#include <string>

#include "tools/bench_view/page_probe.hpp"

namespace beft::bench {

struct DistrictRequest {
  std::string source_dir;  // the repository: scenarios/district_large.xml
  std::string dir;         // the run's folder (made anew)
  double seconds = 20;     // of wall time with the page connected
  int view_port = 0;
};

struct DistrictFrames {
  std::string problem;         // why nothing was measured, or ""
  PageReadings page;
  double median_frame_ms = 0;  // of the page's own rolling means
  double frames_per_s = 0, renders_per_s = 0, page_ticks_per_s = 0;  // first to last reading
  double run_ticks_per_s = 0;  // the run's own, from its log, since the page was connected
  long long page_behind_ticks = 0;  // the run's tick at the last reading minus the page's
  long bridge_rss_kb = -1;     // when the page had been read for the last time
};

DistrictFrames measureDistrictFrames(const DistrictRequest& request);

}  // namespace beft::bench
