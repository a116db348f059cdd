#include "lib/compare/data_comparison.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/message_check.hpp"

namespace beft::compare {
namespace {

// A message's place in its channel: (utime, rank among that utime's messages).
using Place = std::pair<int64_t, int>;

struct ChannelMessage {
  const LoggedMessage* message = nullptr;
  std::size_t index = 0;
};

using ChannelMessages = std::map<Place, ChannelMessage>;

bool compared(const std::string& channel, const ComparisonOptions& options) {
  return channels::isDataPlaneChannel(channel) && (options.channels.empty() || options.channels.count(channel) > 0);
}

// The data messages of one run, per channel, by place; `count`: how many.
std::map<std::string, ChannelMessages> byChannel(const std::vector<LoggedMessage>& log,
                                                 const ComparisonOptions& options, std::size_t& count) {
  std::map<std::string, ChannelMessages> channels;
  std::map<std::string, int64_t> last_utime;
  std::map<std::pair<std::string, int64_t>, int> rank;
  count = 0;
  for (const auto& message : log) {
    if (!compared(message.channel, options)) continue;
    int64_t& utime = last_utime[message.channel];  // too short to hold one: that of the message before
    wire::encodedUtime(message.data.data(), message.data.size(), utime);
    const int order = rank[{message.channel, utime}]++;
    channels[message.channel][{utime, order}] = {&message, 0};
    ++count;
  }
  for (auto& [channel, messages] : channels) {
    std::size_t index = 0;
    for (auto& [place, entry] : messages) entry.index = index++;
  }
  return channels;
}

DifferingMessage side(const ChannelMessage& entry, int64_t utime, const std::string& channel) {
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

bool refused(const ChannelMessage& entry, const std::string& channel) {
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
  const auto first_channels = byChannel(first, options, result.first_messages);
  const auto second_channels = byChannel(second, options, result.second_messages);
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
