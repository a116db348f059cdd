#include "blackboard/channel_filter.hpp"

#include <stdexcept>

#include "channels.hpp"

namespace beft::blackboard {

ChannelFilter::ChannelFilter(const std::vector<std::string>& exclude_patterns) : patterns_(exclude_patterns) {
  for (const std::string& pattern : patterns_) {
    try {
      regexes_.emplace_back(pattern, std::regex::ECMAScript);
    } catch (const std::regex_error& error) {
      throw std::invalid_argument("exclusion pattern '" + pattern + "' is not a valid regular expression: " +
                                  error.what());
    }
  }
}

std::vector<std::string> ChannelFilter::defaultExclusions() {
  return {channels::kFire, channels::kDone, channels::kHeartbeat, channels::kMarking, "BB_.*"};
}

bool ChannelFilter::accepts(const std::string& channel) {
  if (auto it = verdicts_.find(channel); it != verdicts_.end()) return it->second;
  bool accepted = true;
  for (const std::regex& regex : regexes_)
    if (std::regex_match(channel, regex)) accepted = false;
  verdicts_.emplace(channel, accepted);
  return accepted;
}

bool isLcmInternalChannel(const std::string& channel) { return channel == "LCM_SELF_TEST"; }

}  // namespace beft::blackboard
