#include "blackboard/channel_filter.hpp"

#include <stdexcept>

#include "lib/common/channels.hpp"

namespace beft::blackboard {

void ChannelFilter::RegexDeleter::operator()(regex_t* regex) const {
  regfree(regex);
  delete regex;
}

ChannelFilter::ChannelFilter(const std::vector<std::string>& exclude_patterns) : patterns_(exclude_patterns) {
  for (const std::string& pattern : patterns_) {
    auto* compiled = new regex_t;
    const int status = regcomp(compiled, ("^(" + pattern + ")$").c_str(), REG_EXTENDED | REG_NOSUB);
    if (status != 0) {
      char reason[256];
      regerror(status, compiled, reason, sizeof reason);
      delete compiled;  // regcomp frees what it allocated on failure
      throw std::invalid_argument("exclusion pattern '" + pattern + "' is not a valid regular expression: " +
                                  reason);
    }
    regexes_.emplace_back(compiled);
  }
}

std::vector<std::string> ChannelFilter::defaultExclusions() {
  return {channels::kFire, channels::kDone, channels::kHeartbeat, channels::kMarking, "BB_.*"};
}

bool ChannelFilter::accepts(const std::string& channel) {
  if (auto it = verdicts_.find(channel); it != verdicts_.end()) return it->second;
  bool accepted = true;
  for (const Regex& regex : regexes_)
    if (regexec(regex.get(), channel.c_str(), 0, nullptr, 0) == 0) accepted = false;
  verdicts_.emplace(channel, accepted);
  return accepted;
}

bool isLcmInternalChannel(const std::string& channel) { return channel == "LCM_SELF_TEST"; }

}  // namespace beft::blackboard
