// Two runs compared by their data messages (channels::isDataPlaneChannel):
// every message of either run, per channel, in order, both ways. A message
// only one run has is a difference; so is one the message guard refuses
// (wire::MessageRules), never left out. Within a channel, messages are in
// the order of their utime, then of their bytes (a message too short to
// carry a utime takes the utime of the one logged before it), and a message
// is matched with the other run's message of the same utime and rank within
// that utime (lib/compare/data_order.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "lib/compare/run_log.hpp"

namespace beft::compare {

enum class DifferenceKind {
  kBytesDiffer,   // both runs have the message; its bytes differ
  kOnlyInFirst,   // missing from the second run
  kOnlyInSecond,  // an extra message of the second run
  kRefused,       // one run's message (or both's) fails the message guard
};

// One side of a difference: the message as that run has it, if it has one.
struct DifferingMessage {
  bool present = false;
  std::size_t index = 0;  // its position among its run's messages of the channel
  int64_t utime = 0;
  std::vector<uint8_t> data;
  std::string refusal;  // the guard's verdict ("" when accepted)
};

struct MessageDifference {
  DifferenceKind kind = DifferenceKind::kBytesDiffer;
  std::string channel;
  DifferingMessage first, second;
};

struct ComparisonOptions {
  std::set<std::string> channels;   // only these data channels (empty: every one)
  std::size_t max_differences = 1;  // stop after this many (0: every difference)
};

struct RunComparison {
  std::size_t first_messages = 0, second_messages = 0;  // data messages of each run compared
  std::vector<MessageDifference> differences;           // the earliest (by utime) first
  bool identical() const { return differences.empty(); }
};

RunComparison compareRuns(const std::vector<LoggedMessage>& first, const std::vector<LoggedMessage>& second,
                          const ComparisonOptions& options = {});

}  // namespace beft::compare
