// What an expert stores of one input channel: decoded messages in a
// ChannelHistory, looked up by the tick a firing is for. Every message type
// an expert reads carries `utime` and `tick`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "channel_history.hpp"
#include "expert.hpp"

namespace beft::expert {

template <typename Message>
class TickChannel {
 public:
  explicit TickChannel(std::size_t capacity = 16) : history_(capacity) {}

  // Decodes and stores one message; false if the bytes are not a Message.
  bool store(const void* data, int size) {
    Message message{};
    if (!decodeMessage(data, size, message)) return false;
    const int64_t utime = message.utime;
    history_.store(std::move(message), utime);  // moved: a camera frame's pixels are not copied again
    return true;
  }
  void store(const Message& message) { history_.store(message, message.utime); }

  // The newest stored message of tick k, or null. Walks back one simulated
  // time at a time (utime strictly falls), so it ends on any history.
  const Message* ofTick(int64_t tick) const {
    for (const auto* entry = history_.latest(); entry != nullptr;
         entry = history_.atOrBefore(entry->utime - 1)) {
      if (entry->message.tick == tick) return &entry->message;
    }
    return nullptr;
  }

  const Message* latest() const {
    const auto* newest = history_.latest();
    return newest == nullptr ? nullptr : &newest->message;
  }
  bool has(int64_t tick) const { return ofTick(tick) != nullptr; }
  bool empty() const { return history_.empty(); }

 private:
  blackboard::ChannelHistory<Message> history_;
};

}  // namespace beft::expert
