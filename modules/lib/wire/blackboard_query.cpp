#include "lib/wire/blackboard_query.hpp"

#include <unistd.h>

#include <chrono>

#include <beft/bb_query_t.hpp>

#include "lib/common/channels.hpp"

namespace beft::wire {

std::string blackboardAnswerChannel(const std::string& process_name) {
  return std::string(channels::kBlackboardSnapshotPrefix.name) + process_name + "_" + std::to_string(getpid());
}

beft::bb_query_t blackboardQuery(const std::string& answer_channel, int64_t query_id,
                                 const std::vector<std::string>& channels) {
  beft::bb_query_t query{};
  query.utime = std::chrono::duration_cast<std::chrono::microseconds>(
                    std::chrono::system_clock::now().time_since_epoch())
                    .count();
  query.requester = answer_channel.substr(std::string(channels::kBlackboardSnapshotPrefix.name).size());
  query.query_id = query_id;
  query.channels = channels;
  query.num_channels = static_cast<int32_t>(query.channels.size());
  return query;
}

}  // namespace beft::wire
