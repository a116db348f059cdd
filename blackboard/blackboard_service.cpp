#include "blackboard/blackboard_service.hpp"

#include <cstdio>

#include "blackboard/snapshot.hpp"
#include "lib/common/channels.hpp"
#include "lib/wire/message_check.hpp"
#include "lib/wire/reject_counter.hpp"

namespace beft::blackboard {

bool isServiceChannel(const std::string& channel) {
  const std::string prefix = channels::kBlackboardSnapshotPrefix;
  return channel == channels::kBlackboardQuery || channel.compare(0, prefix.size(), prefix) == 0;
}

BlackboardService::BlackboardService(Options options) : store_(options.limits), filter_(options.exclude) {}

BlackboardService::Verdict BlackboardService::onMessage(const std::string& channel, const void* data, int size) {
  if (isLcmInternalChannel(channel)) return Verdict::Ignored;
  if (isServiceChannel(channel) || !filter_.accepts(channel)) {
    ++messages_excluded_;
    return Verdict::Excluded;
  }
  const wire::Verdict check =
      size < 0 ? wire::Verdict{wire::Fault::kTooShort, ""}
               : wire::MessageRules::beftTypes().checkForChannel(channel, data, static_cast<std::size_t>(size));
  if (!check.ok()) {
    wire::processRejects().count(channel, check);
    ++messages_rejected_;
    return Verdict::Rejected;
  }
  const auto sequence = store_.store(channel, data, size);
  if (!sequence) return Verdict::Rejected;
  return *sequence == 1 ? Verdict::StoredNewChannel : Verdict::Stored;
}

std::optional<BlackboardService::Answer> BlackboardService::answer(const beft::bb_query_t& query, int64_t now_utime,
                                                                   std::string* why_not) {
  if (query.requester.empty()) {
    if (why_not) *why_not = "query " + std::to_string(query.query_id) + " names no requester to answer to";
    return std::nullopt;
  }
  Answer result;
  result.channel = snapshotChannel(query.requester);
  result.snapshot = buildSnapshot(store_, query, now_utime);
  result.missing = missingChannels(store_, query);
  ++queries_answered_;
  return result;
}

std::string BlackboardService::statusLine() const {
  char held[32];
  std::snprintf(held, sizeof held, "%.1f MB", static_cast<double>(store_.bytesHeld()) / 1e6);
  std::string line = std::to_string(store_.channelCount()) + " channels, " +
                     std::to_string(store_.messagesStored()) + " messages stored, " +
                     std::to_string(messages_excluded_) + " excluded, " + held + " held, " +
                     std::to_string(queries_answered_) + " queries answered";
  if (messages_rejected_ > 0) line += ", " + std::to_string(messages_rejected_) + " rejected as malformed";
  return line;
}

}  // namespace beft::blackboard
