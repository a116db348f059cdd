// Which message type each named channel carries (modules/common/channels.hpp),
// so a message whose fingerprint is unknown can be named for what it should be.
#pragma once

#include <string>

namespace beft::blackboard {

// "beft.robot_state_t" for "ROBOT_STATE", "beft.bb_snapshot_t" for any
// "BB_SNAPSHOT_<requester>", or "" for a channel not in the table.
std::string expectedTypeOfChannel(const std::string& channel);

}  // namespace beft::blackboard
