#include "lib/compare/data_order.hpp"

#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"

namespace beft::compare {

std::map<std::string, ChannelMessages> dataMessagesByChannel(const std::vector<LoggedMessage>& log,
                                                             const std::set<std::string>& only, std::size_t* count) {
  std::map<std::string, ChannelMessages> channels;
  std::map<std::string, int64_t> last_utime;
  std::map<std::pair<std::string, int64_t>, int> rank;
  std::size_t taken = 0;
  for (const auto& message : log) {
    if (!channels::isDataPlaneChannel(message.channel) || (!only.empty() && only.count(message.channel) == 0))
      continue;
    int64_t& utime = last_utime[message.channel];  // too short to hold one: that of the message before
    wire::encodedUtime(message.data.data(), message.data.size(), utime);
    const int order = rank[{message.channel, utime}]++;
    channels[message.channel][{utime, order}] = {&message, 0};
    ++taken;
  }
  for (auto& [channel, messages] : channels) {
    std::size_t index = 0;
    for (auto& [place, entry] : messages) entry.index = index++;
  }
  if (count != nullptr) *count = taken;
  return channels;
}

}  // namespace beft::compare
