// A typed, time-indexed replica of one channel: the latest message and a
// bounded history, each with a sequence number so a reader knows what is new.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>

namespace beft::blackboard {

template <typename Message>
class ChannelHistory {
 public:
  struct Entry {
    uint64_t sequence;  // 1 for the first message stored, then +1 each
    int64_t utime;      // the message's simulated time [us]
    Message message;
  };

  explicit ChannelHistory(std::size_t capacity = 64) : capacity_(capacity == 0 ? 1 : capacity) {}

  // Stores a message; the oldest is dropped when the history is full.
  uint64_t store(const Message& message, int64_t utime) { return store(Message(message), utime); }
  uint64_t store(Message&& message, int64_t utime) { return store(std::move(message), utime, nullptr); }
  // The same; the message dropped to make room, if one was, is moved to
  // `dropped` (a reader decodes the next message over it: its strings' and
  // arrays' storage is reused instead of freed and allocated again).
  uint64_t store(Message&& message, int64_t utime, Message* dropped) {
    entries_.push_back(Entry{++last_sequence_, utime, std::move(message)});
    while (entries_.size() > capacity_) {
      if (dropped != nullptr) *dropped = std::move(entries_.front().message);
      entries_.pop_front();
    }
    return last_sequence_;
  }

  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }
  std::size_t capacity() const { return capacity_; }
  uint64_t lastSequence() const { return last_sequence_; }  // 0 if nothing stored yet
  const Entry* latest() const { return entries_.empty() ? nullptr : &entries_.back(); }
  const Entry* oldest() const { return entries_.empty() ? nullptr : &entries_.front(); }

  // Drops the oldest entry (e.g. to keep a memory budget); sequence numbers
  // are not reused. False if there was nothing to drop.
  bool dropOldest() {
    if (entries_.empty()) return false;
    entries_.pop_front();
    return true;
  }

  // Newest entry whose utime is <= utime (the state "as of" a time), or null.
  const Entry* atOrBefore(int64_t utime) const {
    for (auto it = entries_.rbegin(); it != entries_.rend(); ++it)
      if (it->utime <= utime) return &*it;
    return nullptr;
  }

  // Entry with exactly this utime, or null.
  const Entry* at(int64_t utime) const {
    for (auto it = entries_.rbegin(); it != entries_.rend(); ++it)
      if (it->utime == utime) return &*it;
    return nullptr;
  }

  // Entries newer than a sequence number a reader saw last, oldest first.
  std::deque<Entry> since(uint64_t sequence) const {
    std::deque<Entry> newer;
    for (const auto& entry : entries_)
      if (entry.sequence > sequence) newer.push_back(entry);
    return newer;
  }

 private:
  std::size_t capacity_;
  uint64_t last_sequence_ = 0;
  std::deque<Entry> entries_;
};

}  // namespace beft::blackboard
