// What a sender keeps of what it published, so that it can send a message
// again when a receiver asks (a NACK, reliable_sender.hpp): each message's
// bytes as sent (envelope included), per channel and sequence number, the
// oldest dropped first once the buffer holds more than its budget.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace beft::transport::detail {

class RepairBuffer {
 public:
  // budget_bytes: what the copies may take together; at least the last
  // message of every channel is kept whatever its size.
  explicit RepairBuffer(std::size_t budget_bytes = std::size_t{32} << 20) : budget_bytes_(budget_bytes) {}

  // The next sequence number on `channel` (1 for its first message).
  uint64_t nextSequence(const std::string& channel);
  // When the channel's first message was kept [us since the epoch]; `now_us` for a channel not yet used.
  int64_t streamStart(const std::string& channel, int64_t now_us) const;
  // Keeps the bytes of message `sequence` on `channel`, published at `stream_start_us`'s stream.
  void keep(const std::string& channel, uint64_t sequence, std::vector<uint8_t> bytes, int64_t stream_start_us = 0);
  // The bytes of a kept message; null when it is no longer (or never was) kept.
  std::shared_ptr<const std::vector<uint8_t>> find(const std::string& channel, uint64_t sequence) const;

  struct ChannelState {
    std::string channel;
    uint64_t last_sequence = 0;  // last sent
    uint64_t first_kept = 0;     // oldest kept (last_sequence + 1 when none is)
    int64_t stream_start_us = 0; // when its first message was published
  };
  std::vector<ChannelState> state() const;
  std::size_t bytesKept() const { return bytes_kept_; }

 private:
  struct Channel {
    uint64_t last_sequence = 0;
    int64_t stream_start_us = 0;
    std::map<uint64_t, std::shared_ptr<const std::vector<uint8_t>>> kept;
  };
  void evictOverBudget();

  std::size_t budget_bytes_;
  std::size_t bytes_kept_ = 0;
  std::map<std::string, Channel> channels_;
  std::deque<std::pair<std::string, uint64_t>> order_;  // kept messages, oldest first
};

}  // namespace beft::transport::detail
