// Runs an expert offline against a recorded LCM log and compares its outputs
// with the ones recorded in the run (`./beft replay LOG --module NAME`).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "expert.hpp"

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
  // Every output the log recorded was produced again, identical, in the same
  // firing. Outputs missing from the log are reported, not counted against it:
  // the logger hears the run over UDP and may lose a datagram.
  bool exactMatch() const {
    return firings > 0 && outputs_compared > 0 && outputs_compared == outputs_matching && recorded_only == 0;
  }
};

// Feeds the logged messages on expert.reads() to onMessage in log order,
// fires at every new FIRE for process_name (once its inputs are ready, as
// live), and compares each channel's outputs in order.
ReplayResult replayLog(Expert& expert, const std::string& process_name, const std::string& log_path);

// Prints the result, with the first difference decoded by describe (channel,
// bytes) -> readable text, when given.
void printReplayResult(const ReplayResult& result, const std::string& process_name,
                       const std::function<std::string(const std::string&, const std::vector<uint8_t>&)>& describe);

}  // namespace beft::expert
