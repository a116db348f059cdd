// A difference between two runs as text: which channel, which message (its
// index in the channel, its tick and time), what differs (the first field
// whose decoded text differs, or the first differing byte) and both
// messages decoded (lib/wire/message_decoder.hpp).
#pragma once

#include <string>

#include "lib/compare/data_comparison.hpp"

namespace beft::compare {

struct DifferenceLabels {
  std::string first = "first", second = "second";  // what the two runs are called
  int max_lines = 40;                               // decoded lines printed per message
};

// One line: "CHANNEL message #12 (tick 12, t = 1.2 s): bytes differ".
std::string summarizeDifference(const MessageDifference& difference, const DifferenceLabels& labels = {});

// The summary, what differs, and each run's message decoded.
std::string describeDifference(const MessageDifference& difference, const DifferenceLabels& labels = {});

}  // namespace beft::compare
