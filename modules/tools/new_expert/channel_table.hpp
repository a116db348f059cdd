// The blackboard's channels as the expert generator needs them: the C++
// constant, the channel name, the message type, and whether the type carries
// the `utime` and `tick` a TickInput keys its messages by. Read from the one
// channel list (BEFT_CHANNELS in lib/common/channels.hpp) at compile time.
#pragma once

#include <string>
#include <vector>

namespace beft::new_expert {

struct KnownChannel {
  std::string constant;  // "kRobotState"
  std::string name;      // "ROBOT_STATE"
  std::string type;      // "robot_state_t"
  bool has_utime = false;
  bool has_tick = false;
};

const std::vector<KnownChannel>& knownChannels();
// The channel of that name, or null.
const KnownChannel* findChannel(const std::string& name);
// "ROBOT_STATE, GEOMETRY, ...": every name, in table order.
std::string channelNames();

}  // namespace beft::new_expert
