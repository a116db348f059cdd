// Catch-up for a process that starts late (or under a debugger): ask the
// blackboard for the current state and get the latest message of each channel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include <beft/bb_entry_t.hpp>
#include <beft/bb_snapshot_t.hpp>

namespace beft::blackboard {

// Publishes a bb_query_t on BB_QUERY and waits up to timeout_s for the
// matching bb_snapshot_t on BB_SNAPSHOT_<requester>, re-sending the query
// every half second in case one was lost. Nothing when no blackboard answered.
// While waiting it dispatches every subscription of this LCM object, so call
// it before subscribing to the channels it fetches, or expect their handlers
// to see newer messages before the snapshot is fed.
std::optional<beft::bb_snapshot_t> requestSnapshot(lcm::LCM& lcm, const std::string& requester,
                                                   const std::vector<std::string>& channels, double timeout_s);

// The snapshot's entries (latest message of each channel asked for, all
// channels when none are named), sorted by channel. Empty when no blackboard
// answered in time; answered (if given) tells the two cases apart.
std::vector<beft::bb_entry_t> fetchSnapshot(lcm::LCM& lcm, const std::string& requester,
                                            const std::vector<std::string>& channels, double timeout_s,
                                            bool* answered = nullptr);

}  // namespace beft::blackboard
