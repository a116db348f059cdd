// The runs of beft-bench-key: yard.xml by beft-run, unkeyed or with a key,
// one after the other, each read back from its report.json.
#pragma once

#include <string>

namespace beft::bench {

struct RunFigures {
  bool completed_run = false;  // beft-run exited 0 and wrote its report
  long long ticks = 0;
  double ticks_per_s = 0;      // the lockstep loop's (report.json)
  long long refused = 0;       // refused for want of a valid tag (report.json unauthenticated_total)
};

// One yard run of `ticks` ticks in `dir` (made anew); keyed when `key_file` is not empty.
RunFigures runYard(const std::string& dir, int ticks, const std::string& key_file);

// Writes a new key to `path` with beft-key (an old file there is removed first); false on failure.
bool makeKey(const std::string& path);

}  // namespace beft::bench
