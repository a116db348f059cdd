// The blackboard's answer to a late joiner: the latest message of each
// channel it asks for, still encoded.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>

#include "blackboard/store.hpp"

namespace beft::blackboard {

// Latest entry of each channel the query names (every stored channel when it
// names none), sorted by channel; channels with nothing stored are left out.
beft::bb_snapshot_t buildSnapshot(const Store& store, const beft::bb_query_t& query, int64_t now_utime);

// Channels the query names that the store has nothing for.
std::vector<std::string> missingChannels(const Store& store, const beft::bb_query_t& query);

// The channel the answer to a requester goes to: BB_SNAPSHOT_<requester>.
std::string snapshotChannel(const std::string& requester);

}  // namespace beft::blackboard
