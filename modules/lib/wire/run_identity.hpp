// Which run a message belongs to: its channel says. A process of run R
// publishes and subscribes "VISION@r" (R in hex) instead of "VISION"; the
// launcher gives every process of a run the same id (BEFT_RUN_ID), the
// transport adds the suffix to what a process publishes and takes and
// removes it from what it hands on, so a process never hears another run's
// messages, the kernel filter drops them unread, and the recorder, which
// hears everything, keeps them apart. Every launch draws a fresh id (the
// other hosts of a distributed run adopt it: lib/launch/run_adoption.hpp).
// A user who shares an LCM URL by mistake (isolation by port stays the
// default) gets two runs that ignore each other, and their arbiters say so
// (BEFT_RUNS beacons). Run id 0 (a process started by hand without one) uses
// the plain names, as before.
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

// A fresh run id for a launch: random (getrandom), so that no two launches,
// today's and yesterday's of the same launch file included, share one, and a
// replayed log's messages are never taken as the run's own. Never 0.
// Throws std::runtime_error when the kernel gives no random bytes.
int64_t freshRunId();

// A hash of what defines a run (launch file and arguments): the same
// description gives the same value on every machine, which is how the hosts
// of a distributed run recognise each other's run (run_beacon_t.description).
// Never 0.
int64_t runDescriptionHash(const std::string& description);

// What the launcher says of the run besides its id, for the arbiter's
// beacons (run_beacon_t): which launch it is and when it began. Set in every
// process's environment (BEFT_RUN_DESCRIPTION: runDescriptionHash in hex;
// BEFT_RUN_STARTED: wall time in us); zeros where not given.
struct RunOrigin {
  int64_t description = 0;    // runDescriptionHash of the launch file and its arguments
  int64_t started_utime = 0;  // wall time of the launch [us]
};
RunOrigin runOrigin();
void setRunOriginEnvironment(const RunOrigin& origin);  // for the processes started after
// "BEFT_RUN_DESCRIPTION=... BEFT_RUN_STARTED=..." as a command line sets them ("" for zeros).
std::string runOriginAssignments(const RunOrigin& origin);

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
