#include "lib/compare/data_comparison.hpp"

#include <algorithm>
#include <map>

#include "lib/compare/data_order.hpp"
#include "lib/wire/message_check.hpp"

namespace beft::compare {
namespace {

DifferingMessage side(const PlacedMessage& entry, int64_t utime, const std::string& channel) {
  DifferingMessage out;
  out.present = true;
  out.index = entry.index;
  out.utime = utime;
  out.data = entry.message->data;
  const auto verdict =
      wire::MessageRules::beftTypes().checkForChannel(channel, out.data.data(), out.data.size());
  if (!verdict.ok()) out.refusal = verdict.text();
  return out;
}

bool refused(const PlacedMessage& entry, const std::string& channel) {
  const auto& data = entry.message->data;
  return !wire::MessageRules::beftTypes().checkForChannel(channel, data.data(), data.size()).ok();
}

// The first `limit` differences of one channel (0: all), in place order.
void compareChannel(const std::string& channel, const ChannelMessages& first, const ChannelMessages& second,
                    std::size_t limit, std::vector<MessageDifference>& out) {
  std::set<Place> places;
  for (const auto& [place, entry] : first) places.insert(place);
  for (const auto& [place, entry] : second) places.insert(place);
  for (const Place& place : places) {
    const auto a = first.find(place), b = second.find(place);
    MessageDifference difference;
    difference.channel = channel;
    if (a != first.end()) difference.first = side(a->second, place.first, channel);
    if (b != second.end()) difference.second = side(b->second, place.first, channel);
    if (b == second.end()) difference.kind = DifferenceKind::kOnlyInFirst;
    else if (a == first.end()) difference.kind = DifferenceKind::kOnlyInSecond;
    else if (refused(a->second, channel) || refused(b->second, channel)) difference.kind = DifferenceKind::kRefused;
    else if (a->second.message->data != b->second.message->data) difference.kind = DifferenceKind::kBytesDiffer;
    else continue;
    out.push_back(std::move(difference));
    if (limit != 0 && --limit == 0) return;
  }
}

int64_t utimeOf(const MessageDifference& difference) {
  return difference.first.present ? difference.first.utime : difference.second.utime;
}

}  // namespace

RunComparison compareRuns(const std::vector<LoggedMessage>& first, const std::vector<LoggedMessage>& second,
                          const ComparisonOptions& options) {
  RunComparison result;
  const auto first_channels = dataMessagesByChannel(first, options.channels, &result.first_messages);
  const auto second_channels = dataMessagesByChannel(second, options.channels, &result.second_messages);
  std::set<std::string> names;
  for (const auto& [channel, messages] : first_channels) names.insert(channel);
  for (const auto& [channel, messages] : second_channels) names.insert(channel);
  static const ChannelMessages kNone;
  for (const std::string& channel : names) {
    const auto a = first_channels.find(channel), b = second_channels.find(channel);
    compareChannel(channel, a == first_channels.end() ? kNone : a->second,
                   b == second_channels.end() ? kNone : b->second, options.max_differences, result.differences);
  }
  // The earliest first: a difference at tick k often causes those after it.
  std::stable_sort(result.differences.begin(), result.differences.end(),
                   [](const MessageDifference& x, const MessageDifference& y) { return utimeOf(x) < utimeOf(y); });
  if (options.max_differences != 0 && result.differences.size() > options.max_differences)
    result.differences.resize(options.max_differences);
  return result;
}

}  // namespace beft::compare
