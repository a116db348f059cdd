// The blackboard's authoritative history: every encoded message per channel,
// with a per-channel sequence number and the message's own utime.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lib/wire/channel_history.hpp"

namespace beft::blackboard {

// The utime of an encoded beft message: every type has int64 utime first, so
// it is the 8 bytes after the 8-byte fingerprint, big-endian. Nothing if the
// message is shorter than 16 bytes.
std::optional<int64_t> encodedUtime(const void* data, int size);

class Store {
 public:
  using Bytes = std::vector<uint8_t>;
  using History = ChannelHistory<Bytes>;

  struct Limits {
    std::size_t history = 50;                      // messages kept per channel
    std::size_t max_channel_bytes = 16u << 20;     // bytes kept per channel (about 17 VGA RGB frames); the latest is always kept
  };

  explicit Store(Limits limits);

  // Stores one encoded message. Returns its sequence number on the channel,
  // or nothing if it is too short to hold a fingerprint and a utime.
  std::optional<uint64_t> store(const std::string& channel, const void* data, int size);

  const History* history(const std::string& channel) const;
  const History::Entry* latest(const std::string& channel) const;
  std::vector<std::string> channels() const;  // sorted

  std::size_t channelCount() const { return channels_.size(); }
  uint64_t messagesStored() const { return messages_stored_; }   // since start, all channels
  uint64_t messagesRejected() const { return messages_rejected_; }
  std::size_t bytesHeld() const { return bytes_held_; }          // encoded bytes now in memory
  const Limits& limits() const { return limits_; }

 private:
  struct Channel {
    History history;
    std::size_t bytes = 0;
  };

  Limits limits_;
  std::map<std::string, Channel> channels_;
  uint64_t messages_stored_ = 0;
  uint64_t messages_rejected_ = 0;
  std::size_t bytes_held_ = 0;
};

}  // namespace beft::blackboard
