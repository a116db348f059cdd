// Asking the blackboard for the latest message of some channels: a late
// joiner, an expert whose firing lacks an input, a bridge that needs the
// ground truth in force. The answer (bb_snapshot_t) comes on the asker's own
// channel, BB_SNAPSHOT_<name>_<pid>, of the asker's run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/bb_query_t.hpp>

namespace lcm {
class LCM;
}

namespace beft::wire {

// BB_SNAPSHOT_<process_name>_<pid of this process>.
std::string blackboardAnswerChannel(const std::string& process_name);

// The query askBlackboard sends, for a process that publishes it on a port of its own.
beft::bb_query_t blackboardQuery(const std::string& answer_channel, int64_t query_id,
                                 const std::vector<std::string>& channels);

// Publishes a bb_query_t on this run's BB_QUERY for `channels` (all if
// empty), to be answered on answer_channel (from blackboardAnswerChannel).
void askBlackboard(lcm::LCM& lcm, const std::string& answer_channel, int64_t query_id,
                   const std::vector<std::string>& channels);

}  // namespace beft::wire
