#include "lib/compare/difference_text.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/message_decoder.hpp"

namespace beft::compare {
namespace {

std::string whereInChannel(const MessageDifference& difference) {
  const DifferingMessage& message = difference.first.present ? difference.first : difference.second;
  std::string where = difference.channel + " message #" + std::to_string(message.index);
  int64_t tick = 0;
  char time[48];
  std::snprintf(time, sizeof time, "t = %.6g s", static_cast<double>(message.utime) * 1e-6);
  if (wire::encodedTick(message.data.data(), message.data.size(), tick))
    return where + " (tick " + std::to_string(tick) + ", " + time + ")";
  return where + " (" + time + ")";
}

std::string whatDiffers(const MessageDifference& difference, const DifferenceLabels& labels) {
  switch (difference.kind) {
    case DifferenceKind::kOnlyInFirst:
      return "only in " + labels.first + " (missing from " + labels.second + ")";
    case DifferenceKind::kOnlyInSecond:
      return "only in " + labels.second + " (an extra message, not in " + labels.first + ")";
    case DifferenceKind::kRefused: {
      std::string text = "refused by the message guard in";
      if (!difference.first.refusal.empty()) text += " " + labels.first + " (" + difference.first.refusal + ")";
      if (!difference.second.refusal.empty()) text += " " + labels.second + " (" + difference.second.refusal + ")";
      return text;
    }
    case DifferenceKind::kBytesDiffer:
      break;
  }
  const auto& a = difference.first.data;
  const auto& b = difference.second.data;
  const auto mismatch = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return "bytes differ from byte " + std::to_string(mismatch.first - a.begin()) + " (" + std::to_string(a.size()) +
         " vs " + std::to_string(b.size()) + " bytes)";
}

std::vector<std::string> decodedLines(const std::string& channel, const DifferingMessage& message, int max_lines) {
  blackboard::DescribeOptions options;
  options.max_lines = max_lines;
  return blackboard::MessageDecoder::beftTypes().describeLines(channel, message.data.data(),
                                                               static_cast<int>(message.data.size()), options);
}

// The first line of the decoded texts that differs, as "field: A -> B".
std::string firstDifferingField(const MessageDifference& difference) {
  const int kAllLines = 1 << 20;
  const auto a = decodedLines(difference.channel, difference.first, kAllLines);
  const auto b = decodedLines(difference.channel, difference.second, kAllLines);
  const auto mismatch = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  if (mismatch.first == a.end() && mismatch.second == b.end())
    return "the decoded texts are the same: the difference is inside a byte array or beyond the printed digits";
  const std::string left = mismatch.first == a.end() ? "(no line)" : *mismatch.first;
  const std::string right = mismatch.second == b.end() ? "(no line)" : *mismatch.second;
  return "first differing field (line " + std::to_string(mismatch.first - a.begin() + 1) + "): " + left + "  ->  " +
         right;
}

void appendDecoded(std::string& text, const std::string& label, const std::string& channel,
                   const DifferingMessage& message, int max_lines) {
  if (!message.present) return;
  text += "  in " + label + " (#" + std::to_string(message.index) + "):\n";
  for (const auto& line : decodedLines(channel, message, max_lines)) text += "    " + line + "\n";
}

}  // namespace

std::string summarizeDifference(const MessageDifference& difference, const DifferenceLabels& labels) {
  return whereInChannel(difference) + ": " + whatDiffers(difference, labels);
}

std::string describeDifference(const MessageDifference& difference, const DifferenceLabels& labels) {
  std::string text = summarizeDifference(difference, labels) + "\n";
  if (difference.kind == DifferenceKind::kBytesDiffer) text += "  " + firstDifferingField(difference) + "\n";
  appendDecoded(text, labels.first, difference.channel, difference.first, labels.max_lines);
  appendDecoded(text, labels.second, difference.channel, difference.second, labels.max_lines);
  return text;
}

}  // namespace beft::compare
