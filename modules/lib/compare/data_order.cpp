#include "lib/compare/data_order.hpp"

#include <algorithm>

#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"

namespace beft::compare {
namespace {

using SameUtime = std::map<int64_t, std::vector<const LoggedMessage*>>;

// Messages of one utime from different processes (two experts pushing tasks
// in one tick) reach the recorder in whichever order the network gives, so
// they are ranked by their bytes, not by the log.
void rankByContent(std::vector<const LoggedMessage*>& messages) {
  std::stable_sort(messages.begin(), messages.end(),
                   [](const LoggedMessage* a, const LoggedMessage* b) { return a->data < b->data; });
}

}  // namespace

std::map<std::string, ChannelMessages> dataMessagesByChannel(const std::vector<LoggedMessage>& log,
                                                             const std::set<std::string>& only, std::size_t* count) {
  std::map<std::string, SameUtime> grouped;
  std::map<std::string, int64_t> last_utime;
  std::size_t taken = 0;
  for (const auto& message : log) {
    if (!channels::isDataPlaneChannel(message.channel) || (!only.empty() && only.count(message.channel) == 0))
      continue;
    int64_t& utime = last_utime[message.channel];  // too short to hold one: that of the message before
    wire::encodedUtime(message.data.data(), message.data.size(), utime);
    grouped[message.channel][utime].push_back(&message);
    ++taken;
  }
  std::map<std::string, ChannelMessages> channels;
  for (auto& [channel, by_utime] : grouped) {
    ChannelMessages& placed = channels[channel];
    std::size_t index = 0;
    for (auto& [utime, messages] : by_utime) {
      rankByContent(messages);
      int rank = 0;
      for (const LoggedMessage* message : messages) placed[{utime, rank++}] = {message, index++};
    }
  }
  if (count != nullptr) *count = taken;
  return channels;
}

}  // namespace beft::compare
