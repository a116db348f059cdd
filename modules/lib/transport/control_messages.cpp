#include "lib/transport/control_messages.hpp"

#include "lib/common/channels.hpp"

namespace beft::control {

beft::fire_t makeFire(const std::string& expert, const std::string& transition, int64_t tick, int64_t utime,
                      int64_t firing_id) {
  beft::fire_t fire{};
  fire.utime = utime;
  fire.expert = expert;
  fire.transition = transition;
  fire.tick = tick;
  fire.firing_id = firing_id;
  return fire;
}

beft::run_status_t makeRunStatus(int8_t state, int64_t tick, int64_t utime, const std::string& message) {
  beft::run_status_t status{};
  status.utime = utime;
  status.tick = tick;
  status.state = state;
  status.message = message;
  return status;
}

transport::Rule firesFor(const std::string& expert) {
  transport::Rule rule = transport::channelRule(channels::kFire);
  rule.field_offset = 8;  // after utime
  const uint32_t length = static_cast<uint32_t>(expert.size() + 1);
  for (int shift = 24; shift >= 0; shift -= 8) rule.field.push_back(static_cast<char>((length >> shift) & 0xff));
  rule.field += expert;
  rule.field.push_back('\0');
  rule.what = "own firings";
  return rule;
}

transport::Rule runStatusIn(int8_t state, const std::string& what) {
  transport::Rule rule = transport::channelRule(channels::kRunStatus);
  rule.field_offset = 16;  // after utime and tick
  rule.field = std::string(1, static_cast<char>(state));
  rule.what = what;
  return rule;
}

}  // namespace beft::control
