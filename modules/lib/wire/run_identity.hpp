// Which run a message belongs to: its channel says. A process of run R
// publishes and subscribes "VISION@r" (R in hex) instead of "VISION"; the
// launcher gives every process of a run the same id (BEFT_RUN_ID), the
// transport adds the suffix to what a process publishes and takes and
// removes it from what it hands on, so a process never hears another run's
// messages, the kernel filter drops them unread, and the recorder, which
// hears everything, keeps them apart. A user who shares an LCM URL by
// mistake (isolation by port stays the default) gets two runs that ignore
// each other, and their arbiters say so (BEFT_RUNS beacons). Run id 0 (a
// process started by hand without one) uses the plain names, as before.
// The message types stay as they were: old logs read and replay as ever.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

namespace beft::wire {

// The run of this process: setRunId(), else BEFT_RUN_ID, else 0 (none: the
// plain channel names, for processes and tools outside a launched run).
// Thread-safe.
int64_t runId();
void setRunId(int64_t id);

// A run id as written on a command line or in BEFT_RUN_ID: hexadecimal, as
// the channels show it ("1f3a", "0x1f3a"). Throws std::invalid_argument.
int64_t parseRunId(const std::string& text);

// A run id derived from what defines the run (launch file and arguments):
// the same description gives the same id on every machine. Never 0.
int64_t runIdFor(const std::string& description);

// "VISION@1f3a..." in run `run_id`; the plain name for run 0 and for
// URL-wide channels (BEFT_RUNS, LCM's own).
std::string runChannel(const std::string& channel, int64_t run_id);
std::string runChannel(const std::string& channel);  // this process's run

// The run's names of channels, each made once (publishing is on every
// firing's path); made again if the process's run changes.
class RunChannelNames {
 public:
  const std::string& of(const std::string& channel);

 private:
  int64_t run_id_ = 0;
  std::unordered_map<std::string, std::string> names_;
};

struct RunChannel {
  std::string_view base;  // "VISION"
  int64_t run_id = 0;     // 0: no suffix
};
// Splits a channel name as received; a malformed suffix stays in the base.
RunChannel splitRunChannel(std::string_view channel);
bool isUrlWideChannel(std::string_view channel);

// At start: which run the process is of, or, without one on a network URL,
// how to join a launched run (the command line the launcher prints).
void logRunOf(const std::string& lcm_url);

// "run 1f3a..." (the suffix's hex), or "no run id" for 0.
std::string describeRun(int64_t run_id);
std::string runIdText(int64_t run_id);  // "1f3a..." as BEFT_RUN_ID takes it

}  // namespace beft::wire
