// Which channels the blackboard keeps: every channel except those matching
// an exclusion pattern (the arbiter's control plane and its own service).
#pragma once

#include <regex.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace beft::blackboard {

class ChannelFilter {
 public:
  // POSIX extended regular expressions, each matched against the whole
  // channel name ("BB_.*", "CAMERA_(COLOR|DEPTH)"). Throws
  // std::invalid_argument naming a pattern that does not compile.
  explicit ChannelFilter(const std::vector<std::string>& exclude_patterns);

  // FIRE, DONE, HEARTBEAT, MARKING and BB_.* (queries and snapshots).
  static std::vector<std::string> defaultExclusions();

  // Remembers each channel's verdict: regex matching runs once per channel.
  bool accepts(const std::string& channel);

  const std::vector<std::string>& patterns() const { return patterns_; }

 private:
  struct RegexDeleter {
    void operator()(regex_t* regex) const;
  };
  using Regex = std::unique_ptr<regex_t, RegexDeleter>;

  std::vector<std::string> patterns_;
  std::vector<Regex> regexes_;
  std::map<std::string, bool> verdicts_;
};

// LCM's own traffic (the UDP multicast self-test every LCM object sends when
// it opens): never a beft message, never stored or shown.
bool isLcmInternalChannel(const std::string& channel);

}  // namespace beft::blackboard
