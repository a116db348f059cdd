// Runs an expert offline against a recorded LCM log and compares its outputs
// with the ones recorded in the run (`./beft replay LOG --module NAME`).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <beft/done_t.hpp>

#include "lib/expert/expert.hpp"

namespace beft::expert {

struct ReplayMismatch {
  std::string channel;
  int64_t index = 0;  // firing id the output belongs to
  std::vector<uint8_t> recorded, replayed;
};

struct ReplayResult {
  int64_t firings = 0;           // FIRE tokens for this expert replayed
  int64_t outputs_compared = 0;  // output messages compared
  int64_t outputs_matching = 0;
  int64_t recorded_only = 0;     // recorded outputs the replay did not produce
  int64_t replayed_only = 0;     // replayed outputs absent from the log (a lost datagram, or new output)
  std::vector<ReplayMismatch> first_mismatches;  // up to a few
  std::string log_damage;                        // what the log reader skipped, "" if nothing
  // Firings the log held not every input of (their tick's camera frames in a
  // log recorded with --record-camera every:N or none, ...): fired anyway,
  // as live after the wait, so their outputs differ from the run's.
  int64_t firings_lacking_inputs = 0;
  std::map<std::string, int64_t> lacking_inputs;  // per channel: firings it held nothing of the tick for
  // Every output the log recorded was produced again, identical, in the same
  // firing. Outputs missing from the log are reported, not counted against it:
  // the logger hears the run over UDP and may lose a datagram.
  bool exactMatch() const {
    return firings > 0 && outputs_compared > 0 && outputs_compared == outputs_matching && recorded_only == 0;
  }
  // Not exact, and the log lacks inputs the expert needs: the log, not the
  // expert, is why (exit code 4 of a replay rather than 3).
  bool logLacksInputs() const { return !exactMatch() && firings_lacking_inputs > 0; }
};

// Feeds the logged messages on expert.reads() to onMessage in log order,
// fires at every new FIRE for process_name (once its inputs are ready, as
// live), and compares each channel's outputs in order.
ReplayResult replayLog(Expert& expert, const std::string& process_name, const std::string& log_path);

// Where a restarted expert resumes (crash-only processes): its state rebuilt
// from the run's log, every input it had heard and every firing it had
// finished (those whose DONE the log holds) replayed with the outputs
// dropped, since the run already has them.
struct ResumeState {
  int64_t firings = 0;               // firings replayed
  int64_t inputs = 0;                // input messages delivered
  std::optional<Firing> last_fired;  // the newest firing replayed ...
  std::optional<beft::done_t> last_done;  // ... and its DONE as logged (sent again if asked)
  std::optional<Firing> in_flight;   // a FIRE with no DONE: the arbiter sends it again
  // messageFingerprint of what the log holds on the expert's channels after
  // the in-flight FIRE: published before the process died, so the firing run
  // again does not send them twice.
  std::multiset<uint64_t> in_flight_outputs;
  std::string log_damage;
  // messageFingerprint of the inputs logged in the last second before the
  // live sockets opened: their live copies are dropped once each.
  std::multiset<uint64_t> logged_recently;
  int64_t firings_lacking_inputs = 0;  // replayed without all their inputs: the state rebuilt misses them
  std::map<std::string, int64_t> lacking_inputs;
};

// "CAMERA_DEPTH (446 firings), CAMERA_INSTANCE (446 firings)".
std::string describeLackingInputs(const std::map<std::string, int64_t>& lacking_inputs);

// live_since_us: when the process's live sockets opened [us since the epoch].
ResumeState resumeFromLog(Expert& expert, const std::string& process_name, const std::string& log_path,
                          int64_t live_since_us);

// Identity of a message for ResumeState::logged_recently (channel and bytes).
uint64_t messageFingerprint(const std::string& channel, const void* data, std::size_t size);

// Prints the result, with the first difference decoded by describe (channel,
// bytes) -> readable text, when given.
void printReplayResult(const ReplayResult& result, const std::string& process_name,
                       const std::function<std::string(const std::string&, const std::vector<uint8_t>&)>& describe);

}  // namespace beft::expert
