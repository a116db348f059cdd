// The order in which a run's data messages are compared and digested: per
// channel, by utime, then by their bytes within that utime (a message too
// short to carry a utime takes that of the channel's message before it).
// Within a utime the log's order is the network's (two experts' messages of
// one tick), not the run's, so it is not compared.
// Two runs' messages of a channel are matched by their place.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lib/compare/run_log.hpp"

namespace beft::compare {

// A message's place in its channel: (utime, rank among that utime's messages).
using Place = std::pair<int64_t, int>;

struct PlacedMessage {
  const LoggedMessage* message = nullptr;
  std::size_t index = 0;  // its position among the channel's messages, in place order
};

using ChannelMessages = std::map<Place, PlacedMessage>;

// Every data message of `log` (only those of `only`'s channels, when it is
// not empty), per channel, by place; `count`, when given: how many.
std::map<std::string, ChannelMessages> dataMessagesByChannel(const std::vector<LoggedMessage>& log,
                                                             const std::set<std::string>& only = {},
                                                             std::size_t* count = nullptr);

}  // namespace beft::compare
