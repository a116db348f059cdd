// What the blackboard process does, without LCM: keep every message it hears
// (but the excluded channels) and answer snapshot queries from the store.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>

#include "blackboard/channel_filter.hpp"
#include "blackboard/store.hpp"

namespace beft::blackboard {

class BlackboardService {
 public:
  struct Options {
    Store::Limits limits;
    std::vector<std::string> exclude = ChannelFilter::defaultExclusions();
  };

  enum class Verdict {
    Stored,            // kept
    StoredNewChannel,  // kept, the first message on its channel
    Excluded,          // an excluded channel (or the service's own)
    Rejected,          // refused by the message guard (counted and logged there)
    Ignored,           // LCM's own self-test traffic
  };

  struct Answer {
    std::string channel;                // BB_SNAPSHOT_<requester>
    beft::bb_snapshot_t snapshot{};
    std::vector<std::string> missing;   // asked for, nothing stored
  };

  // Throws std::invalid_argument for a bad exclusion pattern.
  explicit BlackboardService(Options options);

  Verdict onMessage(const std::string& channel, const void* data, int size);

  // The answer to a query, or nothing when it names no requester (why_not
  // then says so).
  std::optional<Answer> answer(const beft::bb_query_t& query, int64_t now_utime, std::string* why_not = nullptr);

  // "12 channels, 4051 messages stored, 230 excluded, 35.2 MB held, 3 queries answered"
  std::string statusLine() const;

  const Store& store() const { return store_; }
  uint64_t messagesExcluded() const { return messages_excluded_; }
  uint64_t messagesRejected() const { return messages_rejected_; }  // refused by the message guard
  uint64_t queriesAnswered() const { return queries_answered_; }

 private:
  Store store_;
  ChannelFilter filter_;
  uint64_t messages_excluded_ = 0;
  uint64_t messages_rejected_ = 0;
  uint64_t queries_answered_ = 0;
};

// True for BB_QUERY and BB_SNAPSHOT_*: never stored, whatever the exclusions,
// or every answer would hold the previous ones.
bool isServiceChannel(const std::string& channel);

}  // namespace beft::blackboard
