// Puts the messages a recorder reads back in the order they entered the host.
//
// A multicast datagram is handed to the receiving sockets one after another
// within its sender's system call. A process that got it early can answer
// within microseconds (the arbiter polls for DONE), and its answer may reach
// the recorder's socket before the datagram that caused it does: the
// recorder's queue then holds the FIRE before the DONE it follows. The
// kernel's receive time (SO_TIMESTAMP, taken before the datagram is handed to
// any socket) keeps the causal order. So events are written sorted by it, and
// the ones younger than a hold-back time stay until the next read, when
// anything that raced them has arrived.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace beft::record {

struct TimedEvent {
  std::string channel;
  std::vector<uint8_t> data;
  int64_t utime = 0;  // kernel receive time [us since the epoch]
};

class TimestampOrder {
 public:
  explicit TimestampOrder(int64_t hold_back_us = 1000) : hold_back_us_(hold_back_us) {}

  void add(TimedEvent event);
  // Hands `write` every event received before now_us - hold_back, oldest
  // first (ties in arrival order); the rest stay. Returns how many.
  std::size_t release(int64_t now_us, const std::function<void(const TimedEvent&)>& write);
  // Hands on everything, oldest first.
  std::size_t releaseAll(const std::function<void(const TimedEvent&)>& write);
  std::size_t held() const { return held_.size(); }

 private:
  std::size_t releaseBefore(int64_t limit_us, const std::function<void(const TimedEvent&)>& write);

  int64_t hold_back_us_;
  std::vector<TimedEvent> held_;  // in arrival order
};

}  // namespace beft::record
