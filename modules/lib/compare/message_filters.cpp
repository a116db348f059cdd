#include "lib/compare/message_filters.hpp"

#include <set>
#include <string>
#include <utility>

#include "lib/common/channels.hpp"
#include "lib/wire/message_check.hpp"

namespace beft::compare {

std::vector<LoggedMessage> withoutRefused(const std::vector<LoggedMessage>& log, std::size_t& refused) {
  const auto& rules = wire::MessageRules::beftTypes();
  std::vector<LoggedMessage> kept;
  refused = 0;
  for (const auto& message : log) {
    if (channels::isDataPlaneChannel(message.channel) &&
        !rules.checkForChannel(message.channel, message.data.data(), message.data.size()).ok())
      ++refused;
    else
      kept.push_back(message);
  }
  return kept;
}

std::vector<LoggedMessage> withoutRepeats(const std::vector<LoggedMessage>& log, std::size_t& repeats) {
  std::vector<LoggedMessage> kept;
  std::set<std::pair<std::string, std::vector<uint8_t>>> seen;
  repeats = 0;
  for (const auto& message : log) {
    if (channels::isDataPlaneChannel(message.channel) && !seen.insert({message.channel, message.data}).second)
      ++repeats;
    else
      kept.push_back(message);
  }
  return kept;
}

}  // namespace beft::compare
