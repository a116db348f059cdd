// Asking the blackboard for the latest message of some channels: a late
// joiner, an expert whose firing lacks an input, a bridge that needs the
// ground truth in force. The answer (bb_snapshot_t) comes on the asker's own
// channel, BB_SNAPSHOT_<name>_<pid>, of the asker's run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/bb_query_t.hpp>

namespace beft::wire {

// BB_SNAPSHOT_<process_name>_<pid of this process>.
std::string blackboardAnswerChannel(const std::string& process_name);

// A bb_query_t for `channels` (all if empty), to be answered on
// answer_channel (from blackboardAnswerChannel); the asker publishes it on
// its run's BB_QUERY (lib/transport/publisher.hpp).
beft::bb_query_t blackboardQuery(const std::string& answer_channel, int64_t query_id,
                                 const std::vector<std::string>& channels);

}  // namespace beft::wire
