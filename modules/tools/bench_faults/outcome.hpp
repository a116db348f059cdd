// One row of beft-bench-faults: how a run under a fault went, read from its
// folder (report.json, the processes' output), and the table of all rows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace beft::bench {

struct Outcome {
  std::string name;
  std::string skipped;  // why the row could not run here ("" when it ran)
  bool completed = false;
  std::string identical;  // the data messages against the clean run's
  long long rejected = 0, other_run = 0, restarts = 0;
  long long untagged = 0;  // refused in a keyed run: no valid tag of the run's key
  // The recorder's loss repair: messages it missed at first (and asked for
  // again), got by repair, and never got. -1: not said.
  long long repairs_asked = -1, repairs_served = -1, lost = -1;
  bool log_complete = false;
  double ticks_per_s = 0;
  double loss = -1;                // share of datagrams the link dropped each way; -1: no lossy link
  uint64_t dropped_datagrams = 0;  // what that link dropped
  int64_t run_id = 0;              // as the run printed it: other runs share the log
};

std::string readFile(const std::string& path);

// The rest of the line after the first `prefix` in `text`; "" if none.
std::string lineAfter(const std::string& text, const std::string& prefix);

// The run's id from "[launch] started ... as run ID" in its output; 0 if not said.
int64_t runIdIn(const std::string& output);

// Fills `outcome` from a run's report.json and its processes' output: the
// figures, the recorder's account of the log, and the restarts.
void readRun(const std::string& report_json, const std::string& processes_output, Outcome& outcome);

void printOutcomes(const std::vector<Outcome>& outcomes);

}  // namespace beft::bench
